package eu.brain.iot.federation.impl;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.AttributeType;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/**
 * The configuration of a node's membership in a fabric (PID {@value #PID}). Without it the federation component does
 * not activate and the node runs alone.
 */
@ObjectClassDefinition(name = "BRAIN-IoT fabric membership", description = "Joins this node to a fabric of nodes "
        + "through an MQTT 5 broker.")
public @interface FabricConfig {

    /** The configuration PID. */
    String PID = "eu.brain.iot.federation";

    @AttributeDefinition(description = "The MQTT 5 broker: tcp://host:port, or ssl://host:port with tls=true")
    String broker_uri() default "tcp://127.0.0.1:1883";

    @AttributeDefinition(description = "The fabric's name: the root of its topic tree is brainiot/<fabric>/")
    String fabric_name() default "default";

    @AttributeDefinition(description = "This node's name in the fabric (letters, digits, '-', '_', '.'); empty: the "
            + "framework property fabric.node.name, else the host name")
    String node_name() default "";

    @AttributeDefinition(description = "Broker user name; empty for none")
    String username() default "";

    @AttributeDefinition(type = AttributeType.PASSWORD, description = "Broker password")
    String _password() default "";

    @AttributeDefinition(description = "Connect with TLS (broker_uri ssl://...)")
    boolean tls() default false;

    @AttributeDefinition(description = "PKCS12 or JKS trust store for TLS; empty: the JVM's default trust")
    String trust_store() default "";

    @AttributeDefinition(type = AttributeType.PASSWORD, description = "Trust store password")
    String _trust_store_password() default "";

    @AttributeDefinition(description = "The fabric's signing key file (created by fabric:keygen FILE); required")
    String key_file() default "";

    @AttributeDefinition(description = "Folder of the node's fabric state (outgoing events until acknowledged, "
            + "windows of received sequences); empty: the framework property fabric.node.state.dir, else "
            + "<user.home>/.brain-iot/federation/<fabric>/<node>")
    String state_dir() default "";

    @AttributeDefinition(description = "MQTT keep-alive in seconds; the broker sends the Last Will after 1.5 of them")
    int keep_alive_s() default 10;

    @AttributeDefinition(description = "How long the broker keeps this node's session while it is away, seconds")
    long session_expiry_s() default 3600;

    @AttributeDefinition(description = "Events sent but not acknowledged for this long are sent again, ms")
    long resend_timeout_ms() default 5000;

    @AttributeDefinition(description = "Events kept per remote node until acknowledged; beyond that publishing to "
            + "it pushes back like a full behaviour queue")
    int max_pending() default 100_000;

    @AttributeDefinition(description = "Messages signed longer ago than this (or this far ahead) are refused as "
            + "replays, ms")
    long max_age_ms() default 300_000;

    @AttributeDefinition(description = "Most events in one MQTT message")
    int batch_max_events() default 256;

    @AttributeDefinition(description = "How long the BMS's question 'which node installs a behaviour for this event?'"
            + " waits for the other online nodes' answers, ms; the choice is made at the first of all answers or this")
    long install_bid_ms() default 100;

    @AttributeDefinition(description = "How long an install on another node may take until its behaviour's interest"
            + " arrives, ms; then the BMS is told it failed, naming the node")
    long install_timeout_ms() default 120_000;

    @AttributeDefinition(description = "How long another node may stay offline before the events kept for it (sent,"
            + " not acknowledged) are published again here for whoever takes them then, ms; a node away for half of "
            + "it or more comes back with a clean broker session")
    long offline_giveup_ms() default 30_000;
}
