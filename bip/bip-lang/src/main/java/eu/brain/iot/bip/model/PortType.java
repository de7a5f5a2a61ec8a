package eu.brain.iot.bip.model;

import java.util.List;

/** {@code port type Port_Orchestrator(float position1, float position2, float position3)}. */
public record PortType(Pos pos, List<Annotation> annotations, String name, List<Param> params) implements Decl {

    public PortType {
        annotations = List.copyOf(annotations);
        params = List.copyOf(params);
    }

    @Override
    public String kind() {
        return "port type";
    }
}
