package eu.brain.iot.bis.api;

import org.osgi.dto.DTO;

/** One bundle the installer put into the framework. */
public class InstalledBundle extends DTO {
    public String symbolicName;
    public String version;
    public long bundleId;
    /** The SHA-256 of its bytes, as verified against the index (hex). */
    public String sha256;
    /** How many installed behaviours need it. */
    public int users;
}
