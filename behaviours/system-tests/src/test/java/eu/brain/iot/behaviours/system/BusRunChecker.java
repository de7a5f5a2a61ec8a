package eu.brain.iot.behaviours.system;

import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.behaviours.events.TransitionFired;
import eu.brain.iot.bip.interp.AtomRun;
import eu.brain.iot.bip.interp.ExternFunctions;
import eu.brain.iot.bip.interp.SystemRun;
import eu.brain.iot.bip.system.SystemModel;
import eu.brain.iot.bip.system.SystemModel.ConnectorInstance;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * Checks that a run of the generated behaviours on a bus (the log of a {@link RecordingBus}, with {@code trace=true}
 * so every transition is a {@code TransitionFired}) is a possible run of the SMC semantics (bip/README, "Semantics
 * of a trace"), replayed by the interpreter ({@link SystemRun}) on the deployed system, the environment's events
 * being what they are: the environment firing an exported port no connector binds.
 * <p>
 * The log is cut into SMC steps: an internal transition, a private port, an environment port (with the event's
 * data), or an interaction: the initiator's transition (a broadcast's trigger, a rendezvous' coordinator) together
 * with the transitions its connector event caused in the other participants. The steps are taken in the bus's order,
 * each atom's in the order it took them ({@link #check}). Each step must be, in the state the previous ones reached,
 * one of the SMC's candidates: an atom's internal step,
 * an enabled private port, an enabled environment port, or a connector interaction that is enabled and maximal
 * ({@link SystemRun#candidates}: the atoms' priorities applied); each transition must go between the places the bus
 * reported. Fails at the first step that is not, saying what the bus did and what the SMC could do.
 * Not thread-safe.
 */
final class BusRunChecker {

    private enum Kind { INTERNAL, PORT, ENVIRONMENT, INTERACTION }

    /** One SMC step: its transitions as the bus reported them, in log order. */
    private static final class Step {
        final Kind kind;
        final String connector;
        final int logIndex;
        /** Where each transition is in the log. */
        final List<Integer> indices = new ArrayList<>();
        final List<TransitionFired> transitions = new ArrayList<>();
        final List<Object> values;

        Step(Kind kind, String connector, int logIndex, List<Object> values) {
            this.kind = kind;
            this.connector = connector;
            this.logIndex = logIndex;
            this.values = values;
        }

        Set<String> ports() {
            Set<String> ports = new HashSet<>();
            transitions.forEach(t -> ports.add(t.component + "." + t.port));
            return ports;
        }

        @Override
        public String toString() {
            return kind.name().toLowerCase() + (connector == null ? " " : " " + connector + " ") + ports()
                    + (values == null ? "" : " " + values) + " (bus log #" + logIndex + ")";
        }
    }

    private final SystemModel system;
    private final SystemRun run;
    private int steps;
    private int reordered;

    /** @param externs the deployed extern implementations (their public methods are called by name) */
    BusRunChecker(SystemModel system, List<Object> externs) {
        this.system = system;
        this.run = new SystemRun(system, calling(externs));
    }

    /** @return the SMC steps checked so far */
    int steps() {
        return steps;
    }

    SystemRun run() {
        return run;
    }

    /**
     * Checks the whole log (the replay starts from the system's initial state): takes its steps in the bus's order
     * (by the initiator's place in the log), keeping each atom's transitions in the order the atom took them: a step
     * whose participant has an earlier step of its own still to take (a broadcast's receiver that changed state
     * before the trigger's event reached it, on an interleaved bus) is taken right after that earlier step, which is
     * pulled forward. That is the same run (an atom's steps commute with the other atoms'), and each step must be an
     * SMC candidate where it is taken.
     *
     * @throws AssertionError at the first step that is not a candidate, saying why and what the candidates were
     */
    void check(List<RecordingBus.Published> log) {
        List<Step> pending = cut(log);
        Map<String, java.util.ArrayDeque<Step>> perAtom = new LinkedHashMap<>();
        List<Object[]> placed = new ArrayList<>();
        for (Step s : pending) {
            for (int t = 0; t < s.transitions.size(); t++) {
                placed.add(new Object[] {s.indices.get(t), s.transitions.get(t).component, s});
            }
        }
        placed.sort(java.util.Comparator.comparingInt(x -> (Integer) x[0]));
        for (Object[] x : placed) {
            perAtom.computeIfAbsent((String) x[1], k -> new java.util.ArrayDeque<>()).add((Step) x[2]);
        }
        Set<Step> done = java.util.Collections.newSetFromMap(new IdentityHashMap<>());
        for (Step s : pending) {
            if (!done.contains(s)) {
                take(s, perAtom, done, new ArrayList<>());
            }
        }
    }

    /** Takes {@code s} after the earlier steps of its participants. */
    private void take(Step s, Map<String, java.util.ArrayDeque<Step>> perAtom, Set<Step> done, List<Step> waiting) {
        if (waiting.contains(s)) {
            throw diverges(s, "its participants' steps wait for each other: " + waiting);
        }
        waiting.add(s);
        for (TransitionFired t : s.transitions) {
            while (perAtom.get(t.component).peek() != s) {
                reordered++;
                take(perAtom.get(t.component).peek(), perAtom, done, waiting);
            }
        }
        waiting.remove(waiting.size() - 1);
        replay(s);
        s.transitions.forEach(t -> perAtom.get(t.component).poll());
        done.add(s);
        steps++;
    }

    /** @return the steps taken before a step that precedes them in the bus's order */
    int reordered() {
        return reordered;
    }

    private List<Step> cut(List<RecordingBus.Published> log) {
        List<Step> steps = new ArrayList<>();
        Map<String, Step> awaitingEvent = new LinkedHashMap<>();
        Map<BrainIoTEvent, Step> byEvent = new IdentityHashMap<>();
        for (int i = 0; i < log.size(); i++) {
            BrainIoTEvent e = log.get(i).event();
            BrainIoTEvent cause = log.get(i).cause();
            if (e instanceof TransitionFired t) {
                if (t.port.equals("initial")) {
                    continue;
                }
                Optional<ConnectorInstance> k = connectorOf(t.component, t.port);
                Step step;
                if (t.port.equals("internal")) {
                    step = new Step(Kind.INTERNAL, null, i, null);
                } else if (k.isEmpty() && run.environmentPort(t.component, t.port)) {
                    step = new Step(Kind.ENVIRONMENT, null, i, portValues(cause, t.component, t.port));
                } else if (k.isEmpty()) {
                    step = new Step(Kind.PORT, null, i, null);
                } else if (cause != null && k.get().path().equals(field(cause, "connector"))
                        && byEvent.containsKey(cause)) {
                    byEvent.get(cause).transitions.add(t); // a participant answering the initiator's event
                    byEvent.get(cause).indices.add(i);
                    continue;
                } else {
                    step = new Step(Kind.INTERACTION, k.get().path(), i, null);
                    if (awaitingEvent.put(k.get().path(), step) != null) {
                        throw new AssertionError("bus log #" + i + ": two initiations of " + k.get().path()
                                + " without its event between them");
                    }
                }
                step.transitions.add(t);
                step.indices.add(i);
                steps.add(step);
            } else if (hasField(e, "initiator")) {
                Step step = awaitingEvent.remove((String) field(e, "connector"));
                if (step == null) {
                    throw new AssertionError("bus log #" + i + ": connector event " + e.getClass().getSimpleName()
                            + " of " + field(e, "connector") + " published by no initiating transition");
                }
                byEvent.put(e, step);
            }
        }
        return steps;
    }

    private void replay(Step s) {
        Map<String, Set<String>> before = new LinkedHashMap<>();
        s.transitions.forEach(t -> before.put(t.component, run.atom(t.component).marking()));
        TransitionFired first = s.transitions.get(0);
        switch (s.kind) {
            case INTERNAL -> {
                AtomRun a = run.atom(first.component);
                if (!a.internalEnabled()) {
                    throw diverges(s, "no internal transition of " + first.component + " is enabled");
                }
                a.internalStep();
            }
            case PORT -> {
                SystemRun.Candidate c = candidate(null, s.ports())
                        .orElseThrow(() -> diverges(s, "port " + first.port + " is not enabled"));
                run.execute(c);
            }
            case ENVIRONMENT -> {
                if (!run.fromEnvironment(first.component, first.port, s.values)) {
                    throw diverges(s, "the environment's port " + first.port + " is not enabled");
                }
            }
            case INTERACTION -> {
                Optional<SystemRun.Candidate> c = candidate(s.connector, s.ports());
                if (c.isEmpty()) {
                    c = smallerThanMaximal(s.connector, s.ports());
                    c.ifPresent(x -> smaller++);
                }
                run.execute(c.orElseThrow(() -> diverges(s, "this interaction is not enabled and maximal")));
            }
            default -> throw new IllegalStateException();
        }
        for (TransitionFired t : s.transitions) {
            Set<String> after = run.atom(t.component).marking();
            if (!before.get(t.component).equals(Set.copyOf(t.from)) || !after.equals(Set.copyOf(t.to))) {
                throw diverges(s, t.component + "." + t.port + " went " + t.from + " -> " + t.to + " on the bus, "
                        + before.get(t.component) + " -> " + after + " in the SMC semantics");
            }
        }
    }

    /**
     * The bus's coordinator fires the largest interaction whose offers it holds; with Warehouse.bip's subset
     * rendezvous ({@code define p4 (p1' p2' p3')}) an offer still in flight makes it fire a smaller one than the
     * SMC's maximal one. Accepted (and counted, {@link #smaller()}) for a coordinated connector (no single-port
     * interaction) when it is part of an enabled maximal interaction of the same connector: every port in it is
     * enabled, so it is enabled in BIP, only not maximal. Never for a broadcast (a ready receiver must join).
     */
    private int smaller;

    private Optional<SystemRun.Candidate> smallerThanMaximal(String connector, Set<String> ports) {
        boolean coordinated = system.connectors().stream().filter(k -> k.path().equals(connector))
                .anyMatch(k -> eu.brain.iot.bip.check.Interactions.of(k.type()).stream()
                        .noneMatch(i -> Long.bitCount(i) == 1));
        if (!coordinated) {
            return Optional.empty(); // a broadcast's receiver that is ready joins: missing it is a divergence
        }
        for (SystemRun.Candidate max : run.candidates()) {
            if (!java.util.Objects.equals(max.connector(), connector)) {
                continue;
            }
            List<SystemModel.Endpoint> kept = new ArrayList<>();
            long mask = 0;
            int i = 0;
            for (int bit = 0; bit < 64 && i < max.ports().size(); bit++) {
                if ((max.interaction() & (1L << bit)) == 0) {
                    continue;
                }
                SystemModel.Endpoint e = max.ports().get(i++);
                if (ports.contains(e.atom() + "." + e.port())) {
                    kept.add(e);
                    mask |= 1L << bit;
                }
            }
            if (kept.size() == ports.size()) {
                return Optional.of(new SystemRun.Candidate(connector, kept, mask));
            }
        }
        return Optional.empty();
    }

    /** @return how many interactions the bus fired smaller than the SMC's maximal one (an offer in flight) */
    int smaller() {
        return smaller;
    }

    private Optional<SystemRun.Candidate> candidate(String connector, Set<String> ports) {
        return run.candidates().stream().filter(c -> java.util.Objects.equals(c.connector(), connector))
                .filter(c -> ports.equals(new HashSet<>(c.ports().stream().map(e -> e.atom() + "." + e.port())
                        .toList())))
                .findFirst();
    }

    private AssertionError diverges(Step s, String why) {
        List<String> internal = new ArrayList<>();
        run.atoms().forEach((path, a) -> {
            if (a.internalEnabled()) {
                internal.add("internal " + path);
            }
        });
        StringBuilder state = new StringBuilder();
        run.atoms().forEach((path, a) -> state.append("\n  ").append(path).append(' ').append(a.marking()).append(' ')
                .append(a.values()));
        return new AssertionError("SMC step " + steps + ": the bus took " + s + ", which the SMC semantics cannot: "
                + why + ".\nSMC candidates: " + internal + " " + run.candidates() + " environment "
                + run.environmentCandidates() + "\nstate:" + state);
    }

    private Optional<ConnectorInstance> connectorOf(String atom, String port) {
        return system.connectors().stream().filter(k -> k.endpoints().stream()
                .anyMatch(e -> atom.equals(e.atom()) && port.equals(e.port()))).findFirst();
    }

    /** The data of an environment event for {@code atom.port}, in its port type's parameter order. */
    private List<Object> portValues(BrainIoTEvent event, String atom, String port) {
        if (event == null || !atom.equals(field(event, "component"))) {
            throw new AssertionError(atom + "." + port + " fired from the environment, but not by an event for it: "
                    + event);
        }
        List<Object> values = new ArrayList<>();
        for (String param : run.atom(atom).portParams(port)) {
            values.add(field(event, param));
        }
        return values;
    }

    private static boolean hasField(Object o, String name) {
        try {
            o.getClass().getField(name);
            return true;
        } catch (NoSuchFieldException e) {
            return false;
        }
    }

    private static Object field(Object o, String name) {
        try {
            Field f = o.getClass().getField(name);
            return f.get(o);
        } catch (ReflectiveOperationException e) {
            return null;
        }
    }

    /** The interpreter's extern functions: the deployed implementations' methods, by name and arity. */
    private static ExternFunctions calling(List<Object> externs) {
        return (name, types, result, args) -> {
            for (Object impl : externs) {
                for (Method m : impl.getClass().getMethods()) {
                    if (m.getName().equals(name) && m.getParameterCount() == args.length) {
                        try {
                            return m.invoke(impl, args);
                        } catch (ReflectiveOperationException e) {
                            throw new IllegalStateException("extern " + name + " failed: " + e, e);
                        }
                    }
                }
            }
            throw new IllegalStateException("no deployed implementation of extern function " + name);
        };
    }
}
