package eu.brain.iot.bip.check;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.AtomType.Transition;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.model.PortType;
import eu.brain.iot.bip.model.Pos;

/** Checks one atom type, and warns about unreachable places and transitions that can never fire. */
final class AtomChecker {

    private final PackageScope scope;
    private final ExprTyper typer;
    private final Diagnostics diagnostics;

    AtomChecker(PackageScope scope, ExprTyper typer, Diagnostics diagnostics) {
        this.scope = scope;
        this.typer = typer;
        this.diagnostics = diagnostics;
    }

    void check(AtomType atom) {
        String owner = "atom type " + atom.name();
        Checker.params(scope, atom.params(), owner);
        Map<String, Pos> names = new HashMap<>();
        atom.params().forEach(p -> Checker.unique(diagnostics, names, p.name(), p.pos(), "name"));
        atom.data().forEach(d -> Checker.unique(diagnostics, names, d.name(), d.pos(), "name"));
        atom.clocks().forEach(c -> Checker.unique(diagnostics, names, c.name(), c.pos(), "name"));
        LocalNames local = LocalNames.atom(scope, atom);
        for (DataDecl d : atom.data()) {
            Type t = Checker.type(scope, d.type(), "data " + d.name());
            if (d.init() != null) {
                Type v = typer.type(d.init(), local);
                if (!scope.assignable(t, v)) {
                    diagnostics.error(d.init().pos(), "data " + d.name() + " of type " + t
                            + " cannot start with a value of type " + v);
                }
            }
        }
        Map<String, Pos> portNames = new HashMap<>();
        for (PortDecl p : atom.ports()) {
            Checker.unique(diagnostics, portNames, p.name(), p.pos(), "port");
            portDecl(atom, p);
        }
        Map<String, Pos> placeNames = new HashMap<>();
        atom.places().forEach(p -> Checker.unique(diagnostics, placeNames, p.name(), p.pos(), "place"));
        if (atom.places().isEmpty()) {
            diagnostics.error(atom.pos(), owner + " declares no place: add 'place <NAME>, ...'");
        }
        if (atom.initial() == null) {
            diagnostics.error(atom.pos(), owner + " has no initial transition: add 'initial to <PLACE>'");
        } else {
            places(atom, atom.initial().to(), atom.initial().pos(), "'initial to'");
            if (atom.initial().action() != null) {
                typer.statements(atom.initial().action().stmts(), local);
            }
        }
        Set<String> labelled = new HashSet<>();
        for (Transition t : atom.transitions()) {
            if (!t.internal()) {
                labelled.add(t.port());
                if (atom.port(t.port()).isEmpty()) {
                    diagnostics.error(t.pos(), "transition on unknown port '" + t.port() + "' in " + owner
                            + ": declare it with 'port <PortType> " + t.port() + "()'");
                }
            }
            places(atom, t.from(), t.pos(), "'from'");
            places(atom, t.to(), t.pos(), "'to'");
            if (t.guard() != null) {
                typer.expectBool(t.guard(), local, "the guard after 'provided'");
            }
            if (t.action() != null) {
                typer.statements(t.action().stmts(), local);
            }
        }
        for (PortDecl p : atom.ports()) {
            if (!labelled.contains(p.name())) {
                diagnostics.warning(p.pos(), "port " + p.name() + " of " + owner + " labels no transition");
            }
        }
        for (AtomType.Priority p : atom.priorities()) {
            for (String port : List.of(p.low(), p.high())) {
                if (!port.equals("*") && atom.port(port).isEmpty()) {
                    diagnostics.error(p.pos(), "priority " + p.name() + " names unknown port '" + port + "'");
                }
            }
            if (p.guard() != null) {
                typer.expectBool(p.guard(), local, "the guard of priority " + p.name());
            }
        }
        for (AtomType.Invariant i : atom.invariants()) {
            places(atom, i.places(), i.pos(), "'at'");
            typer.expectBool(i.condition(), local, "the condition of invariant " + i.name());
        }
        reachability(atom);
    }

    private void portDecl(AtomType atom, PortDecl p) {
        Optional<PortType> type = scope.portType(p.portType());
        if (type.isEmpty()) {
            diagnostics.error(p.pos(), "unknown port type '" + p.portType() + "' of port " + p.name()
                    + ": declare it with 'port type " + p.portType() + "(...)'");
            return;
        }
        List<Param> params = type.get().params();
        if (params.size() != p.boundData().size()) {
            diagnostics.error(p.pos(), "port " + p.name() + " binds " + p.boundData().size() + " data, but port type "
                    + p.portType() + " has " + params.size() + " parameters " + params.stream().map(Param::name).toList());
            return;
        }
        for (int i = 0; i < params.size(); i++) {
            String name = p.boundData().get(i);
            Optional<DataDecl> data = atom.dataDecl(name);
            if (data.isEmpty()) {
                diagnostics.error(p.pos(), "port " + p.name() + " binds unknown data '" + name + "'");
                continue;
            }
            Type expected = scope.resolveType(params.get(i).type().name());
            Type actual = scope.resolveType(data.get().type().name());
            if (expected != null && actual != null && !expected.equals(actual)) {
                diagnostics.error(p.pos(), "port " + p.name() + " binds " + name + " of type " + actual
                        + " to parameter " + params.get(i).name() + " of type " + expected
                        + " (BIP2 does not convert port data)");
            }
        }
    }

    private void places(AtomType atom, List<String> names, Pos pos, String clause) {
        Set<String> seen = new HashSet<>();
        for (String name : names) {
            if (atom.places().stream().noneMatch(p -> p.name().equals(name))) {
                diagnostics.error(pos, "unknown place '" + name + "' after " + clause + " in atom type " + atom.name()
                        + "; places are " + atom.places().stream().map(AtomType.Place::name).toList());
            }
            if (!seen.add(name)) {
                diagnostics.error(pos, "place '" + name + "' appears twice after " + clause);
            }
        }
    }

    /** Warns about places no transition sequence can mark and transitions that can never fire. */
    private void reachability(AtomType atom) {
        if (atom.initial() == null) {
            return;
        }
        Set<String> reached = new LinkedHashSet<>(atom.initial().to());
        List<Transition> live = new ArrayList<>();
        for (Transition t : atom.transitions()) {
            if (t.guard() == null || ConstantFolder.fold(t.guard(), scope) != Boolean.FALSE) {
                live.add(t);
            } else {
                diagnostics.warning(t.pos(), describe(t) + " can never fire: its guard is always false");
            }
        }
        boolean changed = true;
        while (changed) {
            changed = false;
            for (Transition t : live) {
                if (reached.containsAll(t.from()) && reached.addAll(t.to())) {
                    changed = true;
                }
            }
        }
        for (AtomType.Place p : atom.places()) {
            if (!reached.contains(p.name())) {
                diagnostics.warning(p.pos(), "place " + p.name() + " of atom type " + atom.name()
                        + " is unreachable from the initial place");
            }
        }
        for (Transition t : live) {
            if (!reached.containsAll(t.from())) {
                diagnostics.warning(t.pos(), describe(t) + " can never fire: place " + t.from().stream()
                        .filter(f -> !reached.contains(f)).findFirst().orElse("?") + " is unreachable");
            }
        }
    }

    private static String describe(Transition t) {
        return (t.internal() ? "internal transition" : "transition on " + t.port()) + " from "
                + String.join(", ", t.from());
    }
}
