package eu.brain.iot.bip.generate;

import java.util.List;
import java.util.Locale;
import java.util.Set;

import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.model.Annotation;
import eu.brain.iot.bip.model.BipPackage;

/** How BIP names become Java names. */
public final class JavaNames {

    static final Set<String> KEYWORDS = Set.of("abstract", "assert", "boolean", "break", "byte", "case", "catch",
            "char", "class", "const", "continue", "default", "do", "double", "else", "enum", "extends", "final",
            "finally", "float", "for", "goto", "if", "implements", "import", "instanceof", "int", "interface", "long",
            "native", "new", "package", "private", "protected", "public", "return", "short", "static", "strictfp",
            "super", "switch", "synchronized", "this", "throw", "throws", "transient", "try", "void", "volatile",
            "while", "true", "false", "null", "var", "record", "yield", "sealed", "permits", "_");

    /** Endings of an atom type's name that already say behaviour (see {@link #behaviourClass}). */
    private static final List<String> BEHAVIOUR_SUFFIXES = List.of("Behavior", "Behaviour");

    private JavaNames() {
    }

    /** A BIP name usable as a Java identifier: unchanged unless it is a Java keyword (then suffixed with _). */
    public static String id(String bipName) {
        return KEYWORDS.contains(bipName) ? bipName + "_" : bipName;
    }

    /** {@code Robot_behavior} becomes {@code RobotBehavior}, {@code connector_type_door} {@code ConnectorTypeDoor}. */
    public static String type(String bipName) {
        String simple = bipName.substring(bipName.lastIndexOf('.') + 1);
        StringBuilder out = new StringBuilder();
        boolean upper = true;
        for (char c : simple.toCharArray()) {
            if (c == '_') {
                upper = true;
            } else {
                out.append(upper ? Character.toUpperCase(c) : c);
                upper = false;
            }
        }
        String s = out.length() == 0 ? "X" : out.toString();
        return Character.isJavaIdentifierStart(s.charAt(0)) ? s : "X" + s;
    }

    /**
     * The smart behaviour class of an atom type, from its Java type name: {@code Sensor} gives {@code SensorBehaviour};
     * a name that already says behaviour does not say it twice: {@code RobotBehavior} (the paper's
     * {@code Robot_behavior}) gives {@code RobotSmartBehaviour}, not {@code RobotSmartBehaviour}, and stays apart
     * from the atom's own class {@code RobotBehavior}.
     */
    public static String behaviourClass(String atomJavaType) {
        for (String suffix : BEHAVIOUR_SUFFIXES) {
            if (atomJavaType.endsWith(suffix) && atomJavaType.length() > suffix.length()) {
                return atomJavaType.substring(0, atomJavaType.length() - suffix.length()) + "SmartBehaviour";
            }
        }
        return atomJavaType + "Behaviour";
    }

    /** {@code unloadLocation} becomes {@code UnloadLocation} (for method names like onUnloadLocation). */
    public static String capital(String bipName) {
        String t = type(bipName);
        return t;
    }

    /** {@code p1} and {@code position} become {@code p1Position}. */
    public static String field(String prefix, String name) {
        return prefix + Character.toUpperCase(name.charAt(0)) + name.substring(1);
    }

    /** The Java package of a BIP package: {@code @java(package="...")}, else its name in lower case. */
    public static String javaPackage(BipPackage pkg) {
        return Annotation.find(pkg.annotations(), "java", "package")
                .orElse(pkg.name().toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9_.]", "_"));
    }

    /** The Java type of a data type. */
    public static String javaType(Type t, PackageScope scope) {
        return switch (t.kind()) {
            case INT -> "int";
            case FLOAT -> "double";
            case BOOL -> "boolean";
            case STRING -> "String";
            case VOID -> "void";
            case EXTERN -> scope.externType(t.externName()).map(x -> x.backendName())
                    .filter(b -> b != null && b.matches("[A-Za-z_][\\w.]*(<[\\w.<>, ?]*>)?")).orElse("Object");
            case ERROR -> "Object";
        };
    }

    /** @return the Java literal of the value a datum of this type starts with (as the interpreter's Ops) */
    public static String defaultLiteral(Type t) {
        return t == null ? "null" : switch (t.kind()) {
            case INT -> "0";
            case FLOAT -> "0.0";
            case BOOL -> "false";
            case STRING -> "\"\"";
            default -> "null";
        };
    }

    /** The Java type for use as a generic argument or in a list. */
    public static String boxed(String javaType) {
        return switch (javaType) {
            case "int" -> "Integer";
            case "double" -> "Double";
            case "boolean" -> "Boolean";
            default -> javaType;
        };
    }

    /** @return the file name of a position, without its directories (for generated comments) */
    public static String fileName(eu.brain.iot.bip.model.Pos pos) {
        String f = pos.file().replace('\\', '/');
        return f.substring(f.lastIndexOf('/') + 1);
    }

    /** A Java string literal (non-ASCII characters as unicode escapes). */
    public static String literal(String s) {
        return eu.brain.iot.bip.print.Printer.quote(s, true);
    }

    /** @return a Java literal for a folded constant value (an int, double, boolean or string) */
    public static String value(Object v) {
        if (v instanceof String str) {
            return literal(str);
        }
        if (v instanceof Double d) {
            if (d.isNaN()) {
                return "Double.NaN";
            }
            if (d.isInfinite()) {
                return d > 0 ? "Double.POSITIVE_INFINITY" : "Double.NEGATIVE_INFINITY";
            }
            return d.toString();
        }
        if (v instanceof Integer i && i == Integer.MIN_VALUE) {
            return "Integer.MIN_VALUE";
        }
        if (v == null) {
            throw new IllegalStateException("a constant that does not fold reached the generator (the checker refuses it)");
        }
        return v.toString();
    }
}
