package eu.brain.iot.probe;

/** A publishing run (PID {@value #PID}); each new configuration (another {@code run}) publishes once. */
public @interface ProbePublisherConfig {
    String PID = "eu.brain.iot.probe.publisher";

    /** The run's name, carried by every event. */
    String run();

    /** Events to publish, numbered 1..count. */
    long count() default 1000;

    /** Events per second; 0: back to back. */
    int rate() default 500;

    /** How long to wait for another node's behaviour to take probe events (its interest), seconds. */
    int consumer_timeout_s() default 120;
}
