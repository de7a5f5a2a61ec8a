package eu.brain.iot.federation.api;

/** Service properties by which a consumer on the bus tells the fabric how to treat it. */
public final class FabricProperties {

    /**
     * A smart behaviour (typed or untyped) registered with this property set to {@code true} (a {@code Boolean}, or
     * the text {@code "true"}) takes the events published on its own node only: the fabric does not announce it to
     * the other nodes, so no node forwards an event to this node for it. For monitoring consumers such as the
     * dashboard: announced, their interest (every command, every outcome) would pull the events of every node to each
     * node that runs one. Other behaviours on its node still consume what they announce.
     */
    public static final String LOCAL_ONLY = "eu.brain.iot.fabric.local";

    private FabricProperties() {
    }
}
