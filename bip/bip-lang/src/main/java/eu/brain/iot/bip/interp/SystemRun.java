package eu.brain.iot.bip.interp;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.ToIntFunction;

import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.Interactions;
import eu.brain.iot.bip.check.LocalNames;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Symbol;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.system.SystemModel;
import eu.brain.iot.bip.system.SystemModel.AtomInstance;
import eu.brain.iot.bip.system.SystemModel.ConnectorInstance;
import eu.brain.iot.bip.system.SystemModel.Endpoint;

/**
 * A whole system run by the BIP semantics, one step at a time: internal transitions first; otherwise one of the
 * enabled candidates (transitions of ports that are not exported, and connector interactions whose ports are all
 * enabled and whose guard holds, after maximal progress within each connector) is chosen by the caller's scheduler
 * and executed (up, down, then each participant's transition). The basis of statistical model checking.
 * Extern ports take events of the environment ({@link #deliver}); invariants are observed, never enforced
 * ({@link #violatedInvariants}). Hierarchical connectors and compound priorities are not interpreted. Not
 * thread-safe.
 */
public final class SystemRun {

    /** One possible step: an atom's own transition ({@code connector} null) or an interaction. */
    public record Candidate(String connector, List<Endpoint> ports, long interaction) {
        @Override
        public String toString() {
            return (connector == null ? "" : connector + ": ") + ports.stream().map(e -> e.atom() + "." + e.port())
                    .toList();
        }
    }

    /** What became of an environment event given to an extern port ({@link #deliver}). */
    public enum Delivery {
        /** the port was enabled: its transition fired at once */
        FIRED,
        /** policy remember: kept; the port's transition becomes a candidate once it is enabled */
        REMEMBERED,
        /** policy ignore: dropped */
        IGNORED,
        /** policy error: dropped and recorded in {@link #errors()} */
        REFUSED
    }

    private final SystemModel system;
    /** Remembered events per "atom.port", oldest first: the values of the port's data in port type order. */
    private final Map<String, ArrayDeque<List<Object>>> pending = new HashMap<>();
    private final List<String> errors = new ArrayList<>();
    private static final ArrayDeque<List<Object>> EMPTY = new ArrayDeque<>();

    private final Map<String, AtomRun> atoms = new LinkedHashMap<>();
    private final Map<ConnectorType, Evaluator> evaluators = new HashMap<>();
    private final ExternFunctions externs;

    public SystemRun(SystemModel system, ExternFunctions externs) {
        this.system = system;
        this.externs = externs;
        for (AtomInstance a : system.atoms()) {
            atoms.put(a.path(), new AtomRun(a.type(), a.scope(), a.args(), externs));
        }
        for (ConnectorInstance k : system.connectors()) {
            if (k.endpoints().stream().anyMatch(e -> e.atom() == null || !atoms.containsKey(e.atom()))) {
                throw new IllegalArgumentException("connector " + k.path() + " is hierarchical: not interpreted");
            }
            evaluators.computeIfAbsent(k.type(), t -> new Evaluator(new ExprTyper(k.scope(), new Diagnostics()),
                    LocalNames.connector(k.scope(), t)));
        }
    }

    public Map<String, AtomRun> atoms() {
        return atoms;
    }

    public AtomRun atom(String path) {
        return atoms.get(path);
    }

    /** @return the enabled candidates, internal transitions excluded (they always go first) */
    public List<Candidate> candidates() {
        List<Candidate> list = new ArrayList<>();
        for (Map.Entry<String, AtomRun> a : atoms.entrySet()) {
            for (String port : a.getValue().enabledPorts()) {
                PortDecl decl = a.getValue().type().port(port).orElseThrow();
                boolean local = !decl.exported() && !decl.isExtern();
                if (local || decl.isExtern() && !pending.getOrDefault(a.getKey() + "." + port, EMPTY).isEmpty()) {
                    list.add(new Candidate(null, List.of(new Endpoint(a.getKey(), port, null)), 0));
                }
            }
        }
        for (ConnectorInstance k : system.connectors()) {
            List<Long> enabled = new ArrayList<>();
            for (long interaction : Interactions.of(k.type())) {
                if (ready(k, interaction) && guard(k, interaction)) {
                    enabled.add(interaction);
                }
            }
            for (long i : enabled) {
                boolean maximal = enabled.stream().noneMatch(j -> j != i && (j & i) == i);
                if (maximal) {
                    list.add(new Candidate(k.path(), participants(k, i), i));
                }
            }
        }
        return list;
    }

    private boolean ready(ConnectorInstance k, long interaction) {
        for (int p = 0; p < k.endpoints().size(); p++) {
            if ((interaction & (1L << p)) != 0) {
                Endpoint e = k.endpoints().get(p);
                if (!atoms.get(e.atom()).enabledPorts().contains(e.port())) {
                    return false;
                }
            }
        }
        return true;
    }

    private static List<Endpoint> participants(ConnectorInstance k, long interaction) {
        List<Endpoint> list = new ArrayList<>();
        for (int p = 0; p < k.endpoints().size(); p++) {
            if ((interaction & (1L << p)) != 0) {
                list.add(k.endpoints().get(p));
            }
        }
        return list;
    }

    private boolean guard(ConnectorInstance k, long interaction) {
        ConnectorType.Interaction clause = Interactions.clause(k.type(), interaction);
        return clause == null || evaluators.get(k.type()).test(clause.guard(), new ConnectorEnv(k));
    }

    /**
     * Takes one step: an internal transition if any atom has one enabled, else the candidate the scheduler picks
     * (it gets the candidates and returns an index).
     *
     * @return what was executed ("internal A" or the candidate), or empty at a deadlock
     */
    public Optional<String> step(ToIntFunction<List<Candidate>> scheduler) {
        for (Map.Entry<String, AtomRun> a : atoms.entrySet()) {
            if (a.getValue().internalStep()) {
                return Optional.of("internal " + a.getKey());
            }
        }
        List<Candidate> candidates = candidates();
        if (candidates.isEmpty()) {
            return Optional.empty();
        }
        Candidate chosen = candidates.get(scheduler.applyAsInt(candidates));
        execute(chosen);
        return Optional.of(chosen.toString());
    }

    /** Executes a candidate: the interaction's up and down transfers, then each participant's transition. */
    public void execute(Candidate c) {
        if (c.connector() != null) {
            ConnectorInstance k = system.connectors().stream().filter(x -> x.path().equals(c.connector())).findFirst()
                    .orElseThrow();
            ConnectorType.Interaction clause = Interactions.clause(k.type(), c.interaction());
            if (clause != null) {
                ConnectorEnv env = new ConnectorEnv(k);
                Evaluator evaluator = evaluators.get(k.type());
                if (clause.up() != null) {
                    evaluator.run(clause.up().stmts(), env);
                }
                if (clause.down() != null) {
                    evaluator.run(clause.down().stmts(), env);
                }
            }
        }
        if (c.connector() == null) {
            Endpoint e = c.ports().get(0);
            ArrayDeque<List<Object>> events = pending.get(e.atom() + "." + e.port());
            if (events != null && !events.isEmpty()) {
                setPortData(atoms.get(e.atom()), e.port(), events.poll());
            }
        }
        for (Endpoint e : c.ports()) {
            atoms.get(e.atom()).fire(e.port());
        }
    }

    /**
     * An event of the environment for an extern port (BIP2's {@code extern port}): when the port is enabled (after
     * the atom's priorities) its data takes the event's values and its transition fires at once; otherwise the
     * port's policy decides ({@code remember}, the default: kept until the port is enabled, then a candidate like
     * any other; {@code ignore}: dropped; {@code error}: dropped and recorded in {@link #errors()}).
     *
     * @param values the values of the port's data, in its port type's parameter order
     */
    public Delivery deliver(String atom, String port, List<Object> values) {
        AtomRun run = atoms.get(atom);
        if (run == null) {
            throw new IllegalArgumentException("no atom " + atom + " in the system; atoms: " + atoms.keySet());
        }
        PortDecl decl = run.type().port(port).filter(PortDecl::isExtern).orElseThrow(() -> new IllegalArgumentException(
                "atom " + atom + " has no extern port " + port));
        if (run.enabledPorts().contains(port)) {
            setPortData(run, port, values);
            run.fire(port);
            return Delivery.FIRED;
        }
        return switch (decl.extern().policy().effective()) {
            case IGNORE -> Delivery.IGNORED;
            case ERROR -> {
                errors.add(atom + "." + port + ": an event arrived when the port could not take it (policy error)");
                yield Delivery.REFUSED;
            }
            default -> {
                pending.computeIfAbsent(atom + "." + port, k -> new ArrayDeque<>()).add(List.copyOf(values));
                yield Delivery.REMEMBERED;
            }
        };
    }

    /**
     * @return the enabled ports (after the atoms' priorities) of the open system's environment: exported ports that
     *         no connector binds and that are not extern ports. The statistical model checker never fires them (a
     *         closed system models its environment in BIP); a check of an open system does, with
     *         {@link #fromEnvironment}.
     */
    public List<Candidate> environmentCandidates() {
        List<Candidate> list = new ArrayList<>();
        for (Map.Entry<String, AtomRun> a : atoms.entrySet()) {
            for (String port : a.getValue().enabledPorts()) {
                if (environmentPort(a.getKey(), port)) {
                    list.add(new Candidate(null, List.of(new Endpoint(a.getKey(), port, null)), 0));
                }
            }
        }
        return list;
    }

    /** @return whether {@code atom.port} is the environment's (exported, bound by no connector, not extern) */
    public boolean environmentPort(String atom, String port) {
        PortDecl decl = atoms.get(atom).type().port(port).orElseThrow();
        return decl.exported() && !decl.isExtern() && system.connectors().stream().flatMap(k -> k.endpoints().stream())
                .noneMatch(e -> atom.equals(e.atom()) && port.equals(e.port()));
    }

    /**
     * The environment fires one of its ports ({@link #environmentCandidates}) with its data: the port's data take
     * the values, then its transition fires. An event the port cannot take now is no step (the deployed behaviour
     * ignores it).
     *
     * @param values the values of the port's data, in its port type's parameter order
     * @return whether the port was enabled and fired
     */
    public boolean fromEnvironment(String atom, String port, List<Object> values) {
        AtomRun run = atoms.get(atom);
        if (run == null || !environmentPort(atom, port)) {
            throw new IllegalArgumentException(atom + "." + port + " is not a port of the environment; environment "
                    + "ports are exported and bound by no connector");
        }
        if (!run.enabledPorts().contains(port)) {
            return false;
        }
        setPortData(run, port, values);
        run.fire(port);
        return true;
    }

    /** @return the run's errors so far (events refused by extern ports of policy error), oldest first */
    public List<String> errors() {
        return List.copyOf(errors);
    }

    /** @return per atom, the invariants that do not hold now (atoms whose invariants all hold are left out) */
    public Map<String, List<String>> violatedInvariants() {
        Map<String, List<String>> violated = new LinkedHashMap<>();
        atoms.forEach((path, run) -> {
            List<String> names = run.violatedInvariants();
            if (!names.isEmpty()) {
                violated.put(path, names);
            }
        });
        return violated;
    }

    private static void setPortData(AtomRun run, String port, List<Object> values) {
        List<String> data = run.type().port(port).orElseThrow().boundData();
        for (int i = 0; i < data.size() && i < values.size(); i++) {
            run.set(data.get(i), values.get(i));
        }
    }

    /** Connector code reads and writes its ports' data straight in the atoms, and its own data locally. */
    private final class ConnectorEnv implements Env {
        private final ConnectorInstance k;
        private final Map<String, Object> data = new HashMap<>();

        ConnectorEnv(ConnectorInstance k) {
            this.k = k;
            for (DataDecl d : k.type().data()) {
                Type t = k.scope().resolveType(d.type().name());
                data.put(d.name(), Ops.defaultValue(t == null ? Type.ERROR : t));
            }
        }

        private String atomData(String qualified) {
            int dot = qualified.indexOf('.');
            String param = qualified.substring(0, dot);
            String var = qualified.substring(dot + 1);
            Endpoint e = k.endpoints().get(Interactions.index(k.type(), param));
            AtomRun atom = atoms.get(e.atom());
            List<String> params = atom.portParams(e.port());
            PortDecl port = atom.type().port(e.port()).orElseThrow();
            return e.atom() + "\u0000" + port.boundData().get(params.indexOf(var));
        }

        @Override
        public Object get(Symbol symbol, String qualifiedName) {
            if (symbol.kind() == Symbol.Kind.PORT_DATA) {
                String[] at = atomData(qualifiedName).split("\u0000");
                return atoms.get(at[0]).get(at[1]);
            }
            if (symbol.kind() == Symbol.Kind.CONST) {
                return eu.brain.iot.bip.check.ConstantFolder.fold(new eu.brain.iot.bip.model.Expr.Var(
                        eu.brain.iot.bip.model.Pos.NONE, null, qualifiedName), k.scope());
            }
            return data.get(qualifiedName);
        }

        @Override
        public void set(Symbol symbol, String qualifiedName, Object value) {
            if (symbol.kind() == Symbol.Kind.PORT_DATA) {
                String[] at = atomData(qualifiedName).split("\u0000");
                atoms.get(at[0]).set(at[1], value);
            } else {
                data.put(qualifiedName, value);
            }
        }

        @Override
        public Object call(ResolvedCall call, Object[] args) {
            return externs.call(call.name(), call.params().stream().map(Type::toString).toList(),
                    call.result().toString(), args);
        }
    }
}
