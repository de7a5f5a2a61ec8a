package eu.brain.iot.dashboard;

import java.util.Map;
import java.util.Set;

import eu.brain.iot.edge.model.api.ResourceValue;

/**
 * What the edge's thread or a bus worker hands to the dashboard's own thread: typed, and each kind knows how it
 * is applied, so that the thread that applies changes never sorts objects by guessing.
 */
sealed interface Change {

    /**
     * Applies the change on the dashboard thread.
     *
     * @param reloads receives the ids of providers to read again whole from the model
     */
    void apply(Devices devices, Activity activity, Set<String> reloads);

    /** A resource of the device model changed (value or status). */
    record Resource(ResourceValue value) implements Change {
        @Override
        public void apply(Devices devices, Activity activity, Set<String> reloads) {
            if (devices.apply(value)) {
                reloads.add(value.provider());
            }
        }
    }

    /** An event of a consumed type arrived on the bus, as its fields by name. */
    record BusEvent(String type, Map<String, ?> fields) implements Change {
        @Override
        public void apply(Devices devices, Activity activity, Set<String> reloads) {
            activity.event(type, fields, devices);
        }
    }
}
