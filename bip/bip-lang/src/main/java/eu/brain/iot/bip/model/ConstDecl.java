package eu.brain.iot.bip.model;

import java.util.List;

/** {@code const data int inDocking = 1} (one record per declared name). */
public record ConstDecl(Pos pos, List<Annotation> annotations, TypeRef type, String name, Expr value) implements Decl {

    public ConstDecl {
        annotations = List.copyOf(annotations);
    }

    @Override
    public String kind() {
        return "constant";
    }
}
