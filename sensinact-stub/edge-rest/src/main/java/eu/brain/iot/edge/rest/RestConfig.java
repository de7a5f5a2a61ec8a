package eu.brain.iot.edge.rest;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/**
 * Configuration of the northbound REST API (PID {@value #PID}); every value has a default, so none is needed.
 * Where it listens is Felix HTTP's business: framework properties {@code org.apache.felix.http.host} and
 * {@code org.osgi.service.http.port}.
 */
@ObjectClassDefinition(name = "BRAIN-IoT edge: northbound REST (sensiNact-style)",
        description = "Time limits and buffers of /sensinact")
@interface RestConfig {

    String PID = "eu.brain.iot.edge.rest";

    @AttributeDefinition(description = "How long an ACT waits for the device's answer before it answers 504 (milliseconds)")
    long act_timeout_ms() default 5_000;

    @AttributeDefinition(description = "Largest ACT body accepted (bytes); a larger one answers 413")
    int act_max_body_bytes() default 65_536;

    @AttributeDefinition(description = "Changes an SSE client may have waiting; one more and it is disconnected as too slow")
    int sse_queue_capacity() default 1_024;

    @AttributeDefinition(description = "Time between two heartbeat comments on every SSE stream (milliseconds); "
            + "a write that fails tells a client that went away")
    long sse_heartbeat_ms() default 15_000;
}
