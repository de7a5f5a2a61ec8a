package eu.brain.iot.eventing.impl;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;

/** The fields that make up a data object: public, not static, not final, declared in the class or a superclass. */
final class DataFields {

    private DataFields() {
    }

    static List<Field> of(Class<?> type) {
        List<Field> fields = new ArrayList<>();
        for (Field f : type.getFields()) {
            int m = f.getModifiers();
            if (!Modifier.isStatic(m) && !Modifier.isFinal(m)) {
                fields.add(f);
            }
        }
        return fields;
    }
}
