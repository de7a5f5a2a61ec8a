package eu.brain.iot.bip.check;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Annotation;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortExpr;
import eu.brain.iot.bip.model.PortType;
import eu.brain.iot.bip.model.Pos;

/** Checks one connector type: its ports, its define expression, its interactions and their transfer functions. */
final class ConnectorChecker {

    private final PackageScope scope;
    private final ExprTyper typer;
    private final Diagnostics diagnostics;

    ConnectorChecker(PackageScope scope, ExprTyper typer, Diagnostics diagnostics) {
        this.scope = scope;
        this.typer = typer;
        this.diagnostics = diagnostics;
    }

    void check(ConnectorType c) {
        String owner = "connector type " + c.name();
        Map<String, Pos> names = new HashMap<>();
        for (Param p : c.ports()) {
            Checker.unique(diagnostics, names, p.name(), p.pos(), "port");
            if (scope.portType(p.type().name()).isEmpty()) {
                diagnostics.error(p.pos(), "unknown port type '" + p.type().name() + "' of port " + p.name() + " of "
                        + owner);
            }
        }
        if (c.ports().isEmpty()) {
            diagnostics.error(c.pos(), owner + " connects no port");
        }
        if (c.ports().size() > Interactions.MAX_PORTS) {
            diagnostics.warning(c.pos(), owner + " has " + c.ports().size() + " ports; interactions of more than "
                    + Interactions.MAX_PORTS + " ports are not enumerated, so it is not checked further");
            return;
        }
        for (DataDecl d : c.data()) {
            Checker.unique(diagnostics, names, d.name(), d.pos(), "name");
            Checker.type(scope, d.type(), "data " + d.name() + " of " + owner);
        }
        if (c.exportPort() != null) {
            exportPort(c);
        }
        if (c.define() != null) {
            Set<String> used = new HashSet<>();
            define(c, c.define(), used);
            for (Param p : c.ports()) {
                if (!used.contains(p.name())) {
                    diagnostics.warning(c.define().pos(), "port " + p.name() + " of " + owner
                            + " is not in its define expression, so it takes part in no interaction");
                }
            }
        } else if (c.interactions().isEmpty()) {
            diagnostics.error(c.pos(), owner + " defines no interaction: add 'define <ports>' (e.g. define p1 p2)");
        }
        List<Long> defined = Interactions.of(c);
        LocalNames local = LocalNames.connector(scope, c);
        Set<Long> seen = new HashSet<>();
        for (ConnectorType.Interaction i : c.interactions()) {
            Set<String> ports = new HashSet<>();
            for (String p : i.ports()) {
                if (Interactions.index(c, p) < 0) {
                    diagnostics.error(i.pos(), "'on' names unknown port '" + p + "' of " + owner + "; its ports are "
                            + c.ports().stream().map(Param::name).toList());
                } else if (!ports.add(p)) {
                    diagnostics.error(i.pos(), "'on' names port " + p + " twice");
                }
            }
            long mask = Interactions.mask(c, i.ports());
            if (c.define() != null && ports.size() == i.ports().size() && !defined.contains(mask)) {
                diagnostics.error(i.pos(), "'on " + String.join(" ", i.ports()) + "' is not an interaction of "
                        + owner + "; its define allows " + defined.stream().map(m -> Interactions.names(c, m)).toList());
            }
            if (!seen.add(mask)) {
                diagnostics.warning(i.pos(), "interaction " + i.ports() + " of " + owner
                        + " has two 'on' clauses; only the first is used");
            }
            if (i.guard() != null) {
                typer.expectBool(i.guard(), local, "the guard of interaction " + i.ports());
            }
            if (i.up() != null) {
                typer.statements(i.up().stmts(), local);
            }
            if (i.down() != null) {
                typer.statements(i.down().stmts(), local);
            }
        }
        Optional<String> coordinator = Annotation.find(c.annotations(), "bus", "coordinator");
        if (coordinator.isPresent() && Interactions.index(c, coordinator.get()) < 0) {
            diagnostics.error(c.pos(), "@bus(coordinator=" + coordinator.get() + ") names no port of " + owner);
        }
    }

    private void define(ConnectorType c, PortExpr e, Set<String> used) {
        if (e instanceof PortExpr.Ref r) {
            if (Interactions.index(c, r.port()) < 0) {
                diagnostics.error(r.pos(), "define names unknown port '" + r.port() + "' of connector type " + c.name()
                        + "; its ports are " + c.ports().stream().map(Param::name).toList());
            } else if (!used.add(r.port())) {
                diagnostics.error(r.pos(), "define names port " + r.port() + " twice");
            }
            return;
        }
        for (PortExpr item : ((PortExpr.Group) e).items()) {
            define(c, item, used);
        }
    }

    private void exportPort(ConnectorType c) {
        var export = c.exportPort();
        Optional<PortType> type = scope.portType(export.portType());
        if (type.isEmpty()) {
            diagnostics.error(export.pos(), "unknown port type '" + export.portType() + "' of exported port "
                    + export.name());
            return;
        }
        if (type.get().params().size() != export.boundData().size()) {
            diagnostics.error(export.pos(), "exported port " + export.name() + " binds " + export.boundData().size()
                    + " data, but port type " + export.portType() + " has " + type.get().params().size());
            return;
        }
        for (int i = 0; i < export.boundData().size(); i++) {
            String name = export.boundData().get(i);
            Optional<DataDecl> d = c.data().stream().filter(x -> x.name().equals(name)).findFirst();
            if (d.isEmpty()) {
                diagnostics.error(export.pos(), "exported port " + export.name() + " binds unknown data '" + name
                        + "' (declare it with 'data <type> " + name + "' in the connector)");
            } else {
                Type expected = scope.resolveType(type.get().params().get(i).type().name());
                Type actual = scope.resolveType(d.get().type().name());
                if (expected != null && actual != null && !expected.equals(actual)) {
                    diagnostics.error(export.pos(), "exported port " + export.name() + " binds " + name + " of type "
                            + actual + " to a parameter of type " + expected);
                }
            }
        }
    }
}
