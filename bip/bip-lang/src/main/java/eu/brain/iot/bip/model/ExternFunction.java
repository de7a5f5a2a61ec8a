package eu.brain.iot.bip.model;

import java.util.List;

/**
 * {@code extern function int getDockingX()}, also written {@code extern int getPosition ()} (the paper's form) and
 * with named parameters {@code extern function int sendGoto(double x, double y)}. {@code returnType} is null for
 * functions without a result.
 */
public record ExternFunction(Pos pos, List<Annotation> annotations, TypeRef returnType, String name,
        List<Param> params) implements Decl {

    public ExternFunction {
        annotations = List.copyOf(annotations);
        params = List.copyOf(params);
    }

    @Override
    public String kind() {
        return "extern function";
    }
}
