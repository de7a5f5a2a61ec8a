package eu.brain.iot.eventing.impl;

/**
 * Access to a behaviour service object, obtained lazily by its delivery thread. Getting the object at bind time
 * would activate the behaviour's component while the bus itself may still be activating (a behaviour needs the
 * bus), which Declarative Services reports as a circular reference and the behaviour would be missed.
 */
interface BehaviourHandle {

    /** @return the behaviour object, or {@code null} if the service has gone away */
    Object get();

    /** Give the object back; called once by the delivery thread when it ends, only if {@link #get} was called. */
    void release();

    /** A handle on an object that needs no lookup or release (tests, benchmarks). */
    static BehaviourHandle of(Object behaviour) {
        return new BehaviourHandle() {
            @Override
            public Object get() {
                return behaviour;
            }

            @Override
            public void release() {
                // nothing to give back
            }
        };
    }
}
