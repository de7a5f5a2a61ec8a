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

    private final BusPlan plan;
    private final AtomType atom;
    private final Generator.AtomNames names;
    private final EventsWriter events;
    private final List<AtomInstance> instances;
    private final List<BusPlan.PortPlan> ports;
    private final PackageScope atomScope;
    private final Diagnostics diagnostics;
    private final String atomClass;

    BehaviourWriter(BusPlan plan, AtomType atom, Generator.AtomNames names, EventsWriter events) {
        this.plan = plan;
        this.atom = atom;
        this.names = names;
        this.events = events;
        this.instances = plan.instances(atom);
        this.ports = plan.ports(atom);
        this.atomScope = instances.get(0).scope();
        this.diagnostics = atomScope.workspace().diagnostics();
        this.atomClass = names.atomClass();
    }

    private String port(BusPlan.PortPlan p) {
        return atomClass + ".Port." + JavaNames.id(p.port().name());
    }

    private static String suffix(BusPlan.PortPlan p) {
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
                initiate(c, p);
            }
            if (p.has(BusPlan.Role.RECEIVER)) {
                receive(c, p);
            }
            if (p.has(BusPlan.Role.PARTICIPANT)) {
                participate(c, p);
            }
            if (p.has(BusPlan.Role.COORDINATOR)) {
                coordinate(c, p);
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
            return t == null ? "null" : switch (t.kind()) {
                case INT -> "0";
                case FLOAT -> "0.0";
                case BOOL -> "false";
                case STRING -> "\"\"";
                default -> "null";
            };
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
        c.line("continue;").close();
        c.line("boolean acted = false;");
        c.open("for (" + atomClass + ".Port p : a.enabledPorts())");
        c.open("switch (p)");
        for (BusPlan.PortPlan p : ports) {
            String id = JavaNames.id(p.port().name());
            if (p.role() == BusPlan.Role.LOCAL) {
                c.line("case " + id + ": acted = fire(i, p); break;");
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
    private String boundField(PortDecl p, String var) {
        PortType pt = atomScope.portType(p.portType()).orElseThrow();
        for (int k = 0; k < pt.params().size(); k++) {
            if (pt.params().get(k).name().equals(var)) {
                return "atoms[i]." + AtomWriter.field(p.boundData().get(k));
            }
        }
        throw new IllegalStateException("no variable " + var + " in port type " + pt.name());
    }

    private List<Param> portVars(PortDecl p) {
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
        c.line("LOG.log(System.Logger.Level.DEBUG, \"{0}: port " + p.port().name()
                + " is not enabled, event ignored\", COMPONENTS[i]);");
        c.line("continue;").close();
        for (Param v : portVars(p.port())) {
            c.line(boundField(p.port(), v.name()) + " = e." + EventsWriter.externalField(v.name()) + ";");
        }
        c.line("fire(i, " + port(p) + ");");
        c.line("run(i);");
        c.close().close().blank();
    }

    private void initiate(Code c, BusPlan.PortPlan p) {
        ConnectorType t = p.connector();
        String type = events.eventClass(t);
        c.line("/** Fires trigger port " + p.port().name() + " alone and publishes the interaction. */");
        c.open("private boolean initiate" + suffix(p) + "(int i)");
        c.open("if (CONNECTOR_" + suffix(p) + "[i] == null)").line("return false;").close();
        c.line(type + " e = new " + type + "();");
        c.line("e.connector = CONNECTOR_" + suffix(p) + "[i];");
        c.open("switch (PARAM_" + suffix(p) + "[i])");
        for (int j : distinct(p, BusPlan.Role.INITIATOR)) {
            String jName = t.ports().get(j).name();
            c.open("case " + j + ":");
            c.line("e.initiator = " + JavaNames.literal(jName) + ";");
            c.line("e.participants.add(" + JavaNames.literal(jName) + ");");
            ConnectorType.Interaction clause = Interactions.clause(t, 1L << j);
            ConnectorCode code = new ConnectorCode(p, jName, Set.of(jName), "initiator");
            code.locals(c, null);
            if (clause != null) {
                code.body(c, clause, "return false;");
            }
            for (Param v : portVars(p.port())) {
                c.line("e." + EventsWriter.dataField(jName, v.name()) + " = " + boundField(p.port(), v.name()) + ";");
            }
            for (DataDecl d : t.data()) {
                c.line("e." + EventsWriter.connectorDataField(d.name()) + " = d_" + d.name() + ";");
            }
            c.line("break;").close();
        }
        c.line("default: return false;");
        c.close();
        c.line("fire(i, " + port(p) + ");");
        c.line("bus.deliver(e);");
        c.line("return true;");
        c.close().blank();
    }

    private void receive(Code c, BusPlan.PortPlan p) {
        ConnectorType t = p.connector();
        String type = events.eventClass(t);
        BusPlan.ConnectorPlan cp = plan.plan(t);
        c.line("/** A broadcast of " + t.name() + " arrived: synchron port " + p.port().name() + " joins if ready. */");
        c.open("private void receive" + suffix(p) + "(" + type + " e)");
        c.open("for (int i = 0; i < atoms.length; i++)");
        c.open("if (ROLE_" + suffix(p) + "[i] != " + roleCode(BusPlan.Role.RECEIVER) + " || e.connector == null"
                + " || !e.connector.equals(CONNECTOR_" + suffix(p) + "[i]) || waiting[i] != null"
                + " || !atoms[i].enabledPorts().contains(" + port(p) + "))").line("continue;").close();
        c.line("String self = " + JavaNames.literal("") + ";");
        c.line("boolean joins = false;");
        c.open("switch (PARAM_" + suffix(p) + "[i])");
        for (int r : distinct(p, BusPlan.Role.RECEIVER)) {
            String rName = t.ports().get(r).name();
            c.open("case " + r + ":");
            c.line("self = " + JavaNames.literal(rName) + ";");
            for (int j = 0; j < t.ports().size(); j++) {
                if ((cp.initiators() & (1L << j)) == 0 || j == r) {
                    continue;
                }
                String jName = t.ports().get(j).name();
                ConnectorType.Interaction clause = receiverClause(t, j, r);
                c.open("if (" + JavaNames.literal(jName) + ".equals(e.initiator))");
                ConnectorCode code = new ConnectorCode(p, rName, Set.of(jName, rName), "receiver");
                code.locals(c, "e");
                c.open("do");
                if (clause != null) {
                    code.body(c, clause, "break;");
                }
                c.line("joins = true;");
                c.close("} while (false);");
                c.close();
            }
            c.line("break;").close();
        }
        c.line("default: break;");
        c.close();
        c.open("if (joins)");
        c.line("fire(i, " + port(p) + ");");
        c.line("run(i);");
        c.close();
        c.close().close().blank();
    }

    /** The clause for a receiver: exactly {initiator, receiver}, else the first that contains both. */
    private static ConnectorType.Interaction receiverClause(ConnectorType t, int j, int r) {
        long pair = (1L << j) | (1L << r);
        ConnectorType.Interaction exact = Interactions.clause(t, pair);
        if (exact != null) {
            return exact;
        }
        for (ConnectorType.Interaction i : t.interactions()) {
            if ((Interactions.mask(t, i.ports()) & pair) == pair) {
                return i;
            }
        }
        return null;
    }

    private void participate(Code c, BusPlan.PortPlan p) {
        ConnectorType t = p.connector();
        String offer = events.offerClass(t);
        String type = events.eventClass(t);
        c.line("/** Port " + p.port().name() + " is ready: offer it to the coordinator of " + t.name() + " and wait. */");
        c.open("private boolean offer" + suffix(p) + "(int i)");
        c.open("if (CONNECTOR_" + suffix(p) + "[i] == null)").line("return false;").close();
        c.line(offer + " o = new " + offer + "();");
        c.line("o.connector = CONNECTOR_" + suffix(p) + "[i];");
        c.line("o.component = COMPONENTS[i];");
        c.open("switch (PARAM_" + suffix(p) + "[i])");
        for (int j : distinct(p, BusPlan.Role.PARTICIPANT)) {
            String jName = t.ports().get(j).name();
            c.open("case " + j + ":");
            c.line("o.port = " + JavaNames.literal(jName) + ";");
            for (Param v : portVars(p.port())) {
                c.line("o." + EventsWriter.dataField(jName, v.name()) + " = " + boundField(p.port(), v.name()) + ";");
            }
            c.line("break;").close();
        }
        c.line("default: return false;");
        c.close();
        c.line("waiting[i] = o.connector;");
        c.line("bus.deliver(o);");
        c.line("return true;");
        c.close().blank();
        c.line("/** The coordinator of " + t.name() + " fired: take part if this instance was in the interaction. */");
        c.open("private void complete" + suffix(p) + "(" + type + " e)");
        c.open("for (int i = 0; i < atoms.length; i++)");
        c.open("if (ROLE_" + suffix(p) + "[i] != " + roleCode(BusPlan.Role.PARTICIPANT) + " || e.connector == null"
                + " || !e.connector.equals(waiting[i]) || !e.connector.equals(CONNECTOR_" + suffix(p) + "[i]))")
                .line("continue;").close();
        c.open("switch (PARAM_" + suffix(p) + "[i])");
        for (int j : distinct(p, BusPlan.Role.PARTICIPANT)) {
            String jName = t.ports().get(j).name();
            c.open("case " + j + ":");
            c.open("if (!e.participants.contains(" + JavaNames.literal(jName) + "))").line("continue;").close();
            for (Param v : portVars(p.port())) {
                c.line(boundField(p.port(), v.name()) + " = e." + EventsWriter.dataField(jName, v.name()) + ";");
            }
            c.line("break;").close();
        }
        c.line("default: continue;");
        c.close();
        c.line("waiting[i] = null;");
        c.line("fire(i, " + port(p) + ");");
        c.line("run(i);");
        c.close().close().blank();
    }

    private void coordinate(Code c, BusPlan.PortPlan p) {
        ConnectorType t = p.connector();
        BusPlan.ConnectorPlan cp = plan.plan(t);
        String offer = events.offerClass(t);
        String type = events.eventClass(t);
        int self = cp.coordinator();
        String selfName = t.ports().get(self).name();
        List<Long> candidates = cp.interactions().stream().filter(m -> (m & (1L << self)) != 0).toList();
        c.line("/** An offer for " + t.name() + " arrived: keep it (the latest per port) and see whether to fire. */");
        c.open("private void collect" + suffix(p) + "(" + offer + " o)");
        c.open("for (int i = 0; i < atoms.length; i++)");
        c.open("if (ROLE_" + suffix(p) + "[i] != " + roleCode(BusPlan.Role.COORDINATOR) + " || o.connector == null"
                + " || !o.connector.equals(CONNECTOR_" + suffix(p) + "[i]))").line("continue;").close();
        c.line("int param = paramIndex" + suffix(p) + "(o.port);");
        c.open("if (param < 0 || param == " + self + ")");
        c.line("LOG.log(System.Logger.Level.WARNING, \"offer for unknown port {0} of {1} ignored\", o.port, o.connector);");
        c.line("continue;").close();
        c.line("offers" + suffix(p) + "[i][param] = o;");
        c.line("run(i);");
        c.close().close().blank();
        c.open("private static int paramIndex" + suffix(p) + "(String port)");
        c.open("switch (String.valueOf(port))");
        for (int k = 0; k < t.ports().size(); k++) {
            c.line("case " + JavaNames.literal(t.ports().get(k).name()) + ": return " + k + ";");
        }
        c.line("default: return -1;");
        c.close().close().blank();
        c.line("/** Fires the largest complete interaction of " + t.name() + " (round robin among equals), if any. */");
        c.open("private boolean coordinate" + suffix(p) + "(int i)");
        c.open("if (CONNECTOR_" + suffix(p) + "[i] == null)").line("return false;").close();
        int k = 0;
        while (k < candidates.size()) {
            int size = Long.bitCount(candidates.get(k));
            int end = k;
            while (end < candidates.size() && Long.bitCount(candidates.get(end)) == size) {
                end++;
            }
            int count = end - k;
            c.open("for (int n = 0; n < " + count + "; n++)");
            c.line("int m = " + k + " + (rotation" + suffix(p) + "[i] + n) % " + count + ";");
            c.open("if (interaction" + suffix(p) + "(i, m))");
            c.line("rotation" + suffix(p) + "[i] = m - " + k + " + 1;");
            c.line("return true;").close();
            c.close();
            k = end;
        }
        c.line("return false;");
        c.close().blank();
        c.open("private boolean interaction" + suffix(p) + "(int i, int m)");
        c.line(offer + "[] offers = offers" + suffix(p) + "[i];");
        c.open("switch (m)");
        for (int m = 0; m < candidates.size(); m++) {
            long mask = candidates.get(m);
            List<String> members = Interactions.names(t, mask);
            c.open("case " + m + ":");
            for (int q = 0; q < t.ports().size(); q++) {
                if (q != self && (mask & (1L << q)) != 0) {
                    c.open("if (offers[" + q + "] == null)").line("return false;").close();
                }
            }
            ConnectorCode code = new ConnectorCode(p, selfName, new LinkedHashSet<>(members), "coordinator");
            code.coordinatorLocals(c, mask, self);
            ConnectorType.Interaction clause = Interactions.clause(t, mask);
            if (clause != null) {
                code.body(c, clause, "return false;");
            }
            for (Param v : portVars(p.port())) {
                c.line(boundField(p.port(), v.name()) + " = " + ConnectorCode.local(selfName, v.name()) + ";");
            }
            c.line(type + " e = new " + type + "();");
            c.line("e.connector = CONNECTOR_" + suffix(p) + "[i];");
            c.line("e.initiator = " + JavaNames.literal(selfName) + ";");
            for (String member : members) {
                c.line("e.participants.add(" + JavaNames.literal(member) + ");");
                Param param = t.ports().get(Interactions.index(t, member));
                for (Param v : events.portType(t, param).params()) {
                    c.line("e." + EventsWriter.dataField(member, v.name()) + " = " + ConnectorCode.local(member, v.name())
                            + ";");
                }
            }
            for (DataDecl d : t.data()) {
                c.line("e." + EventsWriter.connectorDataField(d.name()) + " = d_" + d.name() + ";");
            }
            for (int q = 0; q < t.ports().size(); q++) {
                if (q != self && (mask & (1L << q)) != 0) {
                    c.line("offers[" + q + "] = null;");
                }
            }
            c.line("fire(i, " + port(p) + ");");
            c.line("bus.deliver(e);");
            c.line("return true;");
            c.close("}");
        }
        c.line("default: return false;");
        c.close().close().blank();
    }

    /** @return the connector parameters the instances playing {@code role} are bound to */
    private static List<Integer> distinct(BusPlan.PortPlan p, BusPlan.Role role) {
        Set<Integer> set = new LinkedHashSet<>();
        for (int i = 0; i < p.paramByInstance().length; i++) {
            if (p.roleByInstance()[i] == role) {
                set.add(p.paramByInstance()[i]);
            }
        }
        return new ArrayList<>(set);
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
        c.line("return true;");
        c.close().blank();
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

    /**
     * Writes the guard, up and down of a connector clause for one role. Port data become locals
     * ({@code v_p1_position}), connector data {@code d_name}; what a role may not see is reported.
     */
    private final class ConnectorCode {
        private final BusPlan.PortPlan p;
        private final String own;
        private final Set<String> visible;
        private final String role;
        private final PackageScope scope;
        private final ExprTyper typer;
        private final LocalNames names;
        private String eventVar;

        ConnectorCode(BusPlan.PortPlan p, String own, Set<String> visible, String role) {
            this.p = p;
            this.own = own;
            this.visible = visible;
            this.role = role;
            this.scope = events.scope(p.connector());
            this.typer = new ExprTyper(scope, new Diagnostics());
            this.names = LocalNames.connector(scope, p.connector());
        }

        static String local(String param, String var) {
            return "v_" + param + "_" + var;
        }

        private String javaType(String bipType, PackageScope where) {
            Type t = where.resolveType(bipType);
            return JavaNames.javaType(t == null ? Type.ERROR : t, where);
        }

        /** Locals of a broadcast role: own port from the atom, the initiator's from the event, connector data. */
        void locals(Code c, String event) {
            this.eventVar = event;
            ConnectorType t = p.connector();
            for (DataDecl d : t.data()) {
                String init = event == null ? defaultValue(d.type().name())
                        : event + "." + EventsWriter.connectorDataField(d.name());
                c.line(javaType(d.type().name(), scope) + " d_" + d.name() + " = " + init + ";");
            }
        }

        void coordinatorLocals(Code c, long mask, int self) {
            ConnectorType t = p.connector();
            for (int q = 0; q < t.ports().size(); q++) {
                if ((mask & (1L << q)) == 0) {
                    continue;
                }
                Param param = t.ports().get(q);
                PortType pt = events.portType(t, param);
                PackageScope ptScope = new PackageScope(scope.workspace(), scope.owner(pt));
                for (Param v : pt.params()) {
                    String value = q == self ? boundField(p.port(), v.name())
                            : "offers[" + q + "]." + EventsWriter.dataField(param.name(), v.name());
                    c.line(javaType(v.type().name(), ptScope) + " " + local(param.name(), v.name()) + " = " + value + ";");
                }
            }
            for (DataDecl d : t.data()) {
                c.line(javaType(d.type().name(), scope) + " d_" + d.name() + " = " + defaultValue(d.type().name()) + ";");
            }
        }

        private String defaultValue(String bipType) {
            Type t = scope.resolveType(bipType);
            return t == null ? "null" : switch (t.kind()) {
                case INT -> "0";
                case FLOAT -> "0.0";
                case BOOL -> "false";
                case STRING -> "\"\"";
                default -> "null";
            };
        }

        void body(Code c, ConnectorType.Interaction clause, String reject) {
            ExprWriter w = new ExprWriter(typer, names, new Mapper());
            if (clause.guard() != null) {
                c.open("if (!" + w.expr(clause.guard()) + ")").line(reject).close();
            }
            if (clause.up() != null) {
                w.statements(c, clause.up().stmts());
            }
            if (clause.down() != null) {
                w.statements(c, clause.down().stmts());
            }
        }

        private final class Mapper implements ExprWriter.Mapper {
            @Override
            public String read(Symbol s, Expr.Var v) {
                if (s.kind() == Symbol.Kind.CONST) {
                    Object value = ConstantFolder.fold(v, scope);
                    return value instanceof String str ? JavaNames.literal(str) : String.valueOf(value);
                }
                if (v.qualifier() == null) {
                    return "d_" + v.name();
                }
                return portData(v, true);
            }

            @Override
            public String write(Symbol s, Expr.Var v) {
                if (v.qualifier() == null) {
                    return "d_" + v.name();
                }
                if (!role.equals("coordinator") && !v.qualifier().equals(own)) {
                    return null;
                }
                return portData(v, false);
            }

            private String portData(Expr.Var v, boolean reading) {
                if (role.equals("coordinator")) {
                    return local(v.qualifier(), v.name());
                }
                if (v.qualifier().equals(own)) {
                    return boundField(p.port(), v.name());
                }
                if (visible.contains(v.qualifier()) && eventVar != null) {
                    return eventVar + "." + EventsWriter.dataField(v.qualifier(), v.name());
                }
                diagnostics.error(v.pos(), "cannot generate the " + role + " side of connector type "
                        + p.connector().name() + ": " + v.text() + " is data of a port this side does not know on the "
                        + "event bus (a broadcast's guard and transfers may use the trigger's port, the receiver's own "
                        + "port and connector data)");
                return "null";
            }

            @Override
            public String call(ResolvedCall call, List<String> args) {
                return "bipExterns." + JavaNames.id(call.name()) + "(" + String.join(", ", args) + ")";
            }
        }
    }
}
