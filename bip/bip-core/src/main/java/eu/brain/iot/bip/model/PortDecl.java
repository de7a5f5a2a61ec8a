package eu.brain.iot.bip.model;

import java.util.List;

/**
 * {@code [export] port PortType name(data, ...)} in an atom, or the exported port of a connector type (there the
 * arguments name connector data). {@code mergedAs} is the name of a merged export ({@code ... as exp}), else null.
 */
public record PortDecl(Pos pos, List<Annotation> annotations, boolean exported, String portType, String name,
        List<String> boundData, String mergedAs) {

    public PortDecl {
        annotations = List.copyOf(annotations);
        boundData = List.copyOf(boundData);
    }
}
