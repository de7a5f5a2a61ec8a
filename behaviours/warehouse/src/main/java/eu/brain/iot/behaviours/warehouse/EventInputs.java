package eu.brain.iot.behaviours.warehouse;

import java.util.Map;
import java.util.Set;
import java.util.function.Function;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * A binding's table from each consumed event type to the input its thread handles, made on the bus's thread: an
 * event becomes the input of its class, or of the nearest superclass in the table (the bus delivers the consumed
 * types' subtypes too). The table names the same types as the binding's consumed list (each binding's input test
 * ties the two). Immutable: any thread.
 *
 * @param <I> the binding's input type
 */
public final class EventInputs<I> {

    private final Map<Class<? extends BrainIoTEvent>, Function<BrainIoTEvent, I>> table;

    private EventInputs(Map<Class<? extends BrainIoTEvent>, Function<BrainIoTEvent, I>> table) {
        this.table = table;
    }

    /** @return the table of these entries ({@link #input}) */
    @SafeVarargs
    public static <I> EventInputs<I> of(
            Map.Entry<Class<? extends BrainIoTEvent>, Function<BrainIoTEvent, I>>... entries) {
        return new EventInputs<>(Map.ofEntries(entries));
    }

    /** @return an entry of a table: events of {@code type} become {@code make}'s input */
    public static <E extends BrainIoTEvent, I> Map.Entry<Class<? extends BrainIoTEvent>, Function<BrainIoTEvent, I>>
            input(Class<E> type, Function<E, I> make) {
        return Map.entry(type, event -> make.apply(type.cast(event)));
    }

    /** @return the event types of the table */
    public Set<Class<? extends BrainIoTEvent>> types() {
        return table.keySet();
    }

    /** @return the input the event becomes, or {@code null} for an event of a type the table does not know */
    public I inputOf(BrainIoTEvent event) {
        for (Class<?> c = event.getClass(); c != null; c = c.getSuperclass()) {
            Function<BrainIoTEvent, I> make = table.get(c);
            if (make != null) {
                return make.apply(event);
            }
        }
        return null;
    }
}
