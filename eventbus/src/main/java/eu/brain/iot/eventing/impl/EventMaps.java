package eu.brain.iot.eventing.impl;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.osgi.util.converter.Converter;
import org.osgi.util.converter.Converters;

/**
 * Conversions between events and maps of their fields, and between two classes of the same event loaded by
 * different bundles. Events become maps for untyped behaviours and for filter matching; a map becomes an event
 * for a typed behaviour that consumes an event published untyped, or published with another bundle's copy of
 * the class.
 * <p>
 * Reading an object's fields uses var handles fixed once per class. Building a typed object from a map uses the
 * OSGi Converter (its DTO rules: public fields, public no-argument constructor), which converts every field to its
 * declared type, nested data objects and collections included.
 */
final class EventMaps {

    private static final Converter CONVERTER = Converters.standardConverter();

    private static final ClassValue<Reader> READERS = new ClassValue<>() {
        @Override
        protected Reader computeValue(Class<?> type) {
            return Reader.build(type);
        }
    };

    private EventMaps() {
    }

    /** @return a new map of the object's data fields; nested data objects become maps, arrays and collections lists */
    static Map<String, Object> toMap(Object data) {
        return READERS.get(data.getClass()).read(data);
    }

    /** @return a new object of the target class built from a map of field values */
    static <T> T fromMap(Map<String, ?> fields, Class<T> target) {
        return CONVERTER.convert(fields).targetAsDTO().to(target);
    }

    /** @return a new object of the target class with the source's field values, matched by name */
    static <T> T convert(Object source, Class<T> target) {
        return fromMap(toMap(source), target);
    }

    /** @return a deep copy of a map of field values, as {@link #toMap} would have built it */
    static Map<String, Object> copyMap(Map<String, ?> fields) {
        Map<String, Object> copy = new LinkedHashMap<>();
        fields.forEach((k, v) -> copy.put(k, toValue(v)));
        return copy;
    }

    private static Object toValue(Object value) {
        if (value == null || EventCopier.isImmutable(value.getClass())) {
            return value;
        }
        if (value.getClass().isArray()) {
            int length = Array.getLength(value);
            List<Object> list = new ArrayList<>(length);
            for (int i = 0; i < length; i++) {
                list.add(toValue(Array.get(value, i)));
            }
            return list;
        }
        if (value instanceof Collection<?> coll) {
            List<Object> list = new ArrayList<>(coll.size());
            for (Object o : coll) {
                list.add(toValue(o));
            }
            return list;
        }
        if (value instanceof Map<?, ?> map) {
            Map<Object, Object> copy = new LinkedHashMap<>();
            map.forEach((k, v) -> copy.put(k, toValue(v)));
            return copy;
        }
        Reader reader = READERS.get(value.getClass());
        return reader.names.length == 0 ? value : reader.read(value);
    }

    /** Reads the data fields of one class. */
    private static final class Reader {
        final String[] names;
        final VarHandle[] handles;

        private Reader(String[] names, VarHandle[] handles) {
            this.names = names;
            this.handles = handles;
        }

        static Reader build(Class<?> type) {
            List<Field> fields = DataFields.of(type);
            String[] names = new String[fields.size()];
            VarHandle[] handles = new VarHandle[fields.size()];
            try {
                MethodHandles.Lookup lookup = MethodHandles.privateLookupIn(type, MethodHandles.lookup());
                for (int i = 0; i < names.length; i++) {
                    names[i] = fields.get(i).getName();
                    handles[i] = lookup.unreflectVarHandle(fields.get(i));
                }
            } catch (IllegalAccessException e) {
                return new Reader(new String[0], new VarHandle[0]);
            }
            return new Reader(names, handles);
        }

        Map<String, Object> read(Object data) {
            Map<String, Object> map = new LinkedHashMap<>(names.length * 2);
            for (int i = 0; i < names.length; i++) {
                map.put(names[i], toValue(handles[i].get(data)));
            }
            return map;
        }
    }

}
