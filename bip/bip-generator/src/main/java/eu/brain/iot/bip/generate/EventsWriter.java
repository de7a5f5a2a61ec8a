package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortType;
import eu.brain.iot.bip.system.SystemModel.AtomInstance;
import eu.brain.iot.bip.system.SystemModel.ConnectorInstance;

/**
 * Writes the system's event types (public DTOs extending BrainIoTEvent): per connector type its interaction event
 * (and, for coordinated ones, its offer event), per external port its stimulus event, and {@code TransitionFired}
 * for traces.
 */
final class EventsWriter {

    static final Set<String> RESERVED = Set.of("connector", "initiator", "participants", "port", "component", "group",
            "sourceNode", "timestamp", "securityToken");

    private final BusPlan plan;
    private final String javaPackage;

    EventsWriter(BusPlan plan, String javaPackage) {
        this.plan = plan;
        this.javaPackage = javaPackage;
    }

    String javaPackage() {
        return javaPackage;
    }

    String eventClass(ConnectorType type) {
        return javaPackage + "." + JavaNames.type(type.name());
    }

    String offerClass(ConnectorType type) {
        return eventClass(type) + "Offer";
    }

    String externalClass(AtomType atom, String port) {
        return javaPackage + "." + JavaNames.type(atom.name()) + JavaNames.capital(port);
    }

    String traceClass() {
        return javaPackage + ".TransitionFired";
    }

    /** The event field holding variable {@code var} of connector port parameter {@code param}. */
    static String dataField(String param, String var) {
        return JavaNames.field(param, var);
    }

    /** The event field holding connector data {@code name}. */
    static String connectorDataField(String name) {
        String id = JavaNames.id(name);
        return RESERVED.contains(id) ? id + "_" : id;
    }

    /** The event field of an external port event for port type parameter {@code name}. */
    static String externalField(String name) {
        return connectorDataField(name);
    }

    PackageScope scope(ConnectorType type) {
        return plan.system().connectors().stream().filter(k -> k.type() == type).map(ConnectorInstance::scope)
                .findFirst().orElseThrow();
    }

    /** @return the port type of a connector parameter, resolved where the connector type is declared */
    PortType portType(ConnectorType type, Param param) {
        return scope(type).portType(param.type().name()).orElseThrow();
    }

    List<JavaFile> write(eu.brain.iot.bip.diag.Diagnostics diagnostics) {
        List<JavaFile> files = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (BusPlan.ConnectorPlan cp : plan.connectorPlans()) {
            ConnectorType t = cp.type();
            files.add(connectorEvent(t, simple(eventClass(t)), false));
            if (cp.mode() == BusPlan.Mode.COORDINATED) {
                files.add(connectorEvent(t, simple(offerClass(t)), true));
            }
        }
        Set<AtomType> atoms = new java.util.LinkedHashSet<>();
        plan.system().atoms().stream().map(AtomInstance::type).forEach(atoms::add);
        for (AtomType atom : atoms) {
            PackageScope scope = plan.instances(atom).get(0).scope();
            for (BusPlan.PortPlan pp : plan.ports(atom)) {
                if (pp.role() == BusPlan.Role.EXTERNAL) {
                    files.add(externalEvent(atom, pp, scope));
                }
            }
        }
        files.add(trace());
        for (JavaFile f : files) {
            if (!names.add(f.className())) {
                diagnostics.error(plan.system().root().pos(), "two generated event types would be named "
                        + f.className() + "; rename a connector type, atom type or port");
            }
        }
        return files;
    }

    private static String simple(String qualified) {
        return qualified.substring(qualified.lastIndexOf('.') + 1);
    }

    private Code header(String comment, String name) {
        Code c = new Code();
        c.line("package " + javaPackage + ";").blank();
        c.line("/**");
        for (String l : comment.split("\n")) {
            c.line(" * " + l);
        }
        c.line(" * Generated: do not edit.");
        c.line(" */");
        c.line("@javax.annotation.processing.Generated(\"eu.brain.iot.bip\")");
        c.open("public class " + name + " extends eu.brain.iot.eventing.api.BrainIoTEvent");
        return c;
    }

    private JavaFile connectorEvent(ConnectorType t, String name, boolean offer) {
        PackageScope scope = scope(t);
        Code c = header(offer
                ? "A component's offer to take part in an interaction of connector type {@code " + t.name() + "}:\n"
                        + "its port is ready and it waits for the coordinator's {@link " + JavaNames.type(t.name()) + "}."
                : "An interaction of connector type {@code " + t.name() + "} (" + JavaNames.fileName(t.pos()) + ") has fired.\n"
                        + "Each participant reads the data of its own port parameter (after the 'down' transfer).", name);
        c.line("/** The connector instance, e.g. {@code Connector2}. */");
        c.line("public String connector;");
        group(c);
        if (offer) {
            c.line("/** The port parameter of the offering component, e.g. {@code p1}. */");
            c.line("public String port;");
            c.line("/** The offering component instance, e.g. {@code Robot1}. */");
            c.line("public String component;");
        } else {
            c.line("/** The port parameter whose component published this event (a trigger or the coordinator). */");
            c.line("public String initiator;");
            c.line("/** The port parameters that took part, e.g. [p1, p2, p3, p4]. */");
            c.line("public java.util.List<String> participants = new java.util.ArrayList<>();");
        }
        for (Param p : t.ports()) {
            PortType pt = portType(t, p);
            for (Param v : pt.params()) {
                PackageScope ptScope = new PackageScope(scope.workspace(), scope.owner(pt));
                Type type = ptScope.resolveType(v.type().name());
                c.line("/** {@code " + p.name() + "." + v.name() + "} */");
                c.line("public " + JavaNames.javaType(type == null ? Type.ERROR : type, ptScope) + " "
                        + dataField(p.name(), v.name()) + ";");
            }
        }
        if (!offer) {
            for (DataDecl d : t.data()) {
                Type type = scope.resolveType(d.type().name());
                c.line("/** Connector data {@code " + d.name() + "} as the publisher computed it. */");
                c.line("public " + JavaNames.javaType(type == null ? Type.ERROR : type, scope) + " "
                        + connectorDataField(d.name()) + ";");
            }
        }
        c.close();
        return new JavaFile(javaPackage, name, c.toString());
    }

    /** The group field every generated event has (see bip/README.md, "Groups"). */
    private static void group(Code c) {
        c.line("/** The group (copy of the root compound) the event belongs to; null or empty: the default group. */");
        c.line("public String group;");
    }

    private JavaFile externalEvent(AtomType atom, BusPlan.PortPlan pp, PackageScope atomScope) {
        String name = simple(externalClass(atom, pp.port().name()));
        PortType pt = atomScope.portType(pp.port().portType()).orElseThrow();
        PackageScope ptScope = new PackageScope(atomScope.workspace(), atomScope.owner(pt));
        Code c = header("Fires port {@code " + pp.port().name() + "} of atom type {@code " + atom.name()
                + "} from outside the model (no connector binds it):\nwhen the port is enabled, its data takes these "
                + "values and its transition fires; otherwise the event is ignored.", name);
        group(c);
        c.line("/** The component instance, e.g. {@code Robot1}; null or empty for every instance. */");
        c.line("public String component;");
        for (Param v : pt.params()) {
            Type type = ptScope.resolveType(v.type().name());
            c.line("public " + JavaNames.javaType(type == null ? Type.ERROR : type, ptScope) + " "
                    + externalField(v.name()) + ";");
        }
        c.close();
        return new JavaFile(javaPackage, name, c.toString());
    }

    private JavaFile trace() {
        Code c = header("A transition fired in a generated behaviour; published only when the behaviour's\n"
                + "configuration sets {@code trace=true}.", "TransitionFired");
        group(c);
        c.line("/** The component instance, e.g. {@code Robot1}. */");
        c.line("public String component;");
        c.line("/** Its atom type, e.g. {@code Robot_behavior}. */");
        c.line("public String atomType;");
        c.line("/** The port, or {@code internal}. */");
        c.line("public String port;");
        c.line("/** The places marked before and after. */");
        c.line("public java.util.List<String> from = new java.util.ArrayList<>();");
        c.line("public java.util.List<String> to = new java.util.ArrayList<>();");
        c.close();
        return new JavaFile(javaPackage, "TransitionFired", c.toString());
    }
}
