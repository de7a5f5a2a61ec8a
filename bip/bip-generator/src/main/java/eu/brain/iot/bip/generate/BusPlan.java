package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.Interactions;
import eu.brain.iot.bip.check.LocalNames;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Annotation;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.system.SystemModel;
import eu.brain.iot.bip.system.SystemModel.AtomInstance;
import eu.brain.iot.bip.system.SystemModel.ConnectorInstance;
import eu.brain.iot.bip.system.SystemModel.Endpoint;

/**
 * How the system's connectors are realised on the event bus (see bip/README.md, "Connectors on the bus"):
 * <ul>
 * <li>a connector whose interactions include single ports (triggers, as in {@code define s' r1 r2}) is a
 * <b>broadcast</b>: a trigger fires alone and publishes the connector's event; each synchron receiver that is ready
 * when the event arrives takes part;</li>
 * <li>otherwise, when one port takes part in every interaction (a rendezvous such as {@code define p1 p2 p3 p4}),
 * that port's component <b>coordinates</b>: the others publish an offer when ready and wait; the coordinator fires the
 * largest interaction whose ports have all offered (round robin among equals), runs guard, up and down, and
 * publishes the connector's event with everyone's data;</li>
 * <li>other shapes (and hierarchical connectors) cannot be realised and are reported.</li>
 * </ul>
 */
final class BusPlan {

    enum Mode {
        BROADCAST, COORDINATED
    }

    enum Role {
        /** not exported: fires by itself when enabled */
        LOCAL,
        /** exported, bound to no connector: fired by its own event type from the environment */
        EXTERNAL,
        /** bound to a connector: each instance has one of the roles below (or none, if unconnected) */
        BOUND,
        INITIATOR, RECEIVER, PARTICIPANT, COORDINATOR
    }

    /** How one connector type works on the bus. */
    record ConnectorPlan(ConnectorType type, Mode mode, long initiators, int coordinator, List<Long> interactions) {
    }

    /**
     * How one port of an atom type works; per instance index, its connector instance name, parameter and role
     * (instances of one type may play different parts, e.g. both ends of a rendezvous).
     */
    record PortPlan(PortDecl port, Role role, ConnectorType connector, String[] connectorByInstance,
            int[] paramByInstance, Role[] roleByInstance) {

        /** @return whether some instance plays this role */
        boolean has(Role r) {
            return java.util.Arrays.asList(roleByInstance).contains(r);
        }
    }

    private final SystemModel system;
    private final Diagnostics diagnostics;
    private final Map<ConnectorType, ConnectorPlan> connectors = new LinkedHashMap<>();

    BusPlan(SystemModel system, Diagnostics diagnostics) {
        this.system = system;
        this.diagnostics = diagnostics;
        for (ConnectorInstance k : system.connectors()) {
            for (Endpoint e : k.endpoints()) {
                if (e.atom() == null) {
                    diagnostics.error(k.pos(), "connector " + k.path() + " is hierarchical (it binds the exported port of "
                            + "connector " + e.connector() + "); hierarchical connectors cannot be realised on the event bus");
                } else if (system.atom(e.atom()).isEmpty()) {
                    diagnostics.error(k.pos(), "connector " + k.path() + " binds " + e.atom() + "." + e.port()
                            + ", which is not an atom port of the system");
                }
            }
            connectors.computeIfAbsent(k.type(), t -> plan(t, k));
        }
    }

    SystemModel system() {
        return system;
    }

    List<ConnectorPlan> connectorPlans() {
        return connectors.values().stream().filter(p -> p != null).toList();
    }

    ConnectorPlan plan(ConnectorType type) {
        return connectors.get(type);
    }

    private ConnectorPlan plan(ConnectorType type, ConnectorInstance where) {
        List<Long> interactions = Interactions.of(type);
        if (interactions.isEmpty()) {
            diagnostics.error(where.pos(), "connector type " + type.name() + " defines no interaction that can be "
                    + "realised on the event bus");
            return null;
        }
        long initiators = 0;
        for (long i : interactions) {
            if (Long.bitCount(i) == 1) {
                initiators |= i;
            }
        }
        if (initiators != 0) {
            return new ConnectorPlan(type, Mode.BROADCAST, initiators, -1, interactions);
        }
        long common = -1L;
        for (long i : interactions) {
            common &= i;
        }
        if (common == 0) {
            diagnostics.error(where.pos(), "connector type " + type.name() + " cannot be realised on the event bus: no "
                    + "port can fire alone (a trigger, marked ') and no port takes part in every interaction "
                    + "(a coordinator); its interactions are " + interactions.stream()
                            .map(m -> Interactions.names(type, m)).toList());
            return null;
        }
        int coordinator = 63 - Long.numberOfLeadingZeros(common);
        Optional<String> chosen = Annotation.find(type.annotations(), "bus", "coordinator");
        if (chosen.isPresent()) {
            int index = Interactions.index(type, chosen.get());
            if (index < 0 || (common & (1L << index)) == 0) {
                diagnostics.error(type.pos(), "@bus(coordinator=" + chosen.get() + "): the coordinator must take part in "
                        + "every interaction of " + type.name());
            } else {
                coordinator = index;
            }
        }
        List<Long> sorted = new ArrayList<>(interactions);
        sorted.sort((a, b) -> Long.bitCount(b) - Long.bitCount(a));
        return new ConnectorPlan(type, Mode.COORDINATED, 0, coordinator, sorted);
    }

    /** @return the instances of an atom type in the system, in declaration order */
    List<AtomInstance> instances(AtomType atom) {
        return system.atoms().stream().filter(a -> a.type() == atom).toList();
    }

    /** @return the plan of each port of the atom type, in declaration order (empty on errors) */
    List<PortPlan> ports(AtomType atom) {
        List<AtomInstance> instances = instances(atom);
        List<PortPlan> plans = new ArrayList<>();
        for (PortDecl port : atom.ports()) {
            if (port.isExtern()) {
                // fed by the environment (its own event type), never by a connector
                for (AtomInstance a : instances) {
                    system.connectorsOf(a.path(), port.name()).stream().findFirst().ifPresent(k -> diagnostics.error(
                            k.pos(), "connector " + k.path() + " binds extern port " + a.path() + "." + port.name()
                                    + ", which only events of the environment fire; bind an ordinary port"));
                }
                plans.add(new PortPlan(port, Role.EXTERNAL, null, new String[instances.size()],
                        new int[instances.size()], new Role[instances.size()]));
                continue;
            }
            if (!port.exported()) {
                plans.add(new PortPlan(port, Role.LOCAL, null, new String[instances.size()], new int[instances.size()],
                        new Role[instances.size()]));
                continue;
            }
            String[] names = new String[instances.size()];
            int[] params = new int[instances.size()];
            Role[] roles = new Role[instances.size()];
            ConnectorType type = null;
            boolean ok = true;
            for (int i = 0; i < instances.size(); i++) {
                String path = instances.get(i).path();
                List<ConnectorInstance> bound = system.connectorsOf(path, port.name());
                if (bound.isEmpty()) {
                    continue;
                }
                if (bound.size() > 1) {
                    diagnostics.error(bound.get(1).pos(), "port " + path + "." + port.name() + " is bound by "
                            + bound.size() + " connectors; on the event bus a port may be bound by one");
                    ok = false;
                    continue;
                }
                ConnectorInstance k = bound.get(0);
                ConnectorPlan plan = connectors.get(k.type());
                if (plan == null) {
                    ok = false;
                    continue;
                }
                int param = k.endpoints().indexOf(new Endpoint(path, port.name(), null));
                Role r = plan.mode() == Mode.BROADCAST
                        ? ((plan.initiators() & (1L << param)) != 0 ? Role.INITIATOR : Role.RECEIVER)
                        : (param == plan.coordinator() ? Role.COORDINATOR : Role.PARTICIPANT);
                if (type != null && type != k.type()) {
                    diagnostics.error(k.pos(), "instances of atom type " + atom.name() + " bind port " + port.name()
                            + " to connectors of different types (" + type.name() + ", " + k.type().name()
                            + "); the generated behaviour needs one connector type per port");
                    ok = false;
                }
                type = k.type();
                roles[i] = r;
                names[i] = k.path();
                params[i] = param;
            }
            if (ok) {
                plans.add(new PortPlan(port, type == null ? Role.EXTERNAL : Role.BOUND, type, names, params, roles));
            }
        }
        return plans;
    }

    /** @return the extern calls in the code of connectors bound to the atom type's ports */
    List<ResolvedCall> connectorCalls(AtomType atom) {
        List<ResolvedCall> calls = new ArrayList<>();
        Set<ConnectorType> seen = new LinkedHashSet<>();
        for (AtomInstance a : instances(atom)) {
            for (PortDecl p : atom.ports()) {
                for (ConnectorInstance k : system.connectorsOf(a.path(), p.name())) {
                    if (seen.add(k.type())) {
                        CallCollector collector = new CallCollector(new ExprTyper(k.scope(), new Diagnostics()),
                                LocalNames.connector(k.scope(), k.type()), calls);
                        for (ConnectorType.Interaction i : k.type().interactions()) {
                            collector.expr(i.guard());
                            if (i.up() != null) {
                                collector.stmts(i.up().stmts());
                            }
                            if (i.down() != null) {
                                collector.stmts(i.down().stmts());
                            }
                        }
                    }
                }
            }
        }
        return calls;
    }
}
