package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.system.SystemModel.AtomInstance;

/**
 * Writes the group part of a generated behaviour (see bip/README.md, "Groups"): the root compound is replicated once
 * per group named by events' {@code group} field; each group is a {@code Group} object holding one full set of the
 * type's instances and their bus state (waiting flags, offers, remembered events). Also the configuration (a
 * component property type with {@code trace} and {@code max.groups}), the lazy creation of groups within that
 * bound, and the views {@code placesOf}, {@code dataOf} and {@code groups}.
 */
final class GroupWriter {

    /** Default of {@code max.groups}. */
    static final int MAX_GROUPS = 1024;

    private final BehaviourWriter w;
    private final AtomType atom;
    private final Generator.AtomNames names;
    private final List<AtomInstance> instances;
    private final List<BusPlan.PortPlan> ports;
    private final PackageScope atomScope;

    GroupWriter(BehaviourWriter w, AtomType atom, Generator.AtomNames names, List<AtomInstance> instances,
            List<BusPlan.PortPlan> ports) {
        this.w = w;
        this.atom = atom;
        this.names = names;
        this.instances = instances;
        this.ports = ports;
        this.atomScope = instances.get(0).scope();
    }

    /** The component property type and the fields of the behaviour. */
    void fields(Code c, String cls) {
        c.line("/** Configuration (PID = this class's name); a component property type. */");
        c.open("public @interface Config");
        c.line("/** @return whether every transition publishes a TransitionFired event */");
        c.line("boolean trace() default false;");
        c.line("/**");
        c.line(" * @return property {@code max.groups}: how many groups (copies of the root compound, the default one");
        c.line(" *         included) this behaviour hosts at most; an event naming a further group is refused");
        c.line(" */");
        c.line("int max_groups() default " + MAX_GROUPS + ";");
        c.close().blank();
        c.line("private final eu.brain.iot.eventing.api.EventBus bus;");
        c.line("private final boolean trace;");
        c.line("private final int maxGroups;");
        if (names.hasExterns()) {
            c.line("private final " + names.externs() + " bipExterns;");
        }
        c.line("/** The groups by name (\"\" is the default group), in creation order. */");
        c.line("private final java.util.Map<String, Group> groups = new java.util.LinkedHashMap<>();");
        c.line("/** Groups refused for the bound, each logged once (at most " + MAX_GROUPS + " remembered). */");
        c.line("private final java.util.Set<String> refused = new java.util.HashSet<>();");
        c.blank();
        group(c);
    }

    /** The Group class: one copy of the instances of this type in the root compound, with their bus state. */
    private void group(Code c) {
        String atomClass = names.atomClass();
        c.line("/** One copy of the root compound's instances of this type (a group) and their bus state. */");
        c.open("private final class Group");
        c.line("/** The group's name; \"\" for the default group. */");
        c.line("final String name;");
        c.line("/** What the group's events carry in their group field: null for the default group. */");
        c.line("final String wire;");
        c.line("/** The atom instances, by index into COMPONENTS. */");
        c.line("final " + atomClass + "[] atoms = new " + atomClass + "[COMPONENTS.length];");
        c.line("/** Per instance: the connector it offered to and now waits for, or null. */");
        c.line("final String[] waiting = new String[COMPONENTS.length];");
        for (BusPlan.PortPlan p : ports) {
            if (p.has(BusPlan.Role.COORDINATOR)) {
                String offer = w.events.offerClass(p.connector());
                c.line("/** Per instance and port parameter: the offers collected for port " + p.port().name() + ". */");
                c.line("final " + offer + "[][] offers" + BehaviourWriter.suffix(p) + " = new " + offer
                        + "[COMPONENTS.length][" + p.connector().ports().size() + "];");
                c.line("final int[] rotation" + BehaviourWriter.suffix(p) + " = new int[COMPONENTS.length];");
            }
            if (p.role() == BusPlan.Role.EXTERNAL && p.port().isExtern()
                    && p.port().extern().policy().effective() == PortDecl.Policy.REMEMBER) {
                String queue = "java.util.ArrayDeque<" + w.events.externalClass(atom, p.port().name()) + ">";
                c.line("/** Per instance: events for extern port " + p.port().name() + " that came before it was enabled. */");
                c.line("final java.util.Map<Integer, " + queue + "> pending" + BehaviourWriter.suffix(p)
                        + "Queues = new java.util.HashMap<>();");
            }
        }
        c.blank();
        c.line("/** @return instance i for messages: Robot1, or Robot1 of group A */");
        c.open("String who(int i)");
        c.line("return name.isEmpty() ? COMPONENTS[i] : COMPONENTS[i] + \" of group \" + name;");
        c.close().blank();
        c.line("/** Creates the instances, which run their initial transitions (group() then lets them run on). */");
        c.open("Group(String name)");
        c.line("this.name = name;");
        c.line("this.wire = name.isEmpty() ? null : name;");
        for (int k = 0; k < instances.size(); k++) {
            AtomInstance a = instances.get(k);
            List<String> args = new ArrayList<>();
            if (names.hasExterns()) {
                args.add("bipExterns");
                c.line("bipExterns.bipInstance(name, COMPONENTS[" + k + "]);");
            }
            for (int i = 0; i < atom.params().size(); i++) {
                args.add(literal(i < a.args().size() ? a.args().get(i) : null, atom.params().get(i).type().name()));
            }
            c.line("atoms[" + k + "] = new " + atomClass + "(" + String.join(", ", args) + ");");
        }
        c.close().close().blank();
    }

    /** The constructors: DS's, with the property type, and a plain one with a map for use without DS. */
    void constructors(Code c, String cls) {
        String externsParam = names.hasExterns() ? " " + names.externs() + " externs," : "";
        String externsArg = names.hasExterns() ? " externs," : "";
        c.line("/**");
        c.line(" * Creates the default group's instances and runs their initial transitions, then whatever they can do");
        c.line(" * on their own; other groups are created when an event first names them.");
        c.line(" *");
        c.line(" * @param bus the event bus");
        if (names.hasExterns()) {
            c.line(" * @param externs the hand-written extern functions");
        }
        c.line(" * @param config the configuration");
        c.line(" */");
        c.line("@org.osgi.service.component.annotations.Activate");
        c.open("public " + cls + "(@org.osgi.service.component.annotations.Reference eu.brain.iot.eventing.api.EventBus bus,"
                + (names.hasExterns() ? " @org.osgi.service.component.annotations.Reference" + externsParam : "")
                + " Config config)");
        c.line("this.bus = java.util.Objects.requireNonNull(bus, \"bus\");");
        c.line("this.trace = config.trace();");
        c.open("if (config.max_groups() < 1)");
        c.line("LOG.log(System.Logger.Level.ERROR, \"max.groups is {0}; it must be at least 1 (the default group): 1 is "
                + "used\", String.valueOf(config.max_groups()));");
        c.close();
        c.line("this.maxGroups = Math.max(1, config.max_groups());");
        if (names.hasExterns()) {
            c.line("this.bipExterns = java.util.Objects.requireNonNull(externs, \"externs\");");
        }
        c.open("synchronized (this)");
        c.line("group(\"\");");
        c.close().close().blank();
        c.line("/**");
        c.line(" * For use without Declarative Services (tests, tools): the configuration as a map of component properties");
        c.line(" * ({@code trace}, {@code max.groups}); a value that is not a number is logged and the default used.");
        c.line(" *");
        c.line(" * @param bus the event bus");
        if (names.hasExterns()) {
            c.line(" * @param externs the hand-written extern functions");
        }
        c.line(" * @param config component properties");
        c.line(" */");
        c.open("public " + cls + "(eu.brain.iot.eventing.api.EventBus bus," + externsParam
                + " java.util.Map<String, Object> config)");
        c.line("this(bus," + externsArg + " config(config));");
        c.close().blank();
        c.open("private static Config config(java.util.Map<String, Object> properties)");
        c.line("boolean trace = Boolean.parseBoolean(String.valueOf(properties.getOrDefault(\"trace\", \"false\")));");
        c.line("int max = " + MAX_GROUPS + ";");
        c.line("Object value = properties.get(\"max.groups\");");
        c.open("if (value != null)");
        c.open("try");
        c.line("max = Integer.parseInt(String.valueOf(value).trim());");
        c.middle("} catch (NumberFormatException notANumber) {");
        c.line("LOG.log(System.Logger.Level.ERROR, \"max.groups is {0}, not a whole number: {1} is used\", value, String.valueOf(max));");
        c.close();
        c.close();
        c.line("int maxGroups = max;");
        c.open("return new Config()");
        c.line("@Override");
        c.open("public boolean trace()").line("return trace;").close();
        c.line("@Override");
        c.open("public int max_groups()").line("return maxGroups;").close();
        c.line("@Override");
        c.open("public Class<? extends java.lang.annotation.Annotation> annotationType()").line("return Config.class;").close();
        c.close("};");
        c.close().blank();
    }

    /** group(name): the group, created (and started) the first time; null when refused for the bound. */
    void lookup(Code c) {
        String atomClass = names.atomClass();
        c.line("/** @return the group named (null or \"\": the default), created on first use; null beyond max.groups */");
        c.open("private Group group(String name)");
        c.line("String key = name == null ? \"\" : name;");
        c.line("Group g = groups.get(key);");
        c.open("if (g != null)").line("return g;").close();
        c.open("if (groups.size() >= maxGroups)");
        c.open("if (refused.size() < " + MAX_GROUPS + " && refused.add(key))");
        c.line("LOG.log(System.Logger.Level.ERROR, \"events of group \\\"{0}\\\" are refused: this behaviour already hosts "
                + "max.groups={1} groups; configure a larger max.groups (PID {2}) to host more\", key, String.valueOf(maxGroups), "
                + "getClass().getName());");
        c.close();
        c.line("return null;");
        c.close();
        c.line("g = new Group(key);");
        c.line("groups.put(key, g);");
        c.open("for (int i = 0; i < COMPONENTS.length; i++)");
        c.open("if (trace)").line("publishTrace(g, i, \"initial\", java.util.EnumSet.noneOf(" + atomClass + ".Place.class));")
                .close();
        c.line("run(g, i);").close();
        c.line("return g;");
        c.close().blank();
        c.line("/** Tells the externs which instance the calls that follow are for. */");
        c.open("private void enter(Group g, int i)");
        if (names.hasExterns()) {
            c.line("bipExterns.bipInstance(g.name, COMPONENTS[i]);");
        }
        c.close().blank();
    }

    /** placesOf, dataOf (default group and named group) and groups(). */
    void views(Code c) {
        c.line("/** @return the marked places of a component of the default group, e.g. [START], or null if not hosted here */");
        c.open("public synchronized java.util.List<String> placesOf(String component)");
        c.line("return placesOf(\"\", component);");
        c.close().blank();
        c.line("/** @return the marked places of a component of a group (null or \"\": the default), or null if there is none */");
        c.open("public synchronized java.util.List<String> placesOf(String group, String component)");
        c.line(names.atomClass() + " a = atom(group, component);");
        c.open("if (a == null)").line("return null;").close();
        c.line("java.util.List<String> places = new java.util.ArrayList<>();");
        c.line("a.marking().forEach(x -> places.add(x.name()));");
        c.line("return places;");
        c.close().blank();
        c.line("/** @return the data of a component of the default group by name, or null if it is not hosted here */");
        c.open("public synchronized java.util.Map<String, Object> dataOf(String component)");
        c.line("return dataOf(\"\", component);");
        c.close().blank();
        c.line("/** @return the data of a component of a group (null or \"\": the default) by name, or null if there is none */");
        c.open("public synchronized java.util.Map<String, Object> dataOf(String group, String component)");
        c.line(names.atomClass() + " a = atom(group, component);");
        c.line("return a == null ? null : a.data();");
        c.close().blank();
        c.open("private " + names.atomClass() + " atom(String group, String component)");
        c.line("Group g = groups.get(group == null ? \"\" : group);");
        c.open("for (int i = 0; g != null && i < COMPONENTS.length; i++)");
        c.open("if (COMPONENTS[i].equals(component))").line("return g.atoms[i];").close().close();
        c.line("return null;");
        c.close().blank();
        c.line("/** @return the groups this behaviour hosts, in creation order; \"\" is the default group */");
        c.open("public synchronized java.util.List<String> groups()");
        c.line("return new java.util.ArrayList<>(groups.keySet());");
        c.close();
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
}
