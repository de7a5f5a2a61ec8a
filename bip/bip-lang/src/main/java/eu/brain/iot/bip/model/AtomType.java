package eu.brain.iot.bip.model;

import java.util.List;
import java.util.Optional;

/**
 * {@code atom type Name(params) data... port... place... initial... transitions... priorities... end}: a Petri net
 * (usually an automaton) extended with data.
 */
public record AtomType(Pos pos, List<Annotation> annotations, String name, List<Param> params, List<DataDecl> data,
        List<ClockDecl> clocks, List<PortDecl> ports, List<Place> places, InitialTransition initial,
        List<Transition> transitions, List<Priority> priorities, List<Invariant> invariants) implements Decl {

    public AtomType {
        annotations = List.copyOf(annotations);
        params = List.copyOf(params);
        data = List.copyOf(data);
        clocks = List.copyOf(clocks);
        ports = List.copyOf(ports);
        places = List.copyOf(places);
        transitions = List.copyOf(transitions);
        priorities = List.copyOf(priorities);
        invariants = List.copyOf(invariants);
    }

    @Override
    public String kind() {
        return "atom type";
    }

    public Optional<PortDecl> port(String portName) {
        return ports.stream().filter(p -> p.name().equals(portName)).findFirst();
    }

    public Optional<DataDecl> dataDecl(String dataName) {
        return data.stream().filter(d -> d.name().equals(dataName)).findFirst();
    }

    /** {@code place START, UNLOAD}: one record per place. */
    public record Place(Pos pos, String name) {
    }

    /** {@code clock x unit nanosecond} (timed BIP); {@code unit} may be null. */
    public record ClockDecl(Pos pos, String name, String unit) {
    }

    /** {@code initial to START do { ... }}; {@code action} may be null. */
    public record InitialTransition(Pos pos, List<String> to, Block action) {
        public InitialTransition {
            to = List.copyOf(to);
        }
    }

    /** How a timed transition may wait ({@code eager}, {@code lazy}, {@code delayable}); NONE when not said. */
    public enum Urgency {
        NONE, EAGER, LAZY, DELAYABLE
    }

    /**
     * {@code on port from A to B provided (guard) do { ... } [resume]}, or {@code internal from A to B ...} when
     * {@code port} is null. {@code guard} and {@code action} may be null. {@code resume} is BIP2's trailing
     * {@code resume}: the atom's execution goes on after the transition without waiting for an interaction, which
     * in a step semantics where every transition is atomic changes nothing (see bip/README, "Interpreter").
     */
    public record Transition(Pos pos, List<Annotation> annotations, String port, List<String> from, List<String> to,
            Expr guard, Urgency urgency, Block action, boolean resume) {
        public Transition {
            annotations = List.copyOf(annotations);
            from = List.copyOf(from);
            to = List.copyOf(to);
        }

        /** A transition without {@code resume}. */
        public Transition(Pos pos, List<Annotation> annotations, String port, List<String> from, List<String> to,
                Expr guard, Urgency urgency, Block action) {
            this(pos, annotations, port, from, to, guard, urgency, action, false);
        }

        public boolean internal() {
            return port == null;
        }
    }

    /** {@code priority name low < high provided (guard)} between ports ({@code *} for any); guard may be null. */
    public record Priority(Pos pos, String name, String low, String high, Expr guard) {
    }

    /**
     * {@code invariant name [at|from P1, P2] provided (condition)}: the condition must hold whenever one of the places
     * is marked ({@code places} empty: always). {@code at} and {@code from} say the same thing.
     */
    public record Invariant(Pos pos, String name, List<String> places, Expr condition) {
        public Invariant {
            places = List.copyOf(places);
        }

        /** @return whether the invariant applies to a marking */
        public boolean appliesTo(java.util.Collection<String> marking) {
            return places.isEmpty() || places.stream().anyMatch(marking::contains);
        }
    }
}
