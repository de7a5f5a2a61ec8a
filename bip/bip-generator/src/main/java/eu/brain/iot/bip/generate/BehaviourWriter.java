package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.model.PortType;
import eu.brain.iot.bip.system.SystemModel.AtomInstance;

/**
 * Writes the OSGi smart behaviour of one atom type: a Declarative Services component that hosts the type's
 * instances in the root compound, consumes the events of its ports ({@code @SmartBehaviourDefinition(consumed)}),
 * and runs the bus protocol of {@link BusPlan} once per group (see {@link GroupWriter}). All its state is guarded by
 * the component's monitor.
 */
final class BehaviourWriter {

    final BusPlan plan;
    private final AtomType atom;
    private final Generator.AtomNames names;
    final EventsWriter events;
    private final List<AtomInstance> instances;
    private final List<BusPlan.PortPlan> ports;
    private final PackageScope atomScope;
    final Diagnostics diagnostics;
    private final String atomClass;

    BehaviourWriter(BusPlan plan, AtomType atom, Generator.AtomNames names, EventsWriter events,
            Diagnostics diagnostics) {
        this.plan = plan;
        this.atom = atom;
        this.names = names;
        this.events = events;
        this.instances = plan.instances(atom);
        this.ports = plan.ports(atom);
        this.atomScope = instances.get(0).scope();
        this.diagnostics = diagnostics;
        this.atomClass = names.atomClass();
    }

    String port(BusPlan.PortPlan p) {
        return atomClass + ".Port." + JavaNames.id(p.port().name());
    }

    static String suffix(BusPlan.PortPlan p) {
        return JavaNames.capital(p.port().name());
    }

    String write() {
        Set<String> consumed = new LinkedHashSet<>();
        for (BusPlan.PortPlan p : ports) {
            if (p.role() == BusPlan.Role.EXTERNAL) {
                consumed.add(events.externalClass(atom, p.port().name()));
            }
            if (p.has(BusPlan.Role.RECEIVER) || p.has(BusPlan.Role.PARTICIPANT)) {
                consumed.add(events.eventClass(p.connector()));
            }
            if (p.has(BusPlan.Role.COORDINATOR)) {
                consumed.add(events.offerClass(p.connector()));
            }
        }
        String cls = names.behaviour();
        RoleWriter roles = new RoleWriter(this);
        Code c = new Code();
        c.line("package " + names.javaPackage() + ";").blank();
        c.line("/**");
        c.line(" * Smart behaviour of atom type {@code " + atom.name() + "}, instances "
                + instances.stream().map(AtomInstance::path).toList() + " of compound {@code "
                + plan.system().root().name() + "}; generated: do not edit.");
        c.line(" * <p>");
        c.line(" * The root compound is replicated per group: each group named by an event's {@code group} field (null or");
        c.line(" * empty: the default group, created at activation) has its own instances, created when an event first");
        c.line(" * names it, up to {@code max.groups}; groups never interact. See {@link #groups()}.");
        c.line(" * <p>");
        c.line(" * Owner of all state: this component's monitor ({@code notify} and every helper run under it), so it");
        c.line(" * stays consistent even if the bus called {@code notify} from several threads.");
        c.line(" * Configuration (optional, PID = this class's name, see {@link Config}): {@code trace=true} publishes");
        c.line(" * TransitionFired events; {@code max.groups} bounds the number of groups (default " + GroupWriter.MAX_GROUPS + ").");
        c.line(" */");
        c.line("@javax.annotation.processing.Generated(\"eu.brain.iot.bip\")");
        c.line("@org.osgi.service.component.annotations.Component(service = eu.brain.iot.eventing.api.SmartBehaviour.class,");
        c.line("        configurationPolicy = org.osgi.service.component.annotations.ConfigurationPolicy.OPTIONAL)");
        c.line("@eu.brain.iot.eventing.annotation.SmartBehaviourDefinition(consumed = {"
                + consumed.stream().map(x -> x + ".class").collect(Collectors.joining(", ")) + "},");
        c.line("        name = " + JavaNames.literal(atom.name()) + ", author = \"BIP generator\",");
        c.line("        description = " + JavaNames.literal("Atom type " + atom.name() + " of " + JavaNames.fileName(atom.pos())) + ")");
        c.open("public final class " + cls + " implements eu.brain.iot.eventing.api.SmartBehaviour<eu.brain.iot.eventing.api.BrainIoTEvent>");
        c.blank();
        c.line("private static final System.Logger LOG = System.getLogger(" + cls + ".class.getName());");
        c.line("/** Transitions an instance may take on its own per event before it pauses (guards a livelock). */");
        c.line("static final int MAX_STEPS = 1000;");
        c.line("private static final String[] COMPONENTS = {" + instances.stream().map(a -> JavaNames.literal(a.path()))
                .collect(Collectors.joining(", ")) + "};");
        for (BusPlan.PortPlan p : ports) {
            if (p.connector() != null) {
                c.line("private static final String[] CONNECTOR_" + suffix(p) + " = {" + java.util.Arrays
                        .stream(p.connectorByInstance()).map(n -> n == null ? "null" : JavaNames.literal(n))
                        .collect(Collectors.joining(", ")) + "};");
                c.line("private static final int[] PARAM_" + suffix(p) + " = {" + java.util.Arrays
                        .stream(p.paramByInstance()).mapToObj(Integer::toString).collect(Collectors.joining(", ")) + "};");
                c.line("private static final int[] ROLE_" + suffix(p) + " = {" + java.util.Arrays
                        .stream(p.roleByInstance()).map(r -> Integer.toString(roleCode(r)))
                        .collect(Collectors.joining(", ")) + "};");
            }
        }
        c.blank();
        GroupWriter groups = new GroupWriter(this, atom, names, instances, ports);
        groups.fields(c, cls);
        c.blank();
        groups.constructors(c, cls);
        groups.lookup(c);
        notifyMethod(c);
        run(c);
        for (BusPlan.PortPlan p : ports) {
            if (p.role() == BusPlan.Role.EXTERNAL) {
                external(c, p);
            }
            if (p.role() == BusPlan.Role.BOUND) {
                act(c, p);
            }
            if (p.has(BusPlan.Role.INITIATOR)) {
                roles.initiate(c, p);
            }
            if (p.has(BusPlan.Role.RECEIVER)) {
                roles.receive(c, p);
            }
            if (p.has(BusPlan.Role.PARTICIPANT)) {
                roles.participate(c, p);
            }
            if (p.has(BusPlan.Role.COORDINATOR)) {
                roles.coordinate(c, p);
            }
        }
        helpers(c);
        groups.views(c);
        c.close();
        return c.toString();
    }

    private void notifyMethod(Code c) {
        c.line("@Override");
        c.open("public synchronized void notify(eu.brain.iot.eventing.api.BrainIoTEvent event)");
        java.util.Map<String, List<String>> handlers = new java.util.LinkedHashMap<>();
        for (BusPlan.PortPlan p : ports) {
            if (p.role() == BusPlan.Role.EXTERNAL) {
                handlers.computeIfAbsent(events.externalClass(atom, p.port().name()), k -> new ArrayList<>())
                        .add("on" + suffix(p));
            }
            if (p.has(BusPlan.Role.RECEIVER)) {
                handlers.computeIfAbsent(events.eventClass(p.connector()), k -> new ArrayList<>()).add("receive" + suffix(p));
            }
            if (p.has(BusPlan.Role.PARTICIPANT)) {
                handlers.computeIfAbsent(events.eventClass(p.connector()), k -> new ArrayList<>()).add("complete" + suffix(p));
            }
            if (p.has(BusPlan.Role.COORDINATOR)) {
                handlers.computeIfAbsent(events.offerClass(p.connector()), k -> new ArrayList<>()).add("collect" + suffix(p));
            }
        }
        boolean first = true;
        for (var h : handlers.entrySet()) {
            String type = h.getKey();
            if (first) {
                c.open("if (event instanceof " + type + ")");
            } else {
                c.middle("} else if (event instanceof " + type + ") {");
            }
            c.line(type + " e = (" + type + ") event;");
            c.line("Group g = group(e.group);");
            c.open("if (g != null)");
            h.getValue().forEach(m -> c.line(m + "(g, e);"));
            c.close();
            first = false;
        }
        if (first) {
            c.line("LOG.log(System.Logger.Level.DEBUG, \"ignored event {0}: no port consumes it\", event.getClass().getName());");
        } else {
            c.middle("} else {");
            c.line("LOG.log(System.Logger.Level.DEBUG, \"ignored event {0}: no port consumes it\", event.getClass().getName());");
            c.close();
        }
        c.close().blank();
    }

    private void run(Code c) {
        c.line("/** Lets instance i take the transitions it can take on its own: internal ones first, then its ports. */");
        c.open("private void run(Group g, int i)");
        c.line(atomClass + " a = g.atoms[i];");
        c.open("for (int step = 0; step < MAX_STEPS; step++)");
        c.open("if (g.waiting[i] != null)").line("return;").close();
        c.line("enter(g, i);");
        c.line("java.util.EnumSet<" + atomClass + ".Place> before = trace ? a.marking() : null;");
        c.open("if (a.internalStep())");
        c.open("if (trace)").line("publishTrace(g, i, \"internal\", before);").close();
        c.line("checkInvariants(g, i, \"internal\");");
        c.line("continue;").close();
        c.line("boolean acted = false;");
        c.open("for (" + atomClass + ".Port p : a.enabledPorts())");
        c.open("switch (p)");
        for (BusPlan.PortPlan p : ports) {
            String id = JavaNames.id(p.port().name());
            if (p.role() == BusPlan.Role.LOCAL) {
                c.line("case " + id + ": acted = fire(g, i, p); break;");
            } else if (p.role() == BusPlan.Role.EXTERNAL && policy(p) == PortDecl.Policy.REMEMBER) {
                c.line("case " + id + ": acted = replay" + suffix(p) + "(g, i); break;");
            } else if (p.role() == BusPlan.Role.BOUND && (p.has(BusPlan.Role.INITIATOR) || p.has(BusPlan.Role.PARTICIPANT)
                    || p.has(BusPlan.Role.COORDINATOR))) {
                c.line("case " + id + ": acted = act" + suffix(p) + "(g, i); break;");
            }
        }
        c.line("default: break;");
        c.close();
        c.open("if (acted)").line("break;").close();
        c.close();
        c.open("if (!acted)").line("return;").close();
        c.close();
        c.line("LOG.log(System.Logger.Level.WARNING, \"{0} took {1} transitions in a row without waiting for an event; "
                + "it pauses until the next event\", g.who(i), MAX_STEPS);");
        c.close().blank();
    }

    /** Java that reads/writes the atom field bound to variable {@code var} of port {@code p} (port type order). */
    String boundField(PortDecl p, String var) {
        PortType pt = atomScope.portType(p.portType()).orElseThrow();
        for (int k = 0; k < pt.params().size(); k++) {
            if (pt.params().get(k).name().equals(var)) {
                return "g.atoms[i]." + AtomWriter.field(p.boundData().get(k));
            }
        }
        throw new IllegalStateException("no variable " + var + " in port type " + pt.name());
    }

    List<Param> portVars(PortDecl p) {
        return atomScope.portType(p.portType()).orElseThrow().params();
    }

    private void external(Code c, BusPlan.PortPlan p) {
        String type = events.externalClass(atom, p.port().name());
        c.line("/** Port " + p.port().name() + " fired from outside: see {@link " + type + "}. */");
        c.open("private void on" + suffix(p) + "(Group g, " + type + " e)");
        c.open("for (int i = 0; i < g.atoms.length; i++)");
        c.open("if (e.component != null && !e.component.isEmpty() && !e.component.equals(COMPONENTS[i]))")
                .line("continue;").close();
        c.line("enter(g, i);");
        c.open("if (g.waiting[i] != null || !g.atoms[i].enabledPorts().contains(" + port(p) + "))");
        switch (policy(p)) {
            case REMEMBER -> {
                c.line("// extern port, policy remember: kept until the port is enabled (run takes it then)");
                c.line("pending" + suffix(p) + "(g, i).add(e);");
            }
            case ERROR -> c.line("LOG.log(System.Logger.Level.ERROR, \"{0}: extern port " + p.port().name()
                    + " cannot take an event now (policy error): event dropped\", g.who(i));");
            default -> c.line("LOG.log(System.Logger.Level.DEBUG, \"{0}: port " + p.port().name()
                    + " is not enabled, event ignored\", g.who(i));");
        }
        c.line("continue;").close();
        c.line("take" + suffix(p) + "(g, i, e);");
        c.line("run(g, i);");
        c.close().close().blank();
        c.open("private boolean take" + suffix(p) + "(Group g, int i, " + type + " e)");
        for (Param v : portVars(p.port())) {
            c.line(boundField(p.port(), v.name()) + " = e." + EventsWriter.externalField(v.name()) + ";");
        }
        c.line("return fire(g, i, " + port(p) + ");");
        c.close().blank();
        if (policy(p) == PortDecl.Policy.REMEMBER) {
            String queue = "java.util.ArrayDeque<" + type + ">";
            c.open("private " + queue + " pending" + suffix(p) + "(Group g, int i)");
            c.line("return g.pending" + suffix(p) + "Queues.computeIfAbsent(i, k -> new java.util.ArrayDeque<>());");
            c.close().blank();
            c.open("private boolean replay" + suffix(p) + "(Group g, int i)");
            c.line(type + " e = pending" + suffix(p) + "(g, i).poll();");
            c.line("return e != null && take" + suffix(p) + "(g, i, e);");
            c.close().blank();
        }
    }

    /** @return the policy of an extern port; an exported port fired by its event behaves as {@code ignore} */
    private static PortDecl.Policy policy(BusPlan.PortPlan p) {
        return p.port().isExtern() ? p.port().extern().policy().effective() : PortDecl.Policy.IGNORE;
    }


    static int roleCode(BusPlan.Role role) {
        return role == null ? 0 : switch (role) {
            case INITIATOR -> 1;
            case RECEIVER -> 2;
            case PARTICIPANT -> 3;
            case COORDINATOR -> 4;
            default -> 0;
        };
    }

    /** What a bound port does on its own, by the instance's role. */
    private void act(Code c, BusPlan.PortPlan p) {
        if (!(p.has(BusPlan.Role.INITIATOR) || p.has(BusPlan.Role.PARTICIPANT) || p.has(BusPlan.Role.COORDINATOR))) {
            return;
        }
        c.line("/** Port " + p.port().name() + " is enabled: what instance i does depends on its part in the connector. */");
        c.open("private boolean act" + suffix(p) + "(Group g, int i)");
        c.open("switch (ROLE_" + suffix(p) + "[i])");
        if (p.has(BusPlan.Role.INITIATOR)) {
            c.line("case " + roleCode(BusPlan.Role.INITIATOR) + ": return initiate" + suffix(p) + "(g, i);");
        }
        if (p.has(BusPlan.Role.PARTICIPANT)) {
            c.line("case " + roleCode(BusPlan.Role.PARTICIPANT) + ": return offer" + suffix(p) + "(g, i);");
        }
        if (p.has(BusPlan.Role.COORDINATOR)) {
            c.line("case " + roleCode(BusPlan.Role.COORDINATOR) + ": return coordinate" + suffix(p) + "(g, i);");
        }
        c.line("default: return false;");
        c.close().close().blank();
    }

    private void helpers(Code c) {
        c.line("/** Fires a port transition of instance i (tracing it when configured). */");
        c.open("private boolean fire(Group g, int i, " + atomClass + ".Port port)");
        c.line("enter(g, i);");
        c.line("java.util.EnumSet<" + atomClass + ".Place> before = trace ? g.atoms[i].marking() : null;");
        c.open("if (!g.atoms[i].fire(port))");
        c.line("LOG.log(System.Logger.Level.WARNING, \"{0}: port {1} is not enabled\", g.who(i), port);");
        c.line("return false;").close();
        c.open("if (trace)").line("publishTrace(g, i, port.name(), before);").close();
        c.line("checkInvariants(g, i, port.name());");
        c.line("return true;");
        c.close().blank();
        c.line("/** A violated invariant is an error of the model: logged, the behaviour goes on. */");
        c.open("private void checkInvariants(Group g, int i, String transition)");
        c.open("for (String invariant : g.atoms[i].violatedInvariants())");
        c.line("LOG.log(System.Logger.Level.ERROR, \"{0}: invariant {1} does not hold after {2}\", g.who(i), "
                + "invariant, transition);");
        c.close().close().blank();
        String trace = events.traceClass();
        c.open("private void publishTrace(Group g, int i, String port, java.util.EnumSet<" + atomClass + ".Place> before)");
        c.line(trace + " t = new " + trace + "();");
        c.line("t.group = g.wire;");
        c.line("t.component = COMPONENTS[i];");
        c.line("t.atomType = " + JavaNames.literal(atom.name()) + ";");
        c.line("t.port = port;");
        c.line("before.forEach(x -> t.from.add(x.name()));");
        c.line("g.atoms[i].marking().forEach(x -> t.to.add(x.name()));");
        c.line("bus.deliver(t);");
        c.close().blank();
    }

}
