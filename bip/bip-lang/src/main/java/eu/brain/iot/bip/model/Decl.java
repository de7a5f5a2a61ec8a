package eu.brain.iot.bip.model;

import java.util.List;

/** A declaration directly inside a package. */
public sealed interface Decl permits ConstDecl, ExternType, ExternFunction, ExternOperator, PortType, AtomType,
        ConnectorType, CompoundType {

    Pos pos();

    String name();

    List<Annotation> annotations();

    /** @return the keyword phrase that introduces it, for messages ("atom type") */
    String kind();
}
