package eu.brain.iot.eventing.api;

import org.osgi.annotation.versioning.ConsumerType;

/**
 * A behaviour that consumes typed events. Register it as an OSGi service annotated with
 * {@link eu.brain.iot.eventing.annotation.SmartBehaviourDefinition}, which names the consumed event types.
 * <p>
 * The bus calls {@link #notify(BrainIoTEvent)} from a thread of its own, one event at a time per behaviour,
 * in publish order (per publishing thread). A slow or failing behaviour never delays another one.
 *
 * @param <T> the consumed event type
 */
@ConsumerType
public interface SmartBehaviour<T extends BrainIoTEvent> {

    /**
     * Receive one event. The object belongs to this behaviour alone.
     *
     * @param event the event, never {@code null}
     */
    void notify(T event);
}
