package eu.brain.iot.dashboard;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/**
 * Configuration of the dashboard (PID {@value #PID}); every value has a default, so none is needed. Where the page
 * is served is Felix HTTP's business (framework properties {@code org.apache.felix.http.host} and
 * {@code org.osgi.service.http.port}), under {@code /dashboard/}.
 */
@ObjectClassDefinition(name = "BRAIN-IoT dashboard", description = "The live page of the warehouse and the fabric")
@interface DashboardConfig {

    String PID = "eu.brain.iot.dashboard";

    @AttributeDefinition(description = "Changes are gathered for this long, then sent as one event (milliseconds); the edge polls every 500 ms, and each event costs the page a redraw")
    long flush_ms() default 500;

    @AttributeDefinition(description = "How often the bus statistics, the installed behaviours and the BMS history "
            + "are read (milliseconds)")
    long fabric_period_ms() default 1_000;

    @AttributeDefinition(description = "Events kept for clients that reconnect with Last-Event-ID; an older id gets "
            + "a fresh snapshot instead")
    int replay_events() default 240;

    @AttributeDefinition(description = "Events a client may have waiting; one more and it is disconnected as too "
            + "slow (it reconnects and catches up)")
    int client_queue_capacity() default 128;

    @AttributeDefinition(description = "Streams (pages open) at most, all clients together; more are answered 503. "
            + "Keeps the server's connections free for other requests")
    int max_streams() default 64;

    @AttributeDefinition(description = "Time between two heartbeat comments on every stream (milliseconds)")
    long heartbeat_ms() default 15_000;

    @AttributeDefinition(description = "Decisions (commands and their outcomes) kept in the log")
    int decisions() default 30;
}
