package eu.brain.iot.containers.probe;

/** The counting behaviour (PID {@value #PID}). */
public @interface ProbeCounterConfig {
    String PID = "eu.brain.iot.containers.probe.counter";

    /** Where every event taken is appended ("run seq" lines), read back at start: counts survive a restart. */
    String file();
}
