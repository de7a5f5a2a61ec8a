package eu.brain.iot.bip.model;

import java.util.List;
import java.util.Optional;

/** {@code compound type Name(params) component... connector... priority... export... end}. */
public record CompoundType(Pos pos, List<Annotation> annotations, String name, List<Param> params,
        List<Component> components, List<Connector> connectors, List<Priority> priorities, List<PortExport> portExports,
        List<DataExport> dataExports) implements Decl {

    public CompoundType {
        annotations = List.copyOf(annotations);
        params = List.copyOf(params);
        components = List.copyOf(components);
        connectors = List.copyOf(connectors);
        priorities = List.copyOf(priorities);
        portExports = List.copyOf(portExports);
        dataExports = List.copyOf(dataExports);
    }

    @Override
    public String kind() {
        return "compound type";
    }

    public Optional<Component> component(String componentName) {
        return components.stream().filter(c -> c.name().equals(componentName)).findFirst();
    }

    public Optional<Connector> connector(String connectorName) {
        return connectors.stream().filter(c -> c.name().equals(connectorName)).findFirst();
    }

    /** {@code component Robot_behavior Robot1(1)} (one record per instance). */
    public record Component(Pos pos, List<Annotation> annotations, String type, String name, List<Expr> args) {
        public Component {
            annotations = List.copyOf(annotations);
            args = List.copyOf(args);
        }
    }

    /** {@code connector connector_type_door Connector1(DoorInstance.openDoor, Robot1.openDoor, ...)}. */
    public record Connector(Pos pos, List<Annotation> annotations, String type, String name, List<PortRef> ports) {
        public Connector {
            annotations = List.copyOf(annotations);
            ports = List.copyOf(ports);
        }
    }

    /** {@code component.port} (or {@code connector.port} for a connector's exported port, or data). */
    public record PortRef(Pos pos, String component, String port) {
        @Override
        public String toString() {
            return component + "." + port;
        }
    }

    /**
     * {@code priority name C:A.p,B.q < D:* provided (guard)}; guard may be null.
     */
    public record Priority(Pos pos, String name, InteractionSpec low, InteractionSpec high, Expr guard) {
    }

    /**
     * One side of a compound priority: {@code connector} is {@code "*"} for all connectors; {@code ports} null
     * stands for {@code *} (every interaction of the connector).
     */
    public record InteractionSpec(Pos pos, String connector, List<PortRef> ports) {
        public InteractionSpec {
            ports = ports == null ? null : List.copyOf(ports);
        }
    }

    /** {@code export port A.p, B.q as name}. */
    public record PortExport(Pos pos, List<PortRef> ports, String name) {
        public PortExport {
            ports = List.copyOf(ports);
        }
    }

    /** {@code export data A.x as name}. */
    public record DataExport(Pos pos, PortRef data, String name) {
    }
}
