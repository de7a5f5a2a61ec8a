package eu.brain.iot.bis.api;

import java.util.List;

import org.osgi.dto.DTO;

/**
 * What to install: a behaviour by identity ({@link #symbolicName}, optionally {@link #versionRange}), or the best
 * behaviour that consumes one of {@link #consumedTypes}. One of the two is required.
 */
public class InstallRequest extends DTO {
    /** The behaviour bundle's symbolic name, or {@code null} to choose by {@link #consumedTypes}. */
    public String symbolicName;
    /** An OSGi version range such as {@code [1.0,2)}; {@code null} for any. */
    public String versionRange;
    /** Event type names the behaviour must consume (any of them), e.g. an event's type and its supertypes. */
    public List<String> consumedTypes;
    /** Why it is installed, recorded in the journal, e.g. "event eu.brain.iot.X had no consumer". */
    public String reason;
    /** {@code true} when a person asked for it (Gogo, REST): overrides and clears an operator's earlier removal. */
    public boolean operator;
    /**
     * The fabric node that installs it ({@link BehaviourCandidate#node} of the chosen candidate); {@code null} for
     * this node. An installer of this node alone ignores it.
     */
    public String node;
}
