package eu.brain.iot.bip.check;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.CompoundType;
import eu.brain.iot.bip.model.CompoundType.PortRef;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.model.PortType;
import eu.brain.iot.bip.model.Pos;

/**
 * Checks one compound type: component types and arguments, connector port references and their port types,
 * priorities and exports.
 */
final class CompoundChecker {

    private final PackageScope scope;
    private final ExprTyper typer;
    private final Diagnostics diagnostics;

    CompoundChecker(PackageScope scope, ExprTyper typer, Diagnostics diagnostics) {
        this.scope = scope;
        this.typer = typer;
        this.diagnostics = diagnostics;
    }

    void check(CompoundType c) {
        String owner = "compound type " + c.name();
        Checker.params(scope, c.params(), owner);
        Map<String, Pos> names = new HashMap<>();
        LocalNames local = LocalNames.compound(scope, c);
        for (CompoundType.Component k : c.components()) {
            Checker.unique(diagnostics, names, k.name(), k.pos(), "component or connector");
            List<Param> params = componentParams(k);
            if (params == null) {
                continue;
            }
            if (params.size() != k.args().size()) {
                diagnostics.error(k.pos(), "component " + k.name() + " gives " + k.args().size() + " arguments, but "
                        + k.type() + " takes " + params.size() + " " + params.stream().map(Param::name).toList());
                continue;
            }
            for (int i = 0; i < params.size(); i++) {
                Type expected = scope.resolveType(params.get(i).type().name());
                Type actual = typer.type(k.args().get(i), local);
                if (expected != null && !scope.assignable(expected, actual)) {
                    diagnostics.error(k.args().get(i).pos(), "argument " + (i + 1) + " of component " + k.name()
                            + " is of type " + actual + ", but parameter " + params.get(i).name() + " is " + expected);
                }
            }
        }
        if (c.components().isEmpty()) {
            diagnostics.warning(c.pos(), owner + " has no component");
        }
        for (CompoundType.Connector k : c.connectors()) {
            Checker.unique(diagnostics, names, k.name(), k.pos(), "component or connector");
            connector(c, k);
        }
        for (CompoundType.Priority p : c.priorities()) {
            for (CompoundType.InteractionSpec s : List.of(p.low(), p.high())) {
                if (!s.connector().equals("*") && c.connector(s.connector()).isEmpty()) {
                    diagnostics.error(s.pos(), "priority " + p.name() + " names unknown connector '" + s.connector()
                            + "'");
                } else if (s.ports() != null && !s.connector().equals("*")) {
                    CompoundType.Connector k = c.connector(s.connector()).get();
                    for (PortRef r : s.ports()) {
                        if (!k.ports().contains(r)) {
                            diagnostics.error(r.pos(), "priority " + p.name() + ": " + r + " is not a port of connector "
                                    + k.name() + " " + k.ports());
                        }
                    }
                }
            }
            if (p.guard() != null) {
                typer.expectBool(p.guard(), local, "the guard of priority " + p.name());
            }
        }
        Map<String, Pos> exports = new HashMap<>();
        for (CompoundType.PortExport e : c.portExports()) {
            Checker.unique(diagnostics, exports, e.name(), e.pos(), "exported port");
            PortType first = null;
            for (PortRef r : e.ports()) {
                PortType t = portTypeOf(c, r);
                if (first == null) {
                    first = t;
                } else if (t != null && t != first) {
                    diagnostics.error(r.pos(), "ports merged into " + e.name() + " must have one port type: " + r
                            + " is " + t.name() + ", not " + first.name());
                }
            }
        }
        for (CompoundType.DataExport e : c.dataExports()) {
            if (local.lookup(e.data().component(), e.data().port()) == null) {
                diagnostics.error(e.pos(), "export data " + e.data() + ": no exported data " + e.data().port()
                        + " in component " + e.data().component());
            }
        }
    }

    private List<Param> componentParams(CompoundType.Component k) {
        Optional<AtomType> atom = scope.atomType(k.type());
        if (atom.isPresent()) {
            return atom.get().params();
        }
        Optional<CompoundType> compound = scope.compoundType(k.type());
        if (compound.isPresent()) {
            return compound.get().params();
        }
        diagnostics.error(k.pos(), "unknown component type '" + k.type() + "' of component " + k.name()
                + ": expected an atom type or a compound type");
        return null;
    }

    private void connector(CompoundType c, CompoundType.Connector k) {
        Optional<ConnectorType> type = scope.connectorType(k.type());
        if (type.isEmpty()) {
            diagnostics.error(k.pos(), "unknown connector type '" + k.type() + "' of connector " + k.name());
            k.ports().forEach(r -> portTypeOf(c, r));
            return;
        }
        List<Param> params = type.get().ports();
        if (params.size() != k.ports().size()) {
            diagnostics.error(k.pos(), "connector " + k.name() + " binds " + k.ports().size() + " ports, but "
                    + k.type() + " has " + params.size() + " " + params.stream().map(Param::name).toList());
        }
        PackageScope typeScope = new PackageScope(scope.workspace(), scope.owner(type.get()));
        for (int i = 0; i < k.ports().size(); i++) {
            PortRef r = k.ports().get(i);
            PortType actual = portTypeOf(c, r);
            c.component(r.component()).flatMap(x -> scope.atomType(x.type())).flatMap(a -> a.port(r.port()))
                    .filter(PortDecl::isExtern).ifPresent(p -> diagnostics.error(r.pos(), "connector " + k.name()
                            + " binds extern port " + r + ", which only events of the environment fire: bind an "
                            + "ordinary port"));
            if (i < params.size() && actual != null) {
                PortType expected = typeScope.portType(params.get(i).type().name()).orElse(null);
                if (expected != null && expected != actual) {
                    diagnostics.error(r.pos(), "connector " + k.name() + ": " + r + " is a port of type "
                            + actual.name() + ", but parameter " + params.get(i).name() + " of " + k.type()
                            + " needs " + expected.name());
                }
            }
        }
    }

    /** Resolves {@code component.port} (or {@code connector.port}) and reports what is wrong; null if unknown. */
    private PortType portTypeOf(CompoundType c, PortRef r) {
        Optional<CompoundType.Component> component = c.component(r.component());
        if (component.isPresent()) {
            Optional<AtomType> atom = scope.atomType(component.get().type());
            if (atom.isPresent()) {
                PackageScope atomScope = new PackageScope(scope.workspace(), scope.owner(atom.get()));
                Optional<PortDecl> port = atom.get().port(r.port());
                if (port.isEmpty()) {
                    port = atom.get().ports().stream().filter(p -> r.port().equals(p.mergedAs())).findFirst();
                }
                if (port.isEmpty()) {
                    diagnostics.error(r.pos(), "component " + r.component() + " (atom type " + atom.get().name()
                            + ") has no port '" + r.port() + "'; its exported ports are " + atom.get().ports().stream()
                                    .filter(PortDecl::exported).map(PortDecl::name).toList());
                    return null;
                }
                if (!port.get().exported() && !port.get().isExtern()) { // a bound extern port: its own error
                    diagnostics.error(r.pos(), "port " + r + " is not exported: write 'export port "
                            + port.get().portType() + " " + r.port() + "(...)' in atom type " + atom.get().name());
                }
                return atomScope.portType(port.get().portType()).orElse(null);
            }
            Optional<CompoundType> inner = scope.compoundType(component.get().type());
            if (inner.isPresent()) {
                Optional<CompoundType.PortExport> export = inner.get().portExports().stream()
                        .filter(e -> e.name().equals(r.port())).findFirst();
                if (export.isEmpty()) {
                    diagnostics.error(r.pos(), "component " + r.component() + " (compound type " + inner.get().name()
                            + ") exports no port '" + r.port() + "'");
                    return null;
                }
                PackageScope innerScope = new PackageScope(scope.workspace(), scope.owner(inner.get()));
                return new CompoundChecker(innerScope, typer, new Diagnostics()).portTypeOf(inner.get(),
                        export.get().ports().get(0));
            }
            return null;
        }
        Optional<CompoundType.Connector> connector = c.connector(r.component());
        if (connector.isPresent()) {
            Optional<ConnectorType> type = scope.connectorType(connector.get().type());
            if (type.isEmpty()) {
                return null;
            }
            if (type.get().exportPort() == null || !type.get().exportPort().name().equals(r.port())) {
                diagnostics.error(r.pos(), "connector " + r.component() + " exports no port '" + r.port() + "'");
                return null;
            }
            return new PackageScope(scope.workspace(), scope.owner(type.get()))
                    .portType(type.get().exportPort().portType()).orElse(null);
        }
        diagnostics.error(r.pos(), "unknown component '" + r.component() + "' in " + r + "; components are "
                + c.components().stream().map(CompoundType.Component::name).toList());
        return null;
    }
}
