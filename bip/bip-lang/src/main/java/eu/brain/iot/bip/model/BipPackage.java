package eu.brain.iot.bip.model;

import java.util.List;
import java.util.stream.Stream;

/** One {@code .bip} file: {@code package name use ... declarations end}. */
public record BipPackage(Pos pos, List<Annotation> annotations, String name, List<Use> uses, List<Decl> decls) {

    public BipPackage {
        annotations = List.copyOf(annotations);
        uses = List.copyOf(uses);
        decls = List.copyOf(decls);
    }

    /** {@code use other.pkg} */
    public record Use(Pos pos, String packageName) {
    }

    public <T extends Decl> Stream<T> decls(Class<T> kind) {
        return decls.stream().filter(kind::isInstance).map(kind::cast);
    }

    public List<AtomType> atomTypes() {
        return decls(AtomType.class).toList();
    }

    public List<ConnectorType> connectorTypes() {
        return decls(ConnectorType.class).toList();
    }

    public List<CompoundType> compoundTypes() {
        return decls(CompoundType.class).toList();
    }

    public List<PortType> portTypes() {
        return decls(PortType.class).toList();
    }

    public List<ExternFunction> externFunctions() {
        return decls(ExternFunction.class).toList();
    }

    public List<ConstDecl> constants() {
        return decls(ConstDecl.class).toList();
    }
}
