package eu.brain.iot.bms.impl;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the Behaviour Management Service (PID {@value BehaviourManagerComponent#PID}); all optional. */
@ObjectClassDefinition(name = "BRAIN-IoT Behaviour Management Service",
        description = "Installs missing behaviours when their first event arrives")
@interface BmsConfig {

    @AttributeDefinition(description = "Events the bus may hold for the BMS, all types together, while behaviours "
            + "are installed. Beyond that a publisher waits as for a full behaviour queue (the bus's "
            + "overflow.timeout.ms), then gets an EventBusOverflowException: nothing is dropped silently.")
    int max_held_events() default 65_536;

    @AttributeDefinition(description = "After no repository had a behaviour for a type (or an operator removed it, "
            + "or the BMS gave up), how long its events are counted as unhandled without searching again (ms)")
    long negative_cache_ms() default 60_000;

    @AttributeDefinition(description = "Delay before the first retry of a failed install (ms); doubles at each "
            + "further failure up to retry.max.ms")
    long retry_initial_ms() default 500;

    @AttributeDefinition(description = "Longest delay between two install attempts (ms)")
    long retry_max_ms() default 30_000;

    @AttributeDefinition(description = "How long held events wait for their behaviour, from the type's first "
            + "event (ms). Past it the BMS gives up: the held events are discarded (counted as unhandled, logged).")
    long install_deadline_ms() default 120_000;

    @AttributeDefinition(description = "How long after a successful install events of its types are still held "
            + "(ms). 0 for an installer that, as the local one, answers only once the behaviour is registered with "
            + "the bus; more for one that may answer earlier (a remote installer). Events still held after it are "
            + "not taken by the behaviour (its filter) and are given up on.")
    long handover_grace_ms() default 0;

    @AttributeDefinition(description = "How often the BMS looks at the bus's held events for deadlines and events "
            + "nothing waits for (ms)")
    long sweep_interval_ms() default 1_000;

    @AttributeDefinition(description = "Event types never searched for: their events are counted as unhandled at "
            + "once. Exact names, or prefixes ending in '*' (e.g. eu.brain.iot.edge.api.*)")
    String[] ignored_types() default {};

    @AttributeDefinition(description = "How many entries bms:history keeps")
    int history_size() default 256;

    @AttributeDefinition(description = "How long after a behaviour's bundle stopped or was uninstalled outside "
            + "the installer (a failure, Gogo's stop or uninstall; not bis:stop, bis:uninstall nor the installer's "
            + "own work) the BMS waits before it has the installer start it again, or install it again, without "
            + "waiting for an event (ms). A bundle active again by then (a refresh, an update) is left alone. Nothing "
            + "is brought back while the framework shuts down.")
    long restart_grace_ms() default 1_000;
}
