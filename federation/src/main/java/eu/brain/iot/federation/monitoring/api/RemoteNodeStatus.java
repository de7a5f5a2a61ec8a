package eu.brain.iot.federation.monitoring.api;

import java.util.List;

import org.osgi.dto.DTO;

/** Another node of the fabric as this node knows it, and what passed between the two since this node started. */
public class RemoteNodeStatus extends DTO {
    /** Announced online (its status message), its events routed to it. */
    public static final String ONLINE = "online";
    /** Gone: its goodbye, or its Last Will sent by the broker. */
    public static final String OFFLINE = "offline";
    /** Known (events kept for it, or an interest seen) but no presence received yet. */
    public static final String UNKNOWN = "unknown";

    /** Its name in the fabric (letters, digits, {@code .}, {@code _}, {@code -}). */
    public String name;
    /** {@link #ONLINE}, {@link #OFFLINE} or {@link #UNKNOWN}. */
    public String status;
    /**
     * When this node was first seen in {@link #status} (milliseconds since the epoch), exact to the period of the
     * monitor's readers (see {@link FabricStatus#since}).
     */
    public long since;
    /** How many behaviours it announces (one interest entry each). */
    public int interestEntries;
    /** The event types its behaviours consume, sorted, as it announced them (text from the network). */
    public List<String> eventTypes;
    /** Events this node published to it, those sent again ({@link #resent}) included. */
    public long sent;
    /** Events sent to it again (no acknowledgement within the resend timeout, or after a reconnection). */
    public long resent;
    /** Events it acknowledged. */
    public long acknowledged;
    /** Events kept for it until it acknowledges them. */
    public long backlog;
    /** Events received from it and handed, in its order, to this node's bus (duplicates not counted). */
    public long received;
    /** Events received from it a second time and dropped. */
    public long duplicates;
    /** Messages from it refused: unsigned, wrongly signed, replayed or malformed. */
    public long refused;
    /** How many behaviours its installer installed; {@code null}: not known here. */
    public Integer installedBehaviours;
}
