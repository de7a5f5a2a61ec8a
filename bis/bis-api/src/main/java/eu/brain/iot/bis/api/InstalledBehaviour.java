package eu.brain.iot.bis.api;

import java.util.List;

import org.osgi.dto.DTO;

/** A behaviour installed by the installer, with the bundles that came with it. */
public class InstalledBehaviour extends DTO {
    public String symbolicName;
    public String version;
    public long bundleId;
    /** Event types it consumes. */
    public List<String> consumed;
    /** The index it came from. */
    public String repository;
    /** Bundles installed for it alone or shared with other behaviours (the behaviour's own bundle included). */
    public List<InstalledBundle> bundles;
    /** When it was installed (milliseconds since the epoch). */
    public long installedAt;
    /** Why, as the request said. */
    public String reason;
    /** The bundle's state now: {@code ACTIVE}, {@code STARTING}, {@code RESOLVED}, {@code INSTALLED} or {@code UNINSTALLED}. */
    public String state;
}
