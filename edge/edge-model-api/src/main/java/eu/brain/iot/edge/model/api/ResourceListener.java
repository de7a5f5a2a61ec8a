package eu.brain.iot.edge.model.api;

import org.osgi.annotation.versioning.ConsumerType;

/**
 * Told of every change of the resources it subscribed to (a new value or a new status). Called on the edge's
 * own thread, in the order of the changes: it must return quickly and must not block (hand the value to your
 * own queue or thread).
 */
@ConsumerType
@FunctionalInterface
public interface ResourceListener {
    void changed(ResourceValue value);
}
