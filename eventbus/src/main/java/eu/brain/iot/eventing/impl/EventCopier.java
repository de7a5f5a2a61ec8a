package eu.brain.iot.eventing.impl;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.invoke.VarHandle;
import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * Deep copies of event objects, cheap enough for the delivery hot path.
 * <p>
 * A copy plan is built once per class (reflection happens only then) and cached in a {@link ClassValue}, which
 * lives and dies with the class, so uninstalled bundles are not pinned. A {@link BrainIoTEvent} is copied with
 * {@link Object#clone()} (one intrinsic shallow copy), then only the fields that can hold mutable values (arrays,
 * collections, maps, nested data objects) are replaced by copies. Immutable values (primitives, strings, boxed
 * numbers, enums, {@code java.time} values, UUIDs) are shared, which is safe. Other data objects (public fields,
 * public no-argument constructor) are copied field by field through var handles. Objects of any other kind are
 * shared as they are: events are expected to be data.
 */
final class EventCopier {

    private static final MethodHandle CLONE;

    static {
        try {
            // Object.clone is protected: a lookup in BrainIoTEvent (our own class, same module) may call it on events.
            MethodHandles.Lookup lookup = MethodHandles.privateLookupIn(BrainIoTEvent.class, MethodHandles.lookup());
            CLONE = lookup.findVirtual(BrainIoTEvent.class, "clone", MethodType.methodType(Object.class))
                    .asType(MethodType.methodType(Object.class, BrainIoTEvent.class));
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    private static final ClassValue<Plan> PLANS = new ClassValue<>() {
        @Override
        protected Plan computeValue(Class<?> type) {
            return Plan.build(type);
        }
    };

    private EventCopier() {
    }

    /** @return a deep copy of the event, of the same class */
    static <E extends BrainIoTEvent> E copyEvent(E event) {
        @SuppressWarnings("unchecked")
        E copy = (E) PLANS.get(event.getClass()).copy(event);
        return copy;
    }

    /** @return a deep copy of any value an event may hold (shared when immutable) */
    static Object copyValue(Object value) {
        if (value == null || isImmutable(value.getClass())) {
            return value;
        }
        Class<?> type = value.getClass();
        if (type.isArray()) {
            return copyArray(value);
        }
        if (value instanceof List<?> list) {
            List<Object> copy = new ArrayList<>(list.size());
            for (Object o : list) {
                copy.add(copyValue(o));
            }
            return copy;
        }
        if (value instanceof Set<?> set) {
            Set<Object> copy = new LinkedHashSet<>();
            for (Object o : set) {
                copy.add(copyValue(o));
            }
            return copy;
        }
        if (value instanceof Collection<?> coll) {
            List<Object> copy = new ArrayList<>(coll.size());
            for (Object o : coll) {
                copy.add(copyValue(o));
            }
            return copy;
        }
        if (value instanceof Map<?, ?> map) {
            Map<Object, Object> copy = new LinkedHashMap<>();
            map.forEach((k, v) -> copy.put(k, copyValue(v)));
            return copy;
        }
        Plan plan = PLANS.get(type);
        return plan.copyable ? plan.copy(value) : value;
    }

    static boolean isImmutable(Class<?> type) {
        return type.isPrimitive() || type == String.class || type.isEnum()
                || Number.class.isAssignableFrom(type) && (type.getName().startsWith("java.lang.")
                        || type == BigDecimal.class || type == BigInteger.class)
                || type == Boolean.class || type == Character.class || type == UUID.class || type == Class.class
                || type.getName().startsWith("java.time.") && !type.isInterface();
    }

    private static Object copyArray(Object array) {
        int length = Array.getLength(array);
        Class<?> component = array.getClass().getComponentType();
        if (component.isPrimitive()) {
            if (array instanceof byte[] a) {
                return a.clone();
            } else if (array instanceof int[] a) {
                return a.clone();
            } else if (array instanceof long[] a) {
                return a.clone();
            } else if (array instanceof double[] a) {
                return a.clone();
            } else if (array instanceof float[] a) {
                return a.clone();
            } else if (array instanceof short[] a) {
                return a.clone();
            } else if (array instanceof char[] a) {
                return a.clone();
            }
            return ((boolean[]) array).clone();
        }
        Object copy = Array.newInstance(component, length);
        for (int i = 0; i < length; i++) {
            Array.set(copy, i, copyValue(Array.get(array, i)));
        }
        return copy;
    }

    /** How to copy one class: fixed once, used for every event of the class. */
    private static final class Plan {
        /** Whether this class is a data object we know how to copy. */
        final boolean copyable;
        final boolean cloneable;
        final MethodHandle constructor;
        /** Fields copied by the field-by-field path (all fields), or re-copied after clone (mutable ones). */
        final VarHandle[] fields;

        private Plan(boolean copyable, boolean cloneable, MethodHandle constructor, VarHandle[] fields) {
            this.copyable = copyable;
            this.cloneable = cloneable;
            this.constructor = constructor;
            this.fields = fields;
        }

        static Plan build(Class<?> type) {
            boolean cloneable = BrainIoTEvent.class.isAssignableFrom(type);
            try {
                MethodHandles.Lookup lookup = MethodHandles.privateLookupIn(type, MethodHandles.lookup());
                MethodHandle ctor = null;
                if (!cloneable) {
                    if (Modifier.isAbstract(type.getModifiers()) || !Modifier.isPublic(type.getModifiers())) {
                        return new Plan(false, false, null, new VarHandle[0]);
                    }
                    ctor = lookup.findConstructor(type, MethodType.methodType(void.class));
                }
                List<VarHandle> handles = new ArrayList<>();
                for (Field f : DataFields.of(type)) {
                    if (!cloneable || !isImmutable(f.getType())) {
                        handles.add(lookup.unreflectVarHandle(f));
                    }
                }
                return new Plan(true, cloneable, ctor, handles.toArray(VarHandle[]::new));
            } catch (NoSuchMethodException | IllegalAccessException notData) {
                // not a data object we can build or read: its instances are shared as they are
                return new Plan(false, false, null, new VarHandle[0]);
            }
        }

        Object copy(Object source) {
            try {
                Object copy = cloneable ? (Object) CLONE.invokeExact((BrainIoTEvent) source) : constructor.invoke();
                for (VarHandle field : fields) {
                    field.set(copy, cloneable ? copyValue(field.get(copy)) : copyValue(field.get(source)));
                }
                return copy;
            } catch (RuntimeException | Error e) {
                throw e;
            } catch (Throwable e) {
                throw new IllegalStateException("Cannot copy " + source.getClass().getName() + ": " + e, e);
            }
        }
    }
}
