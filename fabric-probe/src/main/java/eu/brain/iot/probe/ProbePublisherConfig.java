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

    /**
     * How long to wait for a consumer of probe events on this node (a behaviour, or the federation's forwarder for
     * another node's), seconds; 0: publish at once, without waiting (the events nobody takes are the BMS's).
     */
    int consumer_timeout_s() default 120;
}
