package eu.brain.iot.bip.model;

import java.util.List;

/** {@code [export] data int x = 0} in an atom or connector type (one record per declared name). */
public record DataDecl(Pos pos, List<Annotation> annotations, boolean exported, TypeRef type, String name,
        Expr init) {

    public DataDecl {
        annotations = List.copyOf(annotations);
    }
}
