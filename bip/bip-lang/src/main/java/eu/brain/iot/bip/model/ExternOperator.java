package eu.brain.iot.bip.model;

import java.util.List;

/** {@code extern operator Complex *(Complex, Complex)}. */
public record ExternOperator(Pos pos, List<Annotation> annotations, TypeRef returnType, String operator,
        List<TypeRef> params) implements Decl {

    public ExternOperator {
        annotations = List.copyOf(annotations);
        params = List.copyOf(params);
    }

    @Override
    public String name() {
        return operator;
    }

    @Override
    public String kind() {
        return "extern operator";
    }
}
