package eu.brain.iot.bip.interp;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.LocalNames;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Symbol;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.AtomType.Transition;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.model.PortType;

/**
 * One atom instance run by direct interpretation of its type: the marking, the data, and the same operations the
 * generated atom class has ({@link #fire}, {@link #internalStep}, {@link #enabledPorts}), with the same choices
 * (first enabled transition in declaration order). The statistical model checker builds on it. Not thread-safe.
 */
public final class AtomRun {

    private final AtomType type;
    private final PackageScope scope;
    private final Evaluator evaluator;
    private final ExternFunctions externs;
    private final Set<String> marking = new LinkedHashSet<>();
    private final Map<String, Object> values = new LinkedHashMap<>();
    private final Map<String, Type> types = new HashMap<>();
    private final Env env = new AtomEnv();
    /** Folded constants by name: a constant's value never changes. */
    private final Map<String, Object> constants = new HashMap<>();

    /** Creates the instance and runs its initial transition. */
    public AtomRun(AtomType type, PackageScope scope, List<Object> args, ExternFunctions externs) {
        this.type = type;
        this.scope = scope;
        this.externs = externs;
        ExprTyper typer = new ExprTyper(scope, new Diagnostics());
        this.evaluator = new Evaluator(typer, LocalNames.atom(scope, type));
        for (int i = 0; i < type.params().size(); i++) {
            Param p = type.params().get(i);
            Type t = typeOf(p.type().name());
            types.put(p.name(), t);
            values.put(p.name(), Ops.coerce(i < args.size() ? args.get(i) : Ops.defaultValue(t), t));
        }
        for (DataDecl d : type.data()) {
            Type t = typeOf(d.type().name());
            types.put(d.name(), t);
            values.put(d.name(), d.init() == null ? Ops.defaultValue(t) : Ops.coerce(evaluator.eval(d.init(), env), t));
        }
        type.clocks().forEach(c -> {
            types.put(c.name(), Type.FLOAT);
            values.put(c.name(), 0.0);
        });
        if (type.initial() != null) {
            marking.addAll(type.initial().to());
            if (type.initial().action() != null) {
                evaluator.run(type.initial().action().stmts(), env);
            }
        }
    }

    private Type typeOf(String name) {
        Type t = scope.resolveType(name);
        return t == null ? Type.ERROR : t;
    }

    public AtomType type() {
        return type;
    }

    /** @return the marked places, in the order they were marked */
    public Set<String> marking() {
        return Set.copyOf(marking);
    }

    /** @return parameters and data by name (a copy) */
    public Map<String, Object> values() {
        return new LinkedHashMap<>(values);
    }

    public Object get(String name) {
        return values.get(name);
    }

    /** Sets a datum (as a connector's down transfer does), converting int to float where declared. */
    public void set(String name, Object value) {
        values.put(name, Ops.coerce(value, types.getOrDefault(name, Type.ERROR)));
    }

    /** @return the values of the data bound to a port, in its port type's parameter order */
    public List<Object> portValues(String port) {
        List<Object> list = new ArrayList<>();
        type.port(port).ifPresent(p -> p.boundData().forEach(d -> list.add(values.get(d))));
        return list;
    }

    /** @return the port's data names in port type order, paired with the port type's parameter names */
    public List<String> portParams(String port) {
        PortDecl p = type.port(port).orElseThrow();
        PortType pt = scope.portType(p.portType()).orElseThrow();
        return pt.params().stream().map(Param::name).toList();
    }

    private boolean enabled(Transition t) {
        return marking.containsAll(t.from()) && evaluator.test(t.guard(), env);
    }

    public boolean isEnabled(String port) {
        return type.transitions().stream().anyMatch(t -> port.equals(t.port()) && enabled(t));
    }

    /** @return enabled ports no enabled port has priority over, in declaration order */
    public List<String> enabledPorts() {
        List<String> ports = type.ports().stream().map(PortDecl::name).toList();
        List<String> enabled = ports.stream().filter(this::isEnabled).toList();
        if (type.priorities().isEmpty()) {
            return enabled;
        }
        int n = ports.size();
        boolean[][] lower = new boolean[n][n];
        for (AtomType.Priority p : type.priorities()) {
            if (evaluator.test(p.guard(), env)) {
                int low = p.low().equals("*") ? -1 : ports.indexOf(p.low());
                int high = p.high().equals("*") ? -1 : ports.indexOf(p.high());
                for (int l = 0; l < n; l++) {
                    for (int h = 0; h < n; h++) {
                        if ((low < 0 || l == low) && (high < 0 || h == high) && l != h) {
                            lower[l][h] = true;
                        }
                    }
                }
            }
        }
        for (int k = 0; k < n; k++) {
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    if (lower[i][k] && lower[k][j]) {
                        lower[i][j] = true;
                    }
                }
            }
        }
        List<String> maximal = new ArrayList<>();
        for (String p : enabled) {
            boolean dominated = enabled.stream().anyMatch(q -> !q.equals(p)
                    && lower[ports.indexOf(p)][ports.indexOf(q)]);
            if (!dominated) {
                maximal.add(p);
            }
        }
        return maximal;
    }

    /** Fires the first enabled transition labelled by the port; @return whether one fired */
    public boolean fire(String port) {
        for (Transition t : type.transitions()) {
            if (port.equals(t.port()) && enabled(t)) {
                execute(t);
                return true;
            }
        }
        return false;
    }

    /** Fires the first enabled internal transition; @return whether one fired */
    public boolean internalStep() {
        for (Transition t : type.transitions()) {
            if (t.internal() && enabled(t)) {
                execute(t);
                return true;
            }
        }
        return false;
    }

    /**
     * @return the invariants that do not hold in the current state (one of their places marked, or no place given,
     *         and the condition false), in declaration order; empty in a correct run
     */
    public List<String> violatedInvariants() {
        List<String> violated = new ArrayList<>();
        for (AtomType.Invariant i : type.invariants()) {
            if (i.appliesTo(marking) && !evaluator.test(i.condition(), env)) {
                violated.add(i.name());
            }
        }
        return violated;
    }

    /** @return whether an internal transition is enabled (the statistical model checker offers it as a step) */
    public boolean internalEnabled() {
        return type.transitions().stream().anyMatch(t -> t.internal() && enabled(t));
    }

    private void execute(Transition t) {
        t.from().stream().filter(p -> !t.to().contains(p)).forEach(marking::remove);
        marking.addAll(t.to());
        if (t.action() != null) {
            evaluator.run(t.action().stmts(), env);
        }
    }

    private final class AtomEnv implements Env {
        @Override
        public Object get(Symbol symbol, String qualifiedName) {
            if (symbol.kind() == Symbol.Kind.CONST) {
                return constants.computeIfAbsent(qualifiedName, n -> eu.brain.iot.bip.check.ConstantFolder.fold(
                        new eu.brain.iot.bip.model.Expr.Var(eu.brain.iot.bip.model.Pos.NONE, null, n), scope));
            }
            return values.get(symbol.name());
        }

        @Override
        public void set(Symbol symbol, String qualifiedName, Object value) {
            values.put(symbol.name(), value);
        }

        @Override
        public Object call(ResolvedCall call, Object[] args) {
            List<String> paramTypes = call.params().stream().map(Type::toString).toList();
            return externs.call(call.name(), paramTypes, call.result().toString(), args);
        }
    }
}
