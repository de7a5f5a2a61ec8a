package eu.brain.iot.bip.check;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.PortExpr;

/**
 * The interactions a connector type defines, as bit sets over its port parameters (bit i = parameter i), following
 * the BIP2 rule: an expression {@code e1 ... eN} defines the unions of interactions of its sub-expressions that
 * contain an interaction of a trigger sub-expression, or one of every sub-expression. Without a {@code define}
 * (the paper's Listing 6), the interactions are those named by the {@code on} clauses.
 */
public final class Interactions {

    /** Connectors with more ports than this are not enumerated (2^n interactions). */
    public static final int MAX_PORTS = 16;

    private Interactions() {
    }

    /** @return the defined interactions, in a stable order, or an empty list if there are too many ports */
    public static List<Long> of(ConnectorType type) {
        if (type.ports().size() > MAX_PORTS) {
            return List.of();
        }
        Set<Long> result = new LinkedHashSet<>();
        if (type.define() == null) {
            for (ConnectorType.Interaction i : type.interactions()) {
                long mask = mask(type, i.ports());
                if (mask != 0) {
                    result.add(mask);
                }
            }
        } else {
            result.addAll(expr(type, type.define()));
        }
        result.remove(0L);
        return List.copyOf(result);
    }

    private static Set<Long> expr(ConnectorType type, PortExpr e) {
        Set<Long> out = new LinkedHashSet<>();
        if (e instanceof PortExpr.Ref r) {
            int index = index(type, r.port());
            if (index >= 0) {
                out.add(1L << index);
            }
            return out;
        }
        PortExpr.Group g = (PortExpr.Group) e;
        List<Set<Long>> parts = new ArrayList<>();
        List<Boolean> triggers = new ArrayList<>();
        for (PortExpr item : g.items()) {
            parts.add(expr(type, item));
            triggers.add(item.trigger());
        }
        combine(parts, triggers, 0, 0L, false, true, out);
        out.remove(0L);
        return out;
    }

    private static void combine(List<Set<Long>> parts, List<Boolean> triggers, int i, long acc, boolean hasTrigger,
            boolean all, Set<Long> out) {
        if (i == parts.size()) {
            if (hasTrigger || all) {
                out.add(acc);
            }
            return;
        }
        combine(parts, triggers, i + 1, acc, hasTrigger, false, out);
        for (long choice : parts.get(i)) {
            combine(parts, triggers, i + 1, acc | choice, hasTrigger || triggers.get(i), all, out);
        }
    }

    public static int index(ConnectorType type, String port) {
        for (int i = 0; i < type.ports().size(); i++) {
            if (port.equals(type.ports().get(i).name())) {
                return i;
            }
        }
        return -1;
    }

    public static long mask(ConnectorType type, List<String> ports) {
        long mask = 0;
        for (String p : ports) {
            int i = index(type, p);
            if (i >= 0) {
                mask |= 1L << i;
            }
        }
        return mask;
    }

    /** @return the {@code on} clause for exactly this interaction, or null */
    public static ConnectorType.Interaction clause(ConnectorType type, long interaction) {
        for (ConnectorType.Interaction i : type.interactions()) {
            if (mask(type, i.ports()) == interaction) {
                return i;
            }
        }
        return null;
    }

    /** @return the parameter names of an interaction, in parameter order */
    public static List<String> names(ConnectorType type, long interaction) {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < type.ports().size(); i++) {
            if ((interaction & (1L << i)) != 0) {
                names.add(type.ports().get(i).name());
            }
        }
        return names;
    }
}
