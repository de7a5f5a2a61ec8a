package eu.brain.iot.bip.model;

import java.util.List;

/**
 * {@code connector type Name(PortType p1, ...) data... export port... define expr on... end}. Without a
 * {@code define} (a shape the paper's Listing 6 uses), the defined interactions are those named by the {@code on}
 * clauses.
 */
public record ConnectorType(Pos pos, List<Annotation> annotations, String name, List<Param> ports,
        List<DataDecl> data, PortDecl exportPort, PortExpr.Group define, List<Interaction> interactions)
        implements Decl {

    public ConnectorType {
        annotations = List.copyOf(annotations);
        ports = List.copyOf(ports);
        data = List.copyOf(data);
        interactions = List.copyOf(interactions);
    }

    @Override
    public String kind() {
        return "connector type";
    }

    /**
     * {@code on p1 p2 provided (g) up { ... } down { ... }}: guard and transfer functions of one interaction.
     * {@code guard}, {@code up} and {@code down} may each be null.
     */
    public record Interaction(Pos pos, List<String> ports, Expr guard, Block up, Block down) {
        public Interaction {
            ports = List.copyOf(ports);
        }
    }
}
