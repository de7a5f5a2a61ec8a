package eu.brain.iot.eventing.api;

import java.time.Instant;

import org.osgi.dto.DTO;

/**
 * The base type of every event exchanged on the BRAIN-IoT event bus.
 * <p>
 * Events are data transfer objects: public fields, a public no-argument constructor and no behaviour.
 * The bus gives every consumer its own copy of an event, taken when {@link EventBus#deliver(BrainIoTEvent)}
 * is called, so a consumer may change the event it receives without anyone else seeing it, and a publisher
 * may reuse its event object once {@code deliver} returns. Copies are shallow for immutable values
 * (strings, numbers, enums, {@code java.time} values) and deep for arrays, collections, maps and nested
 * data objects.
 * <p>
 * Implementing {@link Cloneable} lets the bus take those copies with {@link Object#clone()} instead of
 * reflection; subclasses need not do anything about it.
 * <p>
 * As in the original BRAIN-IoT eventing API, an event is an OSGi {@link DTO}, so code that treats events as DTOs
 * (the OSGi Converter's DTO rules, {@link DTO#toString()}) keeps working.
 */
public abstract class BrainIoTEvent extends DTO implements Cloneable {

    /** The framework UUID of the node that published the event; filled in by the bus when missing. */
    public String sourceNode;

    /** When the event was published; filled in by the bus when missing. */
    public Instant timestamp;

    /** An opaque token that a security layer may attach to the event. */
    public byte[] securityToken;

    public BrainIoTEvent() {
        // DTO: public no-arg constructor
    }
}
