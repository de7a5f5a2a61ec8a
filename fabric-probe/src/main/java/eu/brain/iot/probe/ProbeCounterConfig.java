package eu.brain.iot.probe;

/** The counting behaviour (PID {@value #PID}). */
public @interface ProbeCounterConfig {
    String PID = "eu.brain.iot.probe.counter";

    /**
     * Where every event taken is appended ("run seq" lines), read back at start: counts survive a restart. Empty:
     * counts in memory only, as the node-to-node benchmark runs it (a file write inside {@code notify()}, which the
     * operating system stalls now and then, would be measured as the fabric's latency).
     */
    String file() default "";
}
