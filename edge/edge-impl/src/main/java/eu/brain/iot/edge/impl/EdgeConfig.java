package eu.brain.iot.edge.impl;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the edge (PID {@value #PID}); every value has a default that suits robot-sim. */
@ObjectClassDefinition(name = "BRAIN-IoT edge (sensiNact-style gateway)",
        description = "Where the robot fleet answers, what to poll and how often")
@interface EdgeConfig {

    /** The configuration PID; the edge's core names it in its messages, the component is configured by it. */
    String PID = "eu.brain.iot.edge";

    /** Where robot-sim listens by default. */
    String DEFAULT_FLEET_URL = "http://127.0.0.1:8090/";

    @AttributeDefinition(description = "Base URL of the fleet's REST API (robot-sim: one port for every robot and door)")
    String fleet_url() default DEFAULT_FLEET_URL;

    @AttributeDefinition(description = "Robot ids to poll. Empty, with doors empty too: ask the fleet (GET /)")
    String[] robots() default {};

    @AttributeDefinition(description = "Door ids to poll. Empty, with robots empty too: ask the fleet (GET /)")
    String[] doors() default {};

    @AttributeDefinition(description = "Time between two polls of one device (milliseconds)")
    long poll_period_ms() default 500;

    @AttributeDefinition(description = "How long to wait for a device's answer (milliseconds)")
    long request_timeout_ms() default 1_000;

    @AttributeDefinition(description = "Keep-alive connections per fleet host: bounds requests in flight")
    int max_connections() default 64;

    @AttributeDefinition(description = "HTTP client I/O threads (the client is asynchronous: no thread per robot)")
    int io_threads() default 1;

    @AttributeDefinition(description = "Failed polls in a row after which a device is reported unreachable")
    int unreachable_after_failures() default 3;

    @AttributeDefinition(description = "Longest time between two polls of an unreachable device (milliseconds)")
    long backoff_max_ms() default 8_000;

    @AttributeDefinition(description = "Time between two reads of the fleet's world (GET /world: where the carts "
            + "stand, the map), as providers cart1.. and warehouse (milliseconds; 0: never)")
    long world_period_ms() default 2_000;

    @AttributeDefinition(description = "This node's share of the fleet's robots and doors, which it polls and "
            + "commands: 'all'; K/N (the K-th of N nodes: robots whose number modulo N is K-1, the doors when K is "
            + "doors.owner); or device ids separated by commas. A lease manager may move devices at run time")
    String share() default Share.ALL;

    @AttributeDefinition(description = "With share K/N: the node number (1..N) that owns the doors")
    int doors_owner() default 1;

    @AttributeDefinition(description = "The share is this node's only once a lease manager takes it (PID "
            + "eu.brain.iot.federation.lease): a node of a fabric first hears which node holds what, so that a node "
            + "started again does not command robots another node took over meanwhile")
    boolean share_leased() default false;
}
