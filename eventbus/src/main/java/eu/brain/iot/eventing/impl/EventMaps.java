package eu.brain.iot.eventing.impl;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.invoke.VarHandle;
import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.lang.reflect.GenericArrayType;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.lang.reflect.TypeVariable;
import java.lang.reflect.WildcardType;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.LocalTime;
import java.time.OffsetDateTime;
import java.time.ZonedDateTime;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

import org.osgi.util.converter.Converter;
import org.osgi.util.converter.Converters;

/**
 * Conversions between events and maps of their fields, and between two classes of the same event loaded by
 * different bundles. Events become maps for untyped behaviours and for filter matching; a map becomes an event
 * for a typed behaviour that consumes an event published untyped, or published with another bundle's copy of
 * the class.
 * <p>
 * Reading an object's fields uses var handles fixed once per class. Building a typed object from a map follows the
 * OSGi Converter's DTO rules (public fields, public no-argument constructor) with a plan fixed once per class
 * ({@link Writer}): a value that already has its field's type and is immutable is set as it is, a map for a nested
 * data object is built the same way, and only the other values go through the Converter, one field at a time. The
 * Converter on a whole object looks up the class's methods by reflection for every field of every event, which made
 * it the largest cost of taking an event from another node. Text for a {@code java.time} field is parsed by the
 * type's own {@code parse}, the method the Converter finds by reflection for each value.
 */
final class EventMaps {

    private static final Converter CONVERTER = Converters.standardConverter();

    /** The {@code java.time} types events carry, each with its {@code parse}: their text on the wire is ISO-8601. */
    private static final Map<Class<?>, Function<CharSequence, Object>> TEXT_PARSERS = Map.of(
            Instant.class, Instant::parse, LocalDate.class, LocalDate::parse, LocalTime.class, LocalTime::parse,
            LocalDateTime.class, LocalDateTime::parse, OffsetDateTime.class, OffsetDateTime::parse,
            ZonedDateTime.class, ZonedDateTime::parse, Duration.class, Duration::parse);

    private static final ClassValue<Reader> READERS = new ClassValue<>() {
        @Override
        protected Reader computeValue(Class<?> type) {
            return Reader.build(type);
        }
    };

    private static final ClassValue<Writer> WRITERS = new ClassValue<>() {
        @Override
        protected Writer computeValue(Class<?> type) {
            return Writer.build(type);
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
        Writer writer = WRITERS.get(target);
        if (writer.constructor == null) {
            return CONVERTER.convert(fields).targetAsDTO().to(target);
        }
        return target.cast(writer.write(fields));
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

    /**
     * Builds one data class from a map of field values; {@link #constructor} is null for a class outside the DTO
     * rules (no public no-argument constructor, abstract, or a key prefix), which the Converter builds as a whole.
     */
    static final class Writer {
        final MethodHandle constructor;
        final String[] names;
        final VarHandle[] handles;
        final Class<?>[] types;
        final Type[] genericTypes;

        private Writer(MethodHandle constructor, List<Field> fields, VarHandle[] handles) {
            this.constructor = constructor;
            this.names = fields.stream().map(Field::getName).toArray(String[]::new);
            this.handles = handles;
            this.types = fields.stream().map(f -> boxed(f.getType())).toArray(Class<?>[]::new);
            this.genericTypes = fields.stream().map(Field::getGenericType).toArray(Type[]::new);
        }

        static Writer build(Class<?> type) {
            Writer none = new Writer(null, List.of(), new VarHandle[0]);
            int m = type.getModifiers();
            if (!Modifier.isPublic(m) || Modifier.isAbstract(m) || type.isInterface() || type.isArray()
                    || type.isPrimitive() || EventCopier.isImmutable(type) || Map.class.isAssignableFrom(type)
                    || Collection.class.isAssignableFrom(type) || hasKeyPrefix(type)) {
                return none;
            }
            List<Field> fields = DataFields.of(type);
            if (fields.stream().anyMatch(f -> hasTypeVariable(f.getGenericType()))) {
                return none; // a field of a type parameter: the Converter resolves it against the class
            }
            try {
                MethodHandles.Lookup lookup = MethodHandles.privateLookupIn(type, MethodHandles.lookup());
                MethodHandle constructor = lookup.findConstructor(type, MethodType.methodType(void.class));
                if (!Modifier.isPublic(type.getConstructor().getModifiers())) {
                    return none;
                }
                VarHandle[] handles = new VarHandle[fields.size()];
                for (int i = 0; i < handles.length; i++) {
                    handles[i] = lookup.unreflectVarHandle(fields.get(i));
                }
                return new Writer(constructor, fields, handles);
            } catch (ReflectiveOperationException | SecurityException e) {
                return none;
            }
        }

        private static boolean hasTypeVariable(Type type) {
            if (type instanceof TypeVariable<?>) {
                return true;
            }
            if (type instanceof ParameterizedType p) {
                return Arrays.stream(p.getActualTypeArguments()).anyMatch(Writer::hasTypeVariable);
            }
            if (type instanceof GenericArrayType a) {
                return hasTypeVariable(a.getGenericComponentType());
            }
            return type instanceof WildcardType;
        }

        /** The Converter's DTO rule for a class with a {@code PREFIX_} constant: its keys carry that prefix. */
        private static boolean hasKeyPrefix(Class<?> type) {
            try {
                type.getField("PREFIX_");
                return true;
            } catch (NoSuchFieldException e) {
                return false;
            }
        }

        Object write(Map<String, ?> fields) {
            Object target;
            try {
                target = constructor.invoke();
            } catch (RuntimeException | Error e) {
                throw e;
            } catch (Throwable e) {
                throw new IllegalStateException("cannot make a " + constructor.type().returnType().getName(), e);
            }
            for (int i = 0; i < names.length; i++) {
                Object value = fields.get(names[i]);
                if (value != null || fields.containsKey(names[i])) {
                    handles[i].set(target, value(value, i));
                }
            }
            return target;
        }

        private Object value(Object value, int i) {
            Class<?> type = types[i];
            if (value == null) {
                return genericTypes[i] instanceof Class<?> c && c.isPrimitive() ? CONVERTER.convert(null).to(c) : null;
            }
            if (type.isInstance(value) && EventCopier.isImmutable(value.getClass())) {
                return value;
            }
            Object widened = widened(value, type);
            if (widened != null) {
                return widened;
            }
            Function<CharSequence, Object> parse = TEXT_PARSERS.get(type);
            if (parse != null && value instanceof CharSequence text) {
                return parse.apply(text);
            }
            if (value instanceof Map<?, ?> map && genericTypes[i] instanceof Class<?> c) {
                Writer nested = WRITERS.get(c);
                if (nested.constructor != null) {
                    @SuppressWarnings("unchecked")
                    Map<String, ?> nestedFields = (Map<String, ?>) map;
                    return nested.write(nestedFields);
                }
            }
            Object converted = CONVERTER.convert(value).to(genericTypes[i]);
            // the Converter hands a value for an Object field over as it is: the map is shared with other consumers
            return converted == value ? toValue(value) : converted;
        }

        /**
         * A number for a field of a wider number type, as the Converter makes it ({@link Number}'s own conversions)
         * but without its reflection: JSON gives a small {@code long} as an {@link Integer}, a whole {@code double}
         * maybe too. Null for any other pair.
         */
        static Object widened(Object value, Class<?> type) {
            boolean integral = value instanceof Integer || value instanceof Long || value instanceof Short
                    || value instanceof Byte;
            if (!integral && !(value instanceof Float)) {
                return null;
            }
            Number n = (Number) value;
            if (type == Double.class) {
                return n.doubleValue();
            }
            if (!integral) {
                return null;
            }
            if (type == Long.class) {
                return n.longValue();
            }
            if (type == Float.class) {
                return n.floatValue();
            }
            if (type == Integer.class && (value instanceof Short || value instanceof Byte)) {
                return n.intValue();
            }
            return null;
        }

        private static Class<?> boxed(Class<?> type) {
            return type.isPrimitive() ? MethodType.methodType(type).wrap().returnType() : type;
        }
    }
}
