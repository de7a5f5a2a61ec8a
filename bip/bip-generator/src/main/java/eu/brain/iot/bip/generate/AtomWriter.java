package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import eu.brain.iot.bip.check.ConstantFolder;
import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.LocalNames;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Symbol;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.AtomType.Transition;
import eu.brain.iot.bip.model.ConstDecl;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;

/**
 * Writes one atom type as one Java class: its place (an enum field for automata, a marking for Petri nets), its
 * data as fields, one method per port that fires the port's first enabled transition, {@code internalStep()} for
 * internal transitions, and {@code enabledPorts()} after the atom's priorities. No reflection, no thread.
 */
final class AtomWriter {

    static final Set<String> RESERVED = Set.of("bipPlace", "bipMarking", "bipExterns", "Place", "Port");

    private final AtomType atom;
    private final PackageScope scope;
    private final ExprTyper typer;
    private final LocalNames names;
    private final String className;
    private final String externsName;
    private final boolean automaton;

    AtomWriter(AtomType atom, PackageScope scope, ExprTyper typer, String className, String externsName) {
        this.atom = atom;
        this.scope = scope;
        this.typer = typer;
        this.names = LocalNames.atom(scope, atom);
        this.className = className;
        this.externsName = externsName;
        this.automaton = atom.initial() != null && atom.initial().to().size() == 1 && atom.transitions().stream()
                .allMatch(t -> t.from().size() == 1 && t.to().size() == 1);
    }

    static String field(String bipName) {
        String id = JavaNames.id(bipName);
        return RESERVED.contains(id) ? id + "_" : id;
    }

    static String portMethod(String port) {
        return "on" + JavaNames.capital(port);
    }

    /** The calls this atom's own code makes. */
    static List<ResolvedCall> calls(AtomType atom, PackageScope scope, ExprTyper typer) {
        List<ResolvedCall> calls = new ArrayList<>();
        CallCollector collector = new CallCollector(typer, LocalNames.atom(scope, atom), calls);
        atom.data().forEach(d -> collector.expr(d.init()));
        if (atom.initial() != null && atom.initial().action() != null) {
            collector.stmts(atom.initial().action().stmts());
        }
        for (Transition t : atom.transitions()) {
            collector.expr(t.guard());
            if (t.action() != null) {
                collector.stmts(t.action().stmts());
            }
        }
        atom.priorities().forEach(p -> collector.expr(p.guard()));
        return calls;
    }

    String write(String javaPackage, boolean hasExterns) {
        Code c = new Code();
        c.line("package " + javaPackage + ";").blank();
        c.line("/**");
        c.line(" * Atom type {@code " + atom.name() + "} of " + JavaNames.fileName(atom.pos()) + ", generated: do not edit.");
        c.line(" * <p>");
        c.line(" * Not thread-safe: its owner (the generated behaviour) calls it under one lock.");
        c.line(" */");
        c.line("@javax.annotation.processing.Generated(\"eu.brain.iot.bip\")");
        c.open("public final class " + className);
        c.blank();
        c.line("/** The places of the atom. */");
        c.line("public enum Place { " + atom.places().stream().map(p -> JavaNames.id(p.name())).collect(
                Collectors.joining(", ")) + " }");
        c.blank();
        c.line("/** The ports of the atom, in declaration order. */");
        c.line("public enum Port { " + atom.ports().stream().map(p -> JavaNames.id(p.name())).collect(
                Collectors.joining(", ")) + " }");
        c.blank();
        constants(c);
        if (hasExterns) {
            c.line("private final " + externsName + " bipExterns;");
        }
        for (Param p : atom.params()) {
            c.line("/** Parameter {@code " + p.name() + "}. */");
            c.line("final " + javaType(p.type().name()) + " " + field(p.name()) + ";");
        }
        for (DataDecl d : atom.data()) {
            c.line(javaType(d.type().name()) + " " + field(d.name()) + ";");
        }
        atom.clocks().forEach(k -> c.line("double " + field(k.name()) + "; // clock (unit: " + k.unit() + ")"));
        if (automaton) {
            c.line("private Place bipPlace;");
        } else {
            c.line("private final boolean[] bipMarking = new boolean[" + atom.places().size() + "];");
        }
        c.blank();
        constructor(c, hasExterns);
        accessors(c);
        enabled(c);
        for (PortDecl p : atom.ports()) {
            portMethod(c, p);
        }
        internalStep(c);
        c.close();
        return c.toString();
    }

    private void constants(Code c) {
        List<ConstDecl> used = new ArrayList<>();
        new CallCollector(typer, names, new ArrayList<>()) {
            @Override
            void var(Expr.Var v) {
                Symbol s = typer.symbol(v, names);
                if (s != null && s.kind() == Symbol.Kind.CONST && !used.contains((ConstDecl) s.decl())) {
                    used.add((ConstDecl) s.decl());
                }
            }
        }.atom(atom);
        for (ConstDecl k : used) {
            // the folded value, not the initialiser: constants it refers to need no field of their own
            PackageScope owner = new PackageScope(scope.workspace(), scope.owner(k));
            c.line("static final " + javaType(k.type().name()) + " " + constant(k) + " = "
                    + JavaNames.value(ConstantFolder.fold(k.value(), owner)) + ";");
        }
        if (!used.isEmpty()) {
            c.blank();
        }
    }

    /** @return the field of a constant: K_name, or K_package_name for a constant of another package */
    private String constant(ConstDecl k) {
        String pkg = scope.owner(k).name();
        String own = scope.pkg().name();
        return "K_" + (pkg.equals(own) ? "" : pkg.replace('.', '_') + "_") + k.name();
    }

    private String javaType(String bipType) {
        Type t = scope.resolveType(bipType);
        return JavaNames.javaType(t == null ? Type.ERROR : t, scope);
    }

    private void constructor(Code c, boolean hasExterns) {
        List<String> params = new ArrayList<>();
        if (hasExterns) {
            params.add(externsName + " externs");
        }
        atom.params().forEach(p -> params.add(javaType(p.type().name()) + " " + field(p.name())));
        c.line("/** Creates the atom and runs its initial transition. */");
        c.open("public " + className + "(" + String.join(", ", params) + ")");
        if (hasExterns) {
            c.line("this.bipExterns = java.util.Objects.requireNonNull(externs, \"externs\");");
        }
        atom.params().forEach(p -> c.line("this." + field(p.name()) + " = " + field(p.name()) + ";"));
        ExprWriter w = writer();
        for (DataDecl d : atom.data()) {
            if (d.init() != null) {
                c.line("this." + field(d.name()) + " = " + w.expr(d.init()) + ";");
            } else if (scope.resolveType(d.type().name()) == Type.STRING) {
                c.line("this." + field(d.name()) + " = \"\";");
            }
        }
        if (atom.initial() != null) {
            mark(c, atom.initial().to());
            if (atom.initial().action() != null) {
                w.statements(c, atom.initial().action().stmts());
            }
        }
        c.close().blank();
    }

    private void accessors(Code c) {
        if (automaton) {
            c.line("/** @return the current place */");
            c.open("public Place place()").line("return bipPlace;").close().blank();
        }
        c.line("/** @return whether the place is marked */");
        c.open("public boolean isMarked(Place place)");
        c.line(automaton ? "return bipPlace == place;" : "return bipMarking[place.ordinal()];");
        c.close().blank();
        c.line("/** @return the marked places */");
        c.open("public java.util.EnumSet<Place> marking()");
        c.line("java.util.EnumSet<Place> marked = java.util.EnumSet.noneOf(Place.class);");
        c.open("for (Place p : Place.values())").open("if (isMarked(p))").line("marked.add(p);").close().close();
        c.line("return marked;").close().blank();
        c.line("/** @return the data values by name, for tests and traces */");
        c.open("public java.util.Map<String, Object> data()");
        c.line("java.util.Map<String, Object> data = new java.util.LinkedHashMap<>();");
        atom.data().forEach(d -> c.line("data.put(" + JavaNames.literal(d.name()) + ", " + field(d.name()) + ");"));
        c.line("return data;").close().blank();
        c.line("/** @return the invariants that do not hold in the current state (none in a correct run) */");
        c.open("public java.util.List<String> violatedInvariants()");
        if (atom.invariants().isEmpty()) {
            c.line("return java.util.List.of();");
        } else {
            c.line("java.util.List<String> violated = new java.util.ArrayList<>();");
            ExprWriter w = writer();
            for (AtomType.Invariant inv : atom.invariants()) {
                String where = inv.places().isEmpty() ? "" : "(" + inv.places().stream()
                        .map(p -> marked(List.of(p))).collect(Collectors.joining(" || ")) + ") && ";
                c.open("if (" + where + "!" + w.expr(inv.condition()) + ")");
                c.line("violated.add(" + JavaNames.literal(inv.name()) + ");").close();
            }
            c.line("return violated;");
        }
        c.close().blank();
    }

    private String marked(List<String> places) {
        return places.stream().map(p -> automaton ? "bipPlace == Place." + JavaNames.id(p)
                : "bipMarking[Place." + JavaNames.id(p) + ".ordinal()]").collect(Collectors.joining(" && "));
    }

    private void mark(Code c, List<String> to) {
        if (automaton) {
            c.line("bipPlace = Place." + JavaNames.id(to.get(0)) + ";");
        } else {
            to.forEach(p -> c.line("bipMarking[Place." + JavaNames.id(p) + ".ordinal()] = true;"));
        }
    }

    private void move(Code c, Transition t) {
        if (automaton) {
            c.line("bipPlace = Place." + JavaNames.id(t.to().get(0)) + ";");
            return;
        }
        t.from().stream().filter(p -> !t.to().contains(p))
                .forEach(p -> c.line("bipMarking[Place." + JavaNames.id(p) + ".ordinal()] = false;"));
        t.to().forEach(p -> c.line("bipMarking[Place." + JavaNames.id(p) + ".ordinal()] = true;"));
    }

    private String condition(Transition t) {
        String places = marked(t.from());
        return t.guard() == null ? places : places + " && " + writer().expr(t.guard());
    }

    private void enabled(Code c) {
        c.line("/** @return whether a transition labelled by the port is enabled (place marked, guard true) */");
        c.open("public boolean isEnabled(Port port)");
        c.open("switch (port)");
        for (PortDecl p : atom.ports()) {
            List<Transition> ts = transitions(p.name());
            c.line("case " + JavaNames.id(p.name()) + ": return " + (ts.isEmpty() ? "false"
                    : ts.stream().map(t -> "(" + condition(t) + ")").collect(Collectors.joining(" || "))) + ";");
        }
        c.line("default: return false;");
        c.close().close().blank();
        c.line("/** @return the enabled ports that no enabled port has priority over, in declaration order */");
        c.open("public java.util.EnumSet<Port> enabledPorts()");
        c.line("java.util.EnumSet<Port> enabled = java.util.EnumSet.noneOf(Port.class);");
        c.open("for (Port p : Port.values())").open("if (isEnabled(p))").line("enabled.add(p);").close().close();
        if (!atom.priorities().isEmpty()) {
            int n = atom.ports().size();
            c.line("boolean[][] lower = new boolean[" + n + "][" + n + "];");
            ExprWriter w = writer();
            for (AtomType.Priority p : atom.priorities()) {
                String low = p.low().equals("*") ? "-1" : "Port." + JavaNames.id(p.low()) + ".ordinal()";
                String high = p.high().equals("*") ? "-1" : "Port." + JavaNames.id(p.high()) + ".ordinal()";
                c.open("if (" + (p.guard() == null ? "true" : w.expr(p.guard())) + ")");
                c.line("bipPrefer(lower, " + low + ", " + high + ");");
                c.close();
            }
            c.line("bipCloseTransitively(lower);");
            c.line("java.util.EnumSet<Port> maximal = java.util.EnumSet.copyOf(enabled);");
            c.open("for (Port p : enabled)").open("for (Port q : enabled)");
            c.open("if (p != q && lower[p.ordinal()][q.ordinal()])").line("maximal.remove(p);").close();
            c.close().close();
            c.line("return maximal;").close().blank();
            c.open("private static void bipPrefer(boolean[][] lower, int low, int high)");
            c.open("for (int l = 0; l < lower.length; l++)").open("for (int h = 0; h < lower.length; h++)");
            c.open("if ((low < 0 || l == low) && (high < 0 || h == high) && l != h)").line("lower[l][h] = true;");
            c.close().close().close().close().blank();
            c.open("private static void bipCloseTransitively(boolean[][] lower)");
            c.open("for (int k = 0; k < lower.length; k++)").open("for (int i = 0; i < lower.length; i++)");
            c.open("for (int j = 0; j < lower.length; j++)").open("if (lower[i][k] && lower[k][j])");
            c.line("lower[i][j] = true;").close().close().close().close().close().blank();
        } else {
            c.line("return enabled;").close().blank();
        }
        c.line("/** Fires the first enabled transition labelled by the port; @return whether one fired */");
        c.open("public boolean fire(Port port)");
        c.open("switch (port)");
        atom.ports().forEach(p -> c.line("case " + JavaNames.id(p.name()) + ": return " + portMethod(p.name()) + "();"));
        c.line("default: return false;");
        c.close().close().blank();
    }

    private List<Transition> transitions(String port) {
        return atom.transitions().stream().filter(t -> port.equals(t.port())).toList();
    }

    private void portMethod(Code c, PortDecl p) {
        c.line("/** Port {@code " + p.name() + "}: fires its first enabled transition; @return whether one fired */");
        c.open("public boolean " + portMethod(p.name()) + "()");
        fireFirst(c, transitions(p.name()));
        c.close().blank();
    }

    private void internalStep(Code c) {
        c.line("/** Fires the first enabled internal transition; @return whether one fired */");
        c.open("public boolean internalStep()");
        fireFirst(c, atom.transitions().stream().filter(Transition::internal).toList());
        c.close().blank();
        c.line("/** @return whether an internal transition is enabled (the statistical model checker offers it as a step) */");
        c.open("public boolean isInternalEnabled()");
        List<Transition> internal = atom.transitions().stream().filter(Transition::internal).toList();
        c.line("return " + (internal.isEmpty() ? "false"
                : internal.stream().map(t -> "(" + condition(t) + ")").collect(Collectors.joining(" || "))) + ";");
        c.close();
    }

    private void fireFirst(Code c, Collection<Transition> transitions) {
        ExprWriter w = writer();
        for (Transition t : transitions) {
            c.open("if (" + condition(t) + ")");
            move(c, t);
            if (t.action() != null) {
                w.statements(c, t.action().stmts());
            }
            c.line("return true;");
            c.close();
        }
        c.line("return false;");
    }

    private ExprWriter writer() {
        return new ExprWriter(typer, names, new AtomMapper());
    }

    /** Atom code reads and writes its fields and calls its extern interface. */
    private final class AtomMapper implements ExprWriter.Mapper {
        @Override
        public String read(Symbol s, Expr.Var v) {
            return s.kind() == Symbol.Kind.CONST ? constant((ConstDecl) s.decl()) : field(v.name());
        }

        @Override
        public String write(Symbol s, Expr.Var v) {
            return field(v.name());
        }

        @Override
        public String call(ResolvedCall call, List<String> args) {
            return "bipExterns." + JavaNames.id(call.name()) + "(" + String.join(", ", args) + ")";
        }
    }
}
