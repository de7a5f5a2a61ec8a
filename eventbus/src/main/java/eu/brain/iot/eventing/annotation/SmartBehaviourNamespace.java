package eu.brain.iot.eventing.annotation;

/**
 * Names shared by the smart behaviour capability (in a bundle's {@code Provide-Capability}) and the service
 * properties of smart behaviour services. A repository index finds a behaviour by the {@link #CONSUMED} attribute
 * of a capability in {@link #NAMESPACE}.
 */
public final class SmartBehaviourNamespace {

    /** The capability namespace of smart behaviours. */
    public static final String NAMESPACE = "eu.brain.iot.behaviour";

    /** Capability attribute ({@code List<String>}): the names of the consumed event types. */
    public static final String CONSUMED = "consumed";
    /** Capability attribute: the behaviour's author. */
    public static final String AUTHOR = "author";
    /** Capability attribute: the behaviour's name. */
    public static final String NAME = "name";
    /** Capability attribute: the behaviour's description. */
    public static final String DESCRIPTION = "description";
    /** Capability attribute ({@code Boolean}): the behaviour is a consumer of last resort. */
    public static final String LAST_RESORT = "consumer.of.last.resort";

    /** Prefix of every smart behaviour service property. */
    public static final String PROPERTY_PREFIX = NAMESPACE + ".";
    /** Service property ({@code String[]}): the names of the consumed event types. */
    public static final String CONSUMED_PROPERTY = PROPERTY_PREFIX + CONSUMED;
    /** Service property ({@code String}): an LDAP filter over the event's fields; empty for none. */
    public static final String FILTER_PROPERTY = PROPERTY_PREFIX + "filter";
    /** Service property ({@code Boolean}): the behaviour receives only events no one else consumes. */
    public static final String LAST_RESORT_PROPERTY = PROPERTY_PREFIX + LAST_RESORT;

    private SmartBehaviourNamespace() {
        // constants only
    }
}
