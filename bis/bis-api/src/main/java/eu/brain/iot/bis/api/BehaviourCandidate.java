package eu.brain.iot.bis.api;

import java.util.List;

import org.osgi.dto.DTO;

/** A behaviour bundle offered by a repository index. */
public class BehaviourCandidate extends DTO {
    public String symbolicName;
    public String version;
    /** The event types its {@code eu.brain.iot.behaviour} capability says it consumes. */
    public List<String> consumed;
    /** The URL of the index that lists it. */
    public String repository;
    /** Where its bytes are, resolved against the index's URL. */
    public String url;
    /** The SHA-256 the index gives for its bytes (hex). */
    public String sha256;
    public long size;
    /**
     * The fabric node whose installer offers it and would install it, as an installer that spans several nodes
     * chose it; {@code null} from an installer of this node alone. Passed back in {@link InstallRequest#node}.
     */
    public String node;
}
