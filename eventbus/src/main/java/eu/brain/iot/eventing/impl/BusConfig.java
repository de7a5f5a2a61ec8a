package eu.brain.iot.eventing.impl;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the event bus (PID {@value EventBusComponent#PID}); every value has a safe default. */
@ObjectClassDefinition(name = "BRAIN-IoT event bus", description = "Bounds of the asynchronous event bus")
@interface BusConfig {

    @AttributeDefinition(description = "Events that may wait in one behaviour's queue; bounds the bus's memory")
    int queue_capacity() default 65_536;

    @AttributeDefinition(description = "How long deliver() waits for room in a full queue before it throws "
            + "EventBusOverflowException (milliseconds)")
    long overflow_timeout_ms() default 5_000;

    @AttributeDefinition(description = "How long an idle delivery thread keeps yielding before it sleeps "
            + "(microseconds). Longer saves wake-ups at high event rates; shorter saves CPU at low rates.")
    long idle_spin_us() default 50;
}
