package eu.brain.iot.federation.monitoring.api;

import java.util.List;

import org.osgi.dto.DTO;

/** This node in its fabric, and the other nodes it knows. */
public class FabricStatus extends DTO {
    /** The node is connected to the broker and announced itself. */
    public static final String ONLINE = "online";
    /** The node is a member but not connected now (starting, or the broker is unreachable; it keeps trying). */
    public static final String JOINING = "joining";
    /** The node has a fabric configuration but does not join: see {@link #problem}. */
    public static final String NOT_JOINED = "not joined";

    /** This node's name in the fabric. */
    public String node;
    /** The fabric's name (its topic tree is {@code brainiot/<fabric>/}). */
    public String fabric;
    /** The broker's URI. */
    public String brokerUri;
    /** {@link #ONLINE}, {@link #JOINING} or {@link #NOT_JOINED}. */
    public String state;
    /**
     * When this node was first seen in {@link #state} (milliseconds since the epoch): the monitor notes a change
     * when it is read, so this is exact to its readers' period (the dashboard reads every second).
     */
    public long since;
    /** Why the node does not join ({@link #NOT_JOINED}: its key, its state folder), else {@code null}. */
    public String problem;
    /** How many of this node's behaviours the fabric announces (one interest entry each). */
    public int interestEntries;
    /** The event types this node's behaviours consume, sorted. */
    public List<String> eventTypes;
    /** How many behaviours this node's installer installed; {@code null} when the node has no installer. */
    public Integer installedBehaviours;
    /** The other nodes this node knows of, sorted by name. */
    public List<RemoteNodeStatus> remotes;
}
