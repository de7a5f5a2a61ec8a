package eu.brain.iot.bip.check;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.CompoundType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.ConstDecl;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortType;

/** The {@link Names} of each place where expressions occur. */
public final class LocalNames implements Names {

    private final PackageScope scope;
    private final Map<String, Symbol> plain = new HashMap<>();
    private final Map<String, Symbol> qualified = new HashMap<>();
    private final String hint;

    private LocalNames(PackageScope scope, String hint) {
        this.scope = scope;
        this.hint = hint;
    }

    /** Package constants only (constant initialisers, component arguments). */
    public static LocalNames constants(PackageScope scope) {
        return new LocalNames(scope, "no qualified names here");
    }

    /** Inside an atom type: parameters, data, clocks, constants. */
    public static LocalNames atom(PackageScope scope, AtomType atom) {
        LocalNames n = new LocalNames(scope, "a plain name (qualified names are for connectors)");
        for (Param p : atom.params()) {
            n.plain.put(p.name(), new Symbol(Symbol.Kind.PARAM, p.name(), type(scope, p.type().name()), p));
        }
        for (DataDecl d : atom.data()) {
            n.plain.put(d.name(), new Symbol(Symbol.Kind.DATA, d.name(), type(scope, d.type().name()), d));
        }
        for (AtomType.ClockDecl c : atom.clocks()) {
            n.plain.put(c.name(), new Symbol(Symbol.Kind.CLOCK, c.name(), Type.FLOAT, c));
        }
        return n;
    }

    /** Inside a connector type: {@code port.var} of its port parameters, and its own data. */
    public static LocalNames connector(PackageScope scope, ConnectorType connector) {
        LocalNames n = new LocalNames(scope, "port.data, with port one of the connector's ports "
                + connector.ports().stream().map(Param::name).toList());
        for (DataDecl d : connector.data()) {
            n.plain.put(d.name(), new Symbol(Symbol.Kind.DATA, d.name(), type(scope, d.type().name()), d));
        }
        for (Param p : connector.ports()) {
            Optional<PortType> pt = scope.portType(p.type().name());
            if (pt.isPresent()) {
                for (Param v : pt.get().params()) {
                    n.qualified.put(p.name() + "." + v.name(),
                            new Symbol(Symbol.Kind.PORT_DATA, p.name() + "." + v.name(), type(scope, v.type().name()), v));
                }
            }
        }
        return n;
    }

    /** Inside a compound type: its parameters and the exported data of its components ({@code A.x}). */
    public static LocalNames compound(PackageScope scope, CompoundType compound) {
        LocalNames n = new LocalNames(scope, "component.data, with data exported by the component");
        for (Param p : compound.params()) {
            n.plain.put(p.name(), new Symbol(Symbol.Kind.PARAM, p.name(), type(scope, p.type().name()), p));
        }
        for (CompoundType.Component c : compound.components()) {
            scope.atomType(c.type()).ifPresent(a -> a.data().stream().filter(DataDecl::exported).forEach(d ->
                    n.qualified.put(c.name() + "." + d.name(), new Symbol(Symbol.Kind.COMPONENT_DATA,
                            c.name() + "." + d.name(), type(scope, d.type().name()), d))));
            scope.compoundType(c.type()).ifPresent(k -> k.dataExports().forEach(e -> n.qualified.put(
                    c.name() + "." + e.name(), new Symbol(Symbol.Kind.COMPONENT_DATA, c.name() + "." + e.name(),
                            Type.ERROR, e))));
        }
        return n;
    }

    private static Type type(PackageScope scope, String name) {
        Type t = scope.resolveType(name);
        return t == null ? Type.ERROR : t;
    }

    @Override
    public Symbol lookup(String name) {
        Symbol s = plain.get(name);
        if (s != null) {
            return s;
        }
        Optional<ConstDecl> c = scope.constant(name);
        return c.map(d -> new Symbol(Symbol.Kind.CONST, name, type(scope, d.type().name()), d)).orElse(null);
    }

    @Override
    public Symbol lookup(String qualifier, String name) {
        Symbol s = qualified.get(qualifier + "." + name);
        if (s != null) {
            return s;
        }
        Optional<ConstDecl> c = scope.constant(qualifier + "." + name);
        return c.map(d -> new Symbol(Symbol.Kind.CONST, name, type(scope, d.type().name()), d)).orElse(null);
    }

    @Override
    public String qualifiedHint() {
        return hint;
    }
}
