package eu.brain.iot.eventing.monitoring.api;

import java.util.List;

import org.osgi.dto.DTO;

/** Counters of one consumer (a smart behaviour service) since it was registered. */
public class ConsumerStatistics extends DTO {
    /** A readable name: the component or behaviour name, bundle and service id. */
    public String consumer;
    /** The service id of the behaviour. */
    public long serviceId;
    /** The symbolic name of the bundle that registered it. */
    public String bundle;
    /** The consumed event type names (empty for a consumer of last resort). */
    public List<String> consumed;
    /** The behaviour's filter, or empty. */
    public String filter;
    /** Whether it is a consumer of last resort. */
    public boolean lastResort;
    /** Whether it receives maps ({@code UntypedSmartBehaviour}) rather than typed events. */
    public boolean untyped;
    /** Events waiting in its queue now. */
    public int queueDepth;
    /** Events it handled without exception. */
    public long delivered;
    /** Events whose handling threw. */
    public long failures;
    /**
     * Whether it is stalled: its queue full and its notify() not returned for the bus's overflow timeout; it
     * takes no events until notify() returns, and those published for it meanwhile are discarded.
     */
    public boolean stalled;
    /** Events discarded for it because it was stalled. */
    public long discarded;
}
