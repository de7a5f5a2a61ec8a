package eu.brain.iot.bip.model;

import java.util.List;

/** {@code extern data type IntList refine List as "java.util.List"}; {@code backendName} may be null. */
public record ExternType(Pos pos, List<Annotation> annotations, String name, List<String> refines, String backendName)
        implements Decl {

    public ExternType {
        annotations = List.copyOf(annotations);
        refines = List.copyOf(refines);
    }

    @Override
    public String kind() {
        return "extern data type";
    }
}
