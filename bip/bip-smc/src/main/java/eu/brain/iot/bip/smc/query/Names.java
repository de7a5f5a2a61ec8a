package eu.brain.iot.bip.smc.query;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Collectors;

import eu.brain.iot.bip.check.ConstantFolder;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.smc.query.QueryLexer.Token;
import eu.brain.iot.bip.system.SystemModel;
import eu.brain.iot.bip.system.SystemModel.AtomInstance;

/** What a query may name in a system: atom instances (by path), their data, parameters and places, constants. */
public final class Names {

    private final SystemModel system;
    private final PackageScope rootScope;

    public Names(SystemModel system) {
        this.system = system;
        this.rootScope = system.atoms().isEmpty() ? null
                : new PackageScope(system.atoms().get(0).scope().workspace(), system.rootPackage());
    }

    private int index(String path) {
        for (int i = 0; i < system.atoms().size(); i++) {
            if (system.atoms().get(i).path().equals(path)) {
                return i;
            }
        }
        return -1;
    }

    private String components() {
        return system.atoms().stream().map(AtomInstance::path).collect(Collectors.joining(", "));
    }

    private static String join(List<Token> parts, int n) {
        return parts.subList(0, n).stream().map(Token::text).collect(Collectors.joining("."));
    }

    Term at(List<Token> parts, Token place) throws QueryException {
        String path = join(parts, parts.size());
        int atom = index(path);
        if (atom < 0) {
            throw new QueryException(parts.get(0).pos(), "unknown component " + path + " (components: " + components()
                    + ")");
        }
        AtomType type = system.atoms().get(atom).type();
        if (type.places().stream().noneMatch(p -> p.name().equals(place.text()))) {
            throw new QueryException(place.pos(), "component " + path + " (" + type.name() + ") has no place "
                    + place.text() + " (places: " + type.places().stream().map(AtomType.Place::name)
                            .collect(Collectors.joining(", ")) + ")");
        }
        return new Term.At(atom, path, place.text());
    }

    Term value(List<Token> parts, List<Query.Sweep> sweeps) throws QueryException {
        Token first = parts.get(0);
        if (parts.size() == 1) {
            for (int i = 0; i < sweeps.size(); i++) {
                Query.Sweep s = sweeps.get(i);
                if (s.name().equals(first.text())) {
                    return new Term.Param(i, s.name(), s.integral() ? Type.INT : Type.FLOAT);
                }
            }
            Optional<Term> constant = constant(first.text(), first.pos());
            if (constant.isPresent()) {
                return constant.get();
            }
            throw new QueryException(first.pos(), "unknown name " + first.text() + ": not a swept parameter ("
                    + (sweeps.isEmpty() ? "none; sweep one with 'for x = from:to:step'"
                            : sweeps.stream().map(Query.Sweep::name).collect(Collectors.joining(", ")))
                    + ") nor a constant of package " + system.rootPackage().name() + "; data are named component.data");
        }
        String path = join(parts, parts.size() - 1);
        Token datum = parts.get(parts.size() - 1);
        int atom = index(path);
        if (atom < 0) {
            throw new QueryException(first.pos(), "unknown component " + path + " (components: " + components() + ")");
        }
        AtomInstance a = system.atoms().get(atom);
        List<String> known = new ArrayList<>();
        for (Param p : a.type().params()) {
            known.add(p.name());
            if (p.name().equals(datum.text())) {
                return new Term.Data(atom, path, p.name(), type(a, p.type().name()));
            }
        }
        for (DataDecl d : a.type().data()) {
            known.add(d.name());
            if (d.name().equals(datum.text())) {
                Type t = type(a, d.type().name());
                if (!(t.numeric() || t.kind() == Type.Kind.BOOL)) {
                    throw new QueryException(datum.pos(), "datum " + path + "." + d.name() + " is " + t
                            + ": queries compare int, float and bool data");
                }
                return new Term.Data(atom, path, d.name(), t);
            }
        }
        throw new QueryException(datum.pos(), "component " + path + " (" + a.type().name() + ") has no data "
                + datum.text() + " (data: " + String.join(", ", known) + ")");
    }

    private static Type type(AtomInstance a, String bipType) {
        Type t = a.scope().resolveType(bipType);
        return t == null ? Type.ERROR : t;
    }

    private Optional<Term> constant(String name, Pos pos) {
        if (rootScope == null || rootScope.constant(name).isEmpty()) {
            return Optional.empty();
        }
        Object v = ConstantFolder.fold(new Expr.Var(pos, null, name), rootScope);
        if (v instanceof Integer) {
            return Optional.of(new Term.Lit(v, Type.INT));
        }
        if (v instanceof Double) {
            return Optional.of(new Term.Lit(v, Type.FLOAT));
        }
        if (v instanceof Boolean) {
            return Optional.of(new Term.Lit(v, Type.BOOL));
        }
        return Optional.empty();
    }
}
