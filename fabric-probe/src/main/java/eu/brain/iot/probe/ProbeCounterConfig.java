package eu.brain.iot.probe;

/** The counting behaviour (PID {@value #PID}). */
public @interface ProbeCounterConfig {
    String PID = "eu.brain.iot.probe.counter";

    /** Where every event taken is appended ("run seq" lines), read back at start: counts survive a restart. */
    String file();
}
