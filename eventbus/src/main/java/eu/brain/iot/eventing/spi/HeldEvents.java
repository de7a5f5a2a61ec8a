package eu.brain.iot.eventing.spi;

import java.util.List;

import org.osgi.annotation.versioning.ProviderType;

/**
 * The events the bus holds for an {@link UnhandledEventPolicy}, waiting for a behaviour that consumes them.
 * Registered by the bus. Held events are handed over by the bus itself when a behaviour that takes them is
 * registered; this service only lets the policy see them and give up on them.
 * <p>
 * Threading: every method may be called from any thread, but not from within
 * {@link UnhandledEventPolicy#unhandled}.
 */
@ProviderType
public interface HeldEvents {

    /** @return one entry per event type with held events, oldest first */
    List<HeldType> held();

    /**
     * Give up on the held events of one type: they are counted as unhandled in the bus's statistics and logged
     * (once, with the reason); later events of the type are again put to the policy.
     *
     * @param eventType the event's fully qualified type name
     * @param reason why, for the log (e.g. "no repository has a behaviour that consumes it")
     * @return how many events were discarded
     */
    int discard(String eventType, String reason);
}
