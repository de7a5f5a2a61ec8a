package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import eu.brain.iot.bip.check.ConstantFolder;
import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.Interactions;
import eu.brain.iot.bip.check.LocalNames;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Symbol;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.system.SystemModel;
import eu.brain.iot.bip.system.SystemModel.AtomInstance;
import eu.brain.iot.bip.system.SystemModel.ConnectorInstance;
import eu.brain.iot.bip.system.SystemModel.Endpoint;

/**
 * Writes the Java the statistical model checker compiles at run time for a whole system: the deployed atom classes
 * (unchanged, from {@link AtomWriter}), their bridges and extern simulations ({@link SimulationAtomWriter}), and a
 * driver implementing {@code smc.runtime.SimulatedSystem}: the candidate steps enumerated in straight-line code from
 * the atoms' enabled-port masks (kept per atom, recomputed only for the atoms a step changed), connector guards, up
 * and down transfers, and the query's atomic propositions as direct reads. Same semantics and random draws as the
 * interpreter ({@code smc.sim.InterpretedSystem}), which tests compare it with.
 */
public final class SimulationWriter {

    /** Candidates enumerated per generated method, to keep methods small enough for the JIT. */
    private static final int CONNECTORS_PER_METHOD = 24;

    private final SystemModel system;
    private final Diagnostics diagnostics;
    private final SimulationBuiltins builtins;
    private final Map<AtomType, SimulationAtomWriter> types = new LinkedHashMap<>();
    private final List<AtomInstance> atoms;
    private final List<String> names = new ArrayList<>();

    /** @param builtins the extern calls the simulation answers from the trace's random source */
    public SimulationWriter(SystemModel system, Diagnostics diagnostics, SimulationBuiltins builtins) {
        this.system = system;
        this.diagnostics = diagnostics;
        this.builtins = builtins;
        this.atoms = system.atoms();
        for (AtomInstance a : atoms) {
            types.computeIfAbsent(a.type(), t -> new SimulationAtomWriter(t, a.scope(), diagnostics, builtins));
        }
    }

    /** @return the atom classes, extern interfaces, bridges and extern simulations of every atom type used */
    public List<JavaFile> atomFiles() {
        List<JavaFile> files = new ArrayList<>();
        types.values().forEach(w -> files.addAll(w.files()));
        return files;
    }

    private int index(String path) {
        for (int i = 0; i < atoms.size(); i++) {
            if (atoms.get(i).path().equals(path)) {
                return i;
            }
        }
        throw new IllegalArgumentException("no atom " + path);
    }

    private SimulationAtomWriter type(int atom) {
        return types.get(atoms.get(atom).type());
    }

    /** @return Java reading datum (or parameter) {@code name} of atom instance {@code atom} (system order) */
    public String dataRead(int atom, String name) {
        return type(atom).bridge() + ".get_" + name + "(a" + atom + ")";
    }

    /** @return Java testing whether place {@code place} of atom instance {@code atom} is marked */
    public String placeRead(int atom, String place) {
        SimulationAtomWriter w = type(atom);
        return "a" + atom + ".isMarked(" + w.qualified(w.atomClass) + ".Place." + JavaNames.id(place) + ")";
    }

    /**
     * @param javaPackage the driver's package
     * @param className the driver's class name
     * @param propositions Java boolean expressions (from {@link #dataRead}, {@link #placeRead} and
     *        {@code params[i]}), the driver's {@code ap(i)}
     */
    public JavaFile driver(String javaPackage, String className, List<String> propositions) {
        Code c = new Code();
        c.line("package " + javaPackage + ";").blank();
        c.line("/** The simulation driver of system " + system.root().name() + ", generated: do not edit. Owned by one thread. */");
        c.open("public final class " + className + " implements " + SimulationAtomWriter.RT + "SimulatedSystem");
        c.line("private final " + SimulationAtomWriter.RT + "TraceRandom random = new " + SimulationAtomWriter.RT
                + "TraceRandom();");
        c.line("private final " + SimulationAtomWriter.RT + "SimulationExterns simulation;");
        c.line("private final double[] params;");
        c.line("private int last = -1;");
        for (int i = 0; i < atoms.size(); i++) {
            SimulationAtomWriter w = type(i);
            c.line("private " + w.qualified(w.atomClass) + " a" + i + ";");
            c.line("private long e" + i + ";");
        }
        c.open("public " + className + "(" + SimulationAtomWriter.RT + "SimulationExterns simulation, double[] params)");
        c.line("this.simulation = simulation;").line("this.params = params;").close();
        reset(c);
        List<String> steps = new ArrayList<>();
        Code enumerate = new Code();
        int methods = enumerators(enumerate, steps);
        c.line("private final int[] candidates = new int[" + Math.max(1, steps.size()) + "];");
        c.line("@Override");
        c.open("public boolean step()");
        c.line("int[] c = candidates;").line("int n = 0;");
        for (int m = 0; m < methods; m++) {
            c.line("n = enumerate" + m + "(c, n);");
        }
        c.line("if (n == 0) return false;");
        c.line("int id = n == 1 ? c[0] : c[random.nextInt(n)];");
        c.line("last = id;");
        c.open("switch (id)");
        for (int i = 0; i < steps.size(); i++) {
            c.line("case " + i + ": x" + i + "(); break;");
        }
        c.line("default: throw new IllegalStateException();");
        c.close();
        c.line("return true;").close();
        c.raw(enumerate.toString());
        for (String s : steps) {
            c.raw(s);
        }
        c.line("private static final String[] NAMES = {");
        names.forEach(n -> c.line("    " + JavaNames.literal(n) + ","));
        c.line("};");
        c.line("@Override");
        c.open("public String lastStep()").line("return last < 0 ? \"\" : NAMES[last];").close();
        c.line("@Override");
        c.open("public String state()");
        c.line("StringBuilder s = new StringBuilder();");
        for (int i = 0; i < atoms.size(); i++) {
            c.line("s.append(" + JavaNames.literal(atoms.get(i).path() + " ") + ").append(" + type(i).bridge()
                    + ".state(a" + i + ")).append('\\n');");
        }
        c.line("return s.toString();").close();
        c.line("@Override");
        c.open("public boolean ap(int index)");
        c.open("switch (index)");
        for (int i = 0; i < propositions.size(); i++) {
            c.line("case " + i + ": return " + propositions.get(i) + ";");
        }
        c.line("default: throw new IndexOutOfBoundsException(index);");
        c.close().close();
        c.close();
        return new JavaFile(javaPackage, className, c.toString());
    }

    private void reset(Code c) {
        c.line("@Override");
        c.open("public void reset(long seed)");
        c.line("random.seed(seed);").line("last = -1;");
        for (int i = 0; i < atoms.size(); i++) {
            SimulationAtomWriter w = type(i);
            AtomInstance a = atoms.get(i);
            List<String> args = new ArrayList<>();
            if (w.hasExterns()) {
                args.add("new " + w.qualified(w.atomClass + "SmcExterns") + "(random, simulation)");
            }
            for (int p = 0; p < a.type().params().size(); p++) {
                Type t = a.scope().resolveType(a.type().params().get(p).type().name());
                args.add(literal(p < a.args().size() ? a.args().get(p) : null, t));
            }
            c.line("a" + i + " = new " + w.qualified(w.atomClass) + "(" + String.join(", ", args) + ");");
        }
        for (int i = 0; i < atoms.size(); i++) {
            c.line("e" + i + " = " + type(i).bridge() + ".mask(a" + i + ");");
        }
        c.close();
    }

    private static String literal(Object value, Type t) {
        if (value == null || t == null) {
            return JavaNames.defaultLiteral(t);
        }
        return switch (t.kind()) {
            case INT -> Integer.toString(((Number) value).intValue());
            case FLOAT -> {
                double d = ((Number) value).doubleValue();
                yield Double.isFinite(d) ? Double.toString(d) : "Double.NaN";
            }
            case BOOL -> value.toString();
            case STRING -> JavaNames.literal(value.toString());
            default -> "null";
        };
    }

    /** Writes the enumeration methods; each step's executing method goes to {@code steps}. @return method count */
    private int enumerators(Code c, List<String> steps) {
        int method = 0;
        c.open("private int enumerate" + method++ + "(int[] c, int n)");
        for (int i = 0; i < atoms.size(); i++) {
            AtomType t = atoms.get(i).type();
            if (t.transitions().stream().anyMatch(AtomType.Transition::internal)) {
                c.line("if ((e" + i + " & (1L << " + SimulationAtomWriter.INTERNAL_BIT + ")) != 0) c[n++] = "
                        + steps.size() + ";");
                steps.add(atomStep(steps.size(), i, "a" + i + ".internalStep();", "internal " + atoms.get(i).path()));
            }
        }
        for (int i = 0; i < atoms.size(); i++) {
            List<PortDecl> ports = atoms.get(i).type().ports();
            for (int p = 0; p < ports.size(); p++) {
                if (!ports.get(p).exported()) {
                    c.line("if ((e" + i + " & (1L << " + p + ")) != 0) c[n++] = " + steps.size() + ";");
                    steps.add(atomStep(steps.size(), i, "a" + i + "." + AtomWriter.portMethod(ports.get(p).name())
                            + "();", atoms.get(i).path() + "." + ports.get(p).name()));
                }
            }
        }
        int inMethod = 0;
        for (ConnectorInstance k : system.connectors()) {
            if (inMethod++ == CONNECTORS_PER_METHOD) {
                c.line("return n;").close();
                c.open("private int enumerate" + method++ + "(int[] c, int n)");
                inMethod = 1;
            }
            connector(c, k, steps);
        }
        c.line("return n;").close();
        return method;
    }

    private String atomStep(int id, int atom, String fire, String name) {
        names.add(name);
        Code c = new Code();
        c.open("private void x" + id + "()");
        c.line(fire);
        c.line("e" + atom + " = " + type(atom).bridge() + ".mask(a" + atom + ");");
        c.close();
        return c.toString();
    }

    private void connector(Code c, ConnectorInstance k, List<String> steps) {
        if (k.endpoints().stream().anyMatch(e -> e.atom() == null)) {
            diagnostics.error(k.pos(), "connector " + k.path() + " is hierarchical: statistical model checking does "
                    + "not simulate hierarchical connectors yet");
            return;
        }
        List<Long> interactions = Interactions.of(k.type());
        c.line("// connector " + k.path());
        if (interactions.size() == 1) {
            c.line("if (" + ready(k, interactions.get(0)) + ") c[n++] = " + steps.size() + ";");
            steps.add(interactionStep(steps.size(), k, interactions.get(0)));
            return;
        }
        c.open("");
        c.line("long ok = 0L;");
        for (int j = 0; j < interactions.size(); j++) {
            c.line("if (" + ready(k, interactions.get(j)) + ") ok |= 1L << " + j + ";");
        }
        c.open("if (ok != 0L)");
        for (int j = 0; j < interactions.size(); j++) {
            long supersets = 0;
            for (int i = 0; i < interactions.size(); i++) {
                long a = interactions.get(i);
                long b = interactions.get(j);
                if (i != j && (a & b) == b) {
                    supersets |= 1L << i;
                }
            }
            c.line("if ((ok & " + (1L << j) + "L) != 0L && (ok & " + supersets + "L) == 0L) c[n++] = " + steps.size()
                    + ";");
            steps.add(interactionStep(steps.size(), k, interactions.get(j)));
        }
        c.close().close();
    }

    private String ready(ConnectorInstance k, long interaction) {
        Map<Integer, Long> masks = new LinkedHashMap<>();
        for (int p = 0; p < k.endpoints().size(); p++) {
            if ((interaction & (1L << p)) != 0) {
                Endpoint e = k.endpoints().get(p);
                int atom = index(e.atom());
                masks.merge(atom, 1L << portIndex(atom, e.port()), (x, y) -> x | y);
            }
        }
        List<String> tests = new ArrayList<>();
        masks.forEach((atom, m) -> tests.add("(e" + atom + " & " + m + "L) == " + m + "L"));
        ConnectorType.Interaction clause = Interactions.clause(k.type(), interaction);
        if (clause != null && clause.guard() != null) {
            tests.add(new ConnectorWriter(k, true).writer().expr(clause.guard()));
        }
        return String.join(" && ", tests);
    }

    private int portIndex(int atom, String port) {
        List<PortDecl> ports = atoms.get(atom).type().ports();
        for (int i = 0; i < ports.size(); i++) {
            if (ports.get(i).name().equals(port)) {
                return i;
            }
        }
        throw new IllegalArgumentException("no port " + port);
    }

    private String interactionStep(int id, ConnectorInstance k, long interaction) {
        List<String> parts = new ArrayList<>();
        Set<Integer> changed = new LinkedHashSet<>();
        Code c = new Code();
        c.open("private void x" + id + "()");
        ConnectorType.Interaction clause = Interactions.clause(k.type(), interaction);
        ConnectorWriter cw = new ConnectorWriter(k, false);
        if (clause != null && (clause.up() != null || clause.down() != null)) {
            cw.locals(c, interaction);
            ExprWriter w = cw.writer();
            if (clause.up() != null) {
                w.statements(c, clause.up().stmts());
            }
            if (clause.down() != null) {
                w.statements(c, clause.down().stmts());
            }
            cw.writeBack(c, interaction, SimulationCode.written(clause));
        }
        Set<String> written = clause == null ? Set.of() : SimulationCode.written(clause);
        for (int p = 0; p < k.endpoints().size(); p++) {
            if ((interaction & (1L << p)) != 0) {
                Endpoint e = k.endpoints().get(p);
                int atom = index(e.atom());
                parts.add(e.atom() + "." + e.port());
                String param = k.type().ports().get(p).name();
                if (!written.contains(param) && SimulationCode.pureSelfLoops(atoms.get(atom).type(), e.port())) {
                    continue; // nothing of the atom changes: no need to fire it or recompute its mask
                }
                c.line("a" + atom + "." + AtomWriter.portMethod(e.port()) + "();");
                changed.add(atom);
            }
        }
        changed.forEach(atom -> c.line("e" + atom + " = " + type(atom).bridge() + ".mask(a" + atom + ");"));
        c.close();
        names.add(k.path() + ": [" + String.join(", ", parts) + "]");
        return c.toString();
    }

    /**
     * A connector's guard reads port data straight from the atoms; its up and down work on locals
     * ({@code v_p1_x}, {@code d_tmp}) loaded first and written back to the atoms' data after.
     */
    private final class ConnectorWriter implements ExprWriter.Mapper {
        private final ConnectorInstance k;
        private final boolean direct;
        private final PackageScope scope;

        ConnectorWriter(ConnectorInstance k, boolean direct) {
            this.k = k;
            this.direct = direct;
            this.scope = k.scope();
        }

        ExprWriter writer() {
            return new ExprWriter(new ExprTyper(scope, new Diagnostics()), LocalNames.connector(scope, k.type()), this);
        }

        /** @return {atom index, bound datum name} of port data {@code param.var} */
        private Object[] bound(String param, String var) {
            Endpoint e = k.endpoints().get(Interactions.index(k.type(), param));
            int atom = index(e.atom());
            AtomInstance a = atoms.get(atom);
            PortDecl port = a.type().port(e.port()).orElseThrow();
            List<String> params = a.scope().portType(port.portType()).orElseThrow().params().stream()
                    .map(eu.brain.iot.bip.model.Param::name).toList();
            return new Object[] {atom, port.boundData().get(params.indexOf(var))};
        }

        void locals(Code c, long interaction) {
            for (int p = 0; p < k.type().ports().size(); p++) {
                if ((interaction & (1L << p)) == 0) {
                    continue;
                }
                String param = k.type().ports().get(p).name();
                for (String var : portVars(param)) {
                    Object[] b = bound(param, var);
                    int atom = (Integer) b[0];
                    c.line(dataType(atom, (String) b[1]) + " v_" + param + "_" + var + " = " + dataRead(atom,
                            (String) b[1]) + ";");
                }
            }
            for (DataDecl d : k.type().data()) {
                Type t = scope.resolveType(d.type().name());
                c.line(JavaNames.javaType(t == null ? Type.ERROR : t, scope) + " d_" + d.name() + " = "
                        + JavaNames.defaultLiteral(t) + ";");
            }
        }

        void writeBack(Code c, long interaction, Set<String> written) {
            for (int p = 0; p < k.type().ports().size(); p++) {
                if ((interaction & (1L << p)) == 0 || !written.contains(k.type().ports().get(p).name())) {
                    continue;
                }
                String param = k.type().ports().get(p).name();
                for (String var : portVars(param)) {
                    Object[] b = bound(param, var);
                    int atom = (Integer) b[0];
                    if (atoms.get(atom).type().dataDecl((String) b[1]).isPresent()) {
                        c.line(type(atom).bridge() + ".set_" + b[1] + "(a" + atom + ", v_" + param + "_" + var + ");");
                    }
                }
            }
        }

        private List<String> portVars(String param) {
            Endpoint e = k.endpoints().get(Interactions.index(k.type(), param));
            AtomInstance a = atoms.get(index(e.atom()));
            PortDecl port = a.type().port(e.port()).orElseThrow();
            return a.scope().portType(port.portType()).orElseThrow().params().stream()
                    .map(eu.brain.iot.bip.model.Param::name).toList();
        }

        private String dataType(int atom, String name) {
            AtomInstance a = atoms.get(atom);
            String bipType = a.type().dataDecl(name).map(d -> d.type().name()).orElseGet(() -> a.type().params()
                    .stream().filter(p -> p.name().equals(name)).findFirst().orElseThrow().type().name());
            return type(atom).javaType(bipType);
        }

        @Override
        public String read(Symbol s, Expr.Var v) {
            if (s.kind() == Symbol.Kind.CONST) {
                Object value = ConstantFolder.fold(v, scope);
                return value instanceof String str ? JavaNames.literal(str) : String.valueOf(value);
            }
            if (v.qualifier() == null) {
                return "d_" + v.name();
            }
            if (direct) {
                Object[] b = bound(v.qualifier(), v.name());
                return dataRead((Integer) b[0], (String) b[1]);
            }
            return "v_" + v.qualifier() + "_" + v.name();
        }

        @Override
        public String write(Symbol s, Expr.Var v) {
            return v.qualifier() == null ? "d_" + v.name() : "v_" + v.qualifier() + "_" + v.name();
        }

        @Override
        public String call(ResolvedCall call, List<String> args) {
            return SimulationCode.callExpr(call, args, scope, "random", "simulation", builtins);
        }
    }
}
