package eu.brain.iot.eventing.spi;

import org.osgi.dto.DTO;

/** The events held for one event type. */
public class HeldType extends DTO {
    /** The fully qualified event type name. */
    public String eventType;
    /** How many events of this type are held now. */
    public int count;
    /** When the oldest of them was published (milliseconds since the epoch). */
    public long since;
}
