package eu.brain.iot.bip.model;

import java.util.List;
import java.util.Optional;

/**
 * {@code @name(key=value, key2="text", flag)}: information for tools other than the checker, such as the BRAIN-IoT
 * dialect's {@code @java(import="Printer", src="org.printer")} or our {@code @java(package="a.b")}.
 */
public record Annotation(Pos pos, String name, List<Param> params) {

    public Annotation {
        params = List.copyOf(params);
    }

    /** One parameter; {@code value} is null for a bare key, {@code quoted} tells whether it was a string. */
    public record Param(String key, String value, boolean quoted) {
    }

    /** @return the value of the first parameter named {@code key} */
    public Optional<String> value(String key) {
        return params.stream().filter(p -> p.key().equals(key) && p.value() != null).map(Param::value).findFirst();
    }

    /** @return the value of {@code key} in the first annotation named {@code name} */
    public static Optional<String> find(List<Annotation> annotations, String name, String key) {
        return annotations.stream().filter(a -> a.name().equals(name)).map(a -> a.value(key))
                .flatMap(Optional::stream).findFirst();
    }
}
