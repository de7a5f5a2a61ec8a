package eu.brain.iot.bip.model;

import java.util.List;

/**
 * {@code [export] port PortType name(data, ...)} in an atom, or the exported port of a connector type (there the
 * arguments name connector data). {@code mergedAs} is the name of a merged export ({@code ... as exp}), else null.
 * {@code extern} is set for BIP2's {@code extern port PortType name(data) as "event" [policy]}, a port fired by
 * events of the environment rather than by connectors; null for an ordinary port.
 */
public record PortDecl(Pos pos, List<Annotation> annotations, boolean exported, String portType, String name,
        List<String> boundData, String mergedAs, Extern extern) {

    public PortDecl {
        annotations = List.copyOf(annotations);
        boundData = List.copyOf(boundData);
    }

    /** An ordinary (not extern) port. */
    public PortDecl(Pos pos, List<Annotation> annotations, boolean exported, String portType, String name,
            List<String> boundData, String mergedAs) {
        this(pos, annotations, exported, portType, name, boundData, mergedAs, null);
    }

    public boolean isExtern() {
        return extern != null;
    }

    /**
     * What an event arriving when the port cannot take it becomes: kept until the port is enabled
     * ({@code REMEMBER}), dropped ({@code IGNORE}) or an error of the run ({@code ERROR}). {@code NONE} when the
     * model does not say; the tools then use {@code REMEMBER}.
     */
    public enum Policy {
        NONE, REMEMBER, IGNORE, ERROR;

        /** @return the policy the tools apply ({@code NONE} means {@code REMEMBER}) */
        public Policy effective() {
            return this == NONE ? REMEMBER : this;
        }
    }

    /** {@code as "event"} (the name the environment knows the port by; may be null) and the policy. */
    public record Extern(String event, Policy policy) {
    }
}
