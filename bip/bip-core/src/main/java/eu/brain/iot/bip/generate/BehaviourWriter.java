package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

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
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.model.PortType;
import eu.brain.iot.bip.system.SystemModel.AtomInstance;

/**
 * Writes the OSGi smart behaviour of one atom type: a Declarative Services component that hosts the type's
 * instances in the root compound, consumes the events of its ports ({@code @SmartBehaviourDefinition(consumed)}),
 * and runs the bus protocol of {@link BusPlan}. All its state is guarded by the component's monitor.
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
        c.line(" * Owner of all state: this component's monitor ({@code notify} and every helper run under it), so it");
        c.line(" * stays consistent even if the bus called {@code notify} from several threads.");
        c.line(" * Configuration (optional, PID = this class's name): {@code trace=true} publishes TransitionFired events.");
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
        c.line("private final eu.brain.iot.eventing.api.EventBus bus;");
        c.line("private final boolean trace;");
        if (names.hasExterns()) {
            c.line("private final " + names.externs() + " bipExterns;");
        }
        c.line("/** The atom instances, by index into COMPONENTS. */");
        c.line("private final " + atomClass + "[] atoms;");
        c.line("/** Per instance: the connector it offered to and now waits for, or null. */");
        c.line("private final String[] waiting;");
        for (BusPlan.PortPlan p : ports) {
            if (p.has(BusPlan.Role.COORDINATOR)) {
                c.line("/** Per instance and port parameter: the offers collected for port " + p.port().name() + ". */");
                c.line("private final " + events.offerClass(p.connector()) + "[][] offers" + suffix(p) + ";");
                c.line("private final int[] rotation" + suffix(p) + ";");
            }
        }
        c.blank();
        constructor(c, cls);
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
        c.close();
        return c.toString();
    }

    private void constructor(Code c, String cls) {
        c.line("/**");
        c.line(" * Creates the instances and runs their initial transitions, then whatever they can do on their own.");
        c.line(" *");
        c.line(" * @param bus the event bus");
        if (names.hasExterns()) {
            c.line(" * @param externs the hand-written extern functions");
        }
        c.line(" * @param config component properties; {@code trace} (boolean) publishes TransitionFired events");
        c.line(" */");
        c.line("@org.osgi.service.component.annotations.Activate");
        c.open("public " + cls + "(@org.osgi.service.component.annotations.Reference eu.brain.iot.eventing.api.EventBus bus,"
                + (names.hasExterns() ? " @org.osgi.service.component.annotations.Reference " + names.externs() + " externs," : "")
                + " java.util.Map<String, Object> config)");
        c.line("this.bus = java.util.Objects.requireNonNull(bus, \"bus\");");
        c.line("this.trace = Boolean.parseBoolean(String.valueOf(config.getOrDefault(\"trace\", \"false\")));");
        if (names.hasExterns()) {
            c.line("this.bipExterns = java.util.Objects.requireNonNull(externs, \"externs\");");
        }
        c.line("this.waiting = new String[COMPONENTS.length];");
        for (BusPlan.PortPlan p : ports) {
            if (p.has(BusPlan.Role.COORDINATOR)) {
                c.line("this.offers" + suffix(p) + " = new " + events.offerClass(p.connector()) + "[COMPONENTS.length]["
                        + p.connector().ports().size() + "];");
                c.line("this.rotation" + suffix(p) + " = new int[COMPONENTS.length];");
            }
        }
        c.open("synchronized (this)");
        List<String> created = new ArrayList<>();
        for (AtomInstance a : instances) {
            List<String> args = new ArrayList<>();
            if (names.hasExterns()) {
                args.add("externs");
            }
            for (int i = 0; i < atom.params().size(); i++) {
                args.add(literal(i < a.args().size() ? a.args().get(i) : null, atom.params().get(i).type().name()));
            }
            created.add("new " + atomClass + "(" + String.join(", ", args) + ")");
        }
        c.line("this.atoms = new " + atomClass + "[] {" + String.join(", ", created) + "};");
        c.open("for (int i = 0; i < atoms.length; i++)");
        c.open("if (trace)").line("publishTrace(i, \"initial\", java.util.EnumSet.noneOf(" + atomClass + ".Place.class));")
                .close();
        c.line("run(i);").close();
        c.close().close().blank();
    }

    private String literal(Object value, String bipType) {
        Type t = atomScope.resolveType(bipType);
        if (value == null) {
            return JavaNames.defaultLiteral(t);
        }
        if (value instanceof String s) {
            return JavaNames.literal(s);
        }
        if (t != null && t.kind() == Type.Kind.FLOAT && value instanceof Integer i) {
            return i + ".0";
        }
        return value.toString();
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
            h.getValue().forEach(m -> c.line(m + "(e);"));
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
        c.open("private void run(int i)");
        c.line(atomClass + " a = atoms[i];");
        c.open("for (int step = 0; step < MAX_STEPS; step++)");
        c.open("if (waiting[i] != null)").line("return;").close();
        c.line("java.util.EnumSet<" + atomClass + ".Place> before = trace ? a.marking() : null;");
        c.open("if (a.internalStep())");
        c.open("if (trace)").line("publishTrace(i, \"internal\", before);").close();
        c.line("checkInvariants(i, \"internal\");");
        c.line("continue;").close();
        c.line("boolean acted = false;");
        c.open("for (" + atomClass + ".Port p : a.enabledPorts())");
        c.open("switch (p)");
        for (BusPlan.PortPlan p : ports) {
            String id = JavaNames.id(p.port().name());
            if (p.role() == BusPlan.Role.LOCAL) {
                c.line("case " + id + ": acted = fire(i, p); break;");
            } else if (p.role() == BusPlan.Role.EXTERNAL && policy(p) == PortDecl.Policy.REMEMBER) {
                c.line("case " + id + ": acted = replay" + suffix(p) + "(i); break;");
            } else if (p.role() == BusPlan.Role.BOUND && (p.has(BusPlan.Role.INITIATOR) || p.has(BusPlan.Role.PARTICIPANT)
                    || p.has(BusPlan.Role.COORDINATOR))) {
                c.line("case " + id + ": acted = act" + suffix(p) + "(i); break;");
            }
        }
        c.line("default: break;");
        c.close();
        c.open("if (acted)").line("break;").close();
        c.close();
        c.open("if (!acted)").line("return;").close();
        c.close();
        c.line("LOG.log(System.Logger.Level.WARNING, \"{0} took {1} transitions in a row without waiting for an event; "
                + "it pauses until the next event\", COMPONENTS[i], MAX_STEPS);");
        c.close().blank();
    }

    /** Java that reads/writes the atom field bound to variable {@code var} of port {@code p} (port type order). */
    String boundField(PortDecl p, String var) {
        PortType pt = atomScope.portType(p.portType()).orElseThrow();
        for (int k = 0; k < pt.params().size(); k++) {
            if (pt.params().get(k).name().equals(var)) {
                return "atoms[i]." + AtomWriter.field(p.boundData().get(k));
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
        c.open("private void on" + suffix(p) + "(" + type + " e)");
        c.open("for (int i = 0; i < atoms.length; i++)");
        c.open("if (e.component != null && !e.component.isEmpty() && !e.component.equals(COMPONENTS[i]))")
                .line("continue;").close();
        c.open("if (waiting[i] != null || !atoms[i].enabledPorts().contains(" + port(p) + "))");
        switch (policy(p)) {
            case REMEMBER -> {
                c.line("// extern port, policy remember: kept until the port is enabled (run takes it then)");
                c.line("pending" + suffix(p) + "(i).add(e);");
            }
            case ERROR -> c.line("LOG.log(System.Logger.Level.ERROR, \"{0}: extern port " + p.port().name()
                    + " cannot take an event now (policy error): event dropped\", COMPONENTS[i]);");
            default -> c.line("LOG.log(System.Logger.Level.DEBUG, \"{0}: port " + p.port().name()
                    + " is not enabled, event ignored\", COMPONENTS[i]);");
        }
        c.line("continue;").close();
        c.line("take" + suffix(p) + "(i, e);");
        c.line("run(i);");
        c.close().close().blank();
        c.open("private boolean take" + suffix(p) + "(int i, " + type + " e)");
        for (Param v : portVars(p.port())) {
            c.line(boundField(p.port(), v.name()) + " = e." + EventsWriter.externalField(v.name()) + ";");
        }
        c.line("return fire(i, " + port(p) + ");");
        c.close().blank();
        if (policy(p) == PortDecl.Policy.REMEMBER) {
            String queue = "java.util.ArrayDeque<" + type + ">";
            c.line("/** Per instance: events for extern port " + p.port().name() + " that came before it was enabled. */");
            c.line("private final java.util.Map<Integer, " + queue + "> pending" + suffix(p)
                    + "Queues = new java.util.HashMap<>();");
            c.open("private " + queue + " pending" + suffix(p) + "(int i)");
            c.line("return pending" + suffix(p) + "Queues.computeIfAbsent(i, k -> new java.util.ArrayDeque<>());");
            c.close().blank();
            c.open("private boolean replay" + suffix(p) + "(int i)");
            c.line(type + " e = pending" + suffix(p) + "(i).poll();");
            c.line("return e != null && take" + suffix(p) + "(i, e);");
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
        c.open("private boolean act" + suffix(p) + "(int i)");
        c.open("switch (ROLE_" + suffix(p) + "[i])");
        if (p.has(BusPlan.Role.INITIATOR)) {
            c.line("case " + roleCode(BusPlan.Role.INITIATOR) + ": return initiate" + suffix(p) + "(i);");
        }
        if (p.has(BusPlan.Role.PARTICIPANT)) {
            c.line("case " + roleCode(BusPlan.Role.PARTICIPANT) + ": return offer" + suffix(p) + "(i);");
        }
        if (p.has(BusPlan.Role.COORDINATOR)) {
            c.line("case " + roleCode(BusPlan.Role.COORDINATOR) + ": return coordinate" + suffix(p) + "(i);");
        }
        c.line("default: return false;");
        c.close().close().blank();
    }

    private void helpers(Code c) {
        c.line("/** Fires a port transition of instance i (tracing it when configured). */");
        c.open("private boolean fire(int i, " + atomClass + ".Port port)");
        c.line("java.util.EnumSet<" + atomClass + ".Place> before = trace ? atoms[i].marking() : null;");
        c.open("if (!atoms[i].fire(port))");
        c.line("LOG.log(System.Logger.Level.WARNING, \"{0}: port {1} is not enabled\", COMPONENTS[i], port);");
        c.line("return false;").close();
        c.open("if (trace)").line("publishTrace(i, port.name(), before);").close();
        c.line("checkInvariants(i, port.name());");
        c.line("return true;");
        c.close().blank();
        c.line("/** A violated invariant is an error of the model: logged, the behaviour goes on. */");
        c.open("private void checkInvariants(int i, String transition)");
        c.open("for (String invariant : atoms[i].violatedInvariants())");
        c.line("LOG.log(System.Logger.Level.ERROR, \"{0}: invariant {1} does not hold after {2}\", COMPONENTS[i], "
                + "invariant, transition);");
        c.close().close().blank();
        String trace = events.traceClass();
        c.open("private void publishTrace(int i, String port, java.util.EnumSet<" + atomClass + ".Place> before)");
        c.line(trace + " t = new " + trace + "();");
        c.line("t.component = COMPONENTS[i];");
        c.line("t.atomType = " + JavaNames.literal(atom.name()) + ";");
        c.line("t.port = port;");
        c.line("before.forEach(x -> t.from.add(x.name()));");
        c.line("atoms[i].marking().forEach(x -> t.to.add(x.name()));");
        c.line("bus.deliver(t);");
        c.close().blank();
        c.line("/** @return the marked places of a component, e.g. [START], or null if it is not hosted here */");
        c.open("public synchronized java.util.List<String> placesOf(String component)");
        c.open("for (int i = 0; i < COMPONENTS.length; i++)");
        c.open("if (COMPONENTS[i].equals(component))");
        c.line("java.util.List<String> places = new java.util.ArrayList<>();");
        c.line("atoms[i].marking().forEach(x -> places.add(x.name()));");
        c.line("return places;").close().close();
        c.line("return null;");
        c.close().blank();
        c.line("/** @return the data of a component by name, or null if it is not hosted here */");
        c.open("public synchronized java.util.Map<String, Object> dataOf(String component)");
        c.open("for (int i = 0; i < COMPONENTS.length; i++)");
        c.open("if (COMPONENTS[i].equals(component))").line("return atoms[i].data();").close().close();
        c.line("return null;");
        c.close();
    }

}
