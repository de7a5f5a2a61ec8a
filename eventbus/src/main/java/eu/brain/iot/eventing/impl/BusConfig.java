package eu.brain.iot.eventing.impl;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the event bus (PID {@value #PID}); every value has a safe default. */
@ObjectClassDefinition(name = "BRAIN-IoT event bus", description = "Bounds of the asynchronous event bus")
@interface BusConfig {

    /** The configuration PID; the bus's core names it in its errors, the component is configured by it. */
    String PID = "eu.brain.iot.eventing";

    /**
     * The default of {@link #stall_warning_ms()}: ordinary notify() calls on a node's start took up to 160 ms when
     * measured (a behaviour's first event: its component activated, its classes loaded and compiled), later ones up
     * to 50 ms on a loaded machine; a second is several times that, and short for a behaviour that is really stuck.
     */
    long DEFAULT_STALL_WARNING_MS = 1_000;

    @AttributeDefinition(description = "Events that may wait in one behaviour's queue; bounds the bus's memory")
    int queue_capacity() default 65_536;

    @AttributeDefinition(description = "How long deliver() waits for room in a full queue before it throws "
            + "EventBusOverflowException (milliseconds)")
    long overflow_timeout_ms() default 5_000;

    @AttributeDefinition(description = "Delivery workers that take turns on the behaviours' queues; 0 means one "
            + "per available processor, at least 2. More workers than cores only adds wake-ups.")
    int delivery_workers() default 0;

    @AttributeDefinition(description = "How long an idle delivery worker keeps yielding before it sleeps "
            + "(microseconds). Longer saves wake-ups at high event rates; shorter saves CPU at low rates.")
    long idle_spin_us() default 50;

    @AttributeDefinition(description = "When a behaviour has held its delivery worker this long in one notify() "
            + "call while waiting (milliseconds, at least 1; four times as long while computing or in blocking I/O), "
            + "the bus starts another worker so that the other behaviours keep receiving. Workers beyond "
            + "delivery.workers retire after a second without work.")
    long stall_threshold_ms() default 5;

    @AttributeDefinition(description = "When a behaviour has been inside one notify() call this long (milliseconds, "
            + "at least 1), the bus logs a warning naming it, once per behaviour. Shorter stalls only start another "
            + "delivery worker (stall.threshold.ms), which is ordinary at a behaviour's first events")
    long stall_warning_ms() default DEFAULT_STALL_WARNING_MS;
}
