package eu.brain.iot.edge.rest;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/**
 * Configuration of the northbound REST API (PID {@value #PID}); every value has a default, so none is needed.
 * Where it listens is Felix HTTP's business: framework properties {@code org.apache.felix.http.host} and
 * {@code org.osgi.service.http.port}; this API reads the host to know whether it is exposed (then it requires a token).
 */
@ObjectClassDefinition(name = "BRAIN-IoT edge: northbound REST (sensiNact-style)",
        description = "Time limits, buffers, accepted host names and authentication of /sensinact")
@interface RestConfig {

    String PID = "eu.brain.iot.edge.rest";

    @AttributeDefinition(description = "How long an ACT waits for the device's answer before it answers 504 (milliseconds)")
    long act_timeout_ms() default 5_000;

    @AttributeDefinition(description = "Largest ACT body accepted (bytes); a larger one answers 413")
    int act_max_body_bytes() default 65_536;

    @AttributeDefinition(description = "Time an ACT's body may take to arrive whole (milliseconds); then 408 and the "
            + "connection closes")
    long act_body_timeout_ms() default 10_000;

    @AttributeDefinition(description = "Changes an SSE client may have waiting; one more and it is disconnected as too slow")
    int sse_queue_capacity() default 1_024;

    @AttributeDefinition(description = "SSE streams (/sensinact/subscribe) open at most, all clients together; "
            + "more are answered 503. Keeps connections (max.connections) free for ordinary requests")
    int sse_max_streams() default 256;

    @AttributeDefinition(description = "Time between two heartbeat comments on every SSE stream (milliseconds); "
            + "a write that fails tells a client that went away")
    long sse_heartbeat_ms() default 15_000;

    @AttributeDefinition(description = "Time an SSE client may leave the connection unable to take more bytes "
            + "(milliseconds); then it is disconnected as not reading")
    long sse_write_timeout_ms() default 30_000;

    @AttributeDefinition(description = "More names accepted in the Host and Origin headers (name or name:port), besides "
            + "127.0.0.1, localhost, [::1] and the bound address, each with the port; e.g. edge.example or 192.168.1.20")
    String[] allowed_hosts() default {};

    @AttributeDefinition(description = "Authentication: 'auto' requires the API token when the API is bound to "
            + "anything but loopback (org.apache.felix.http.host); 'token' always requires it", options = {
                    @org.osgi.service.metatype.annotations.Option(value = "auto"),
                    @org.osgi.service.metatype.annotations.Option(value = "token") })
    String auth() default "auto";

    @AttributeDefinition(description = "The API token's file; empty: ${XDG_CONFIG_HOME:-~/.config}/brain-iot/"
            + "<fabric.node.name or 'node'>/api-token (created at first need, mode 600)")
    String api_token_file() default "";

    @AttributeDefinition(description = "Lifetime of a browser session cookie from POST /sensinact/session (seconds)")
    long session_max_age_s() default 43_200;

    @AttributeDefinition(description = "Connections Jetty keeps open at most, all clients together; beyond, it "
            + "stops accepting until one closes")
    int max_connections() default 1_000;

    @AttributeDefinition(description = "Connections one client address may keep open at once; more are closed as "
            + "they open")
    int max_connections_per_client() default 64;

    @AttributeDefinition(description = "Send buffer of every connection Jetty accepts (bytes; the kernel may double "
            + "it); bounds what a client that stopped reading can hold back, so sse.write.timeout.ms finds it within "
            + "seconds instead of after the kernel's self-grown buffers (megabytes) fill; 0 leaves it to the kernel")
    int send_buffer_bytes() default 32_768;
}
