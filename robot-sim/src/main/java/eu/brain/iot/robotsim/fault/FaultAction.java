package eu.brain.iot.robotsim.fault;

/** What to do with one request to a robot's endpoint. */
public enum FaultAction {
    /** Answer normally. */
    NONE,
    /** Answer 503: the robot is offline. */
    OFFLINE,
    /** Close the connection without an answer. */
    DROP,
    /** Answer 500. */
    ERROR_500,
    /** Act normally but answer a truncated JSON body. */
    MALFORMED
}
