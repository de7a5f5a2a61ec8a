package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.check.Interactions;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Param;

/**
 * Writes the parts a behaviour's instances play in connectors (see {@link BusPlan}): a broadcast's trigger and
 * receivers, a rendezvous' participants and coordinator.
 */
final class RoleWriter {

    private final BehaviourWriter w;

    RoleWriter(BehaviourWriter w) {
        this.w = w;
    }

    void initiate(Code c, BusPlan.PortPlan p) {
        ConnectorType t = p.connector();
        String type = w.events.eventClass(t);
        c.line("/** Fires trigger port " + p.port().name() + " alone and publishes the interaction. */");
        c.open("private boolean initiate" + BehaviourWriter.suffix(p) + "(Group g, int i)");
        c.open("if (CONNECTOR_" + BehaviourWriter.suffix(p) + "[i] == null)").line("return false;").close();
        c.line(type + " e = new " + type + "();");
        c.line("e.group = g.wire;");
        c.line("e.connector = CONNECTOR_" + BehaviourWriter.suffix(p) + "[i];");
        c.open("switch (PARAM_" + BehaviourWriter.suffix(p) + "[i])");
        for (int j : distinct(p, BusPlan.Role.INITIATOR)) {
            String jName = t.ports().get(j).name();
            c.open("case " + j + ":");
            c.line("e.initiator = " + JavaNames.literal(jName) + ";");
            c.line("e.participants.add(" + JavaNames.literal(jName) + ");");
            ConnectorType.Interaction clause = Interactions.clause(t, 1L << j);
            ConnectorCode code = new ConnectorCode(w, p, jName, Set.of(jName), "initiator");
            code.locals(c, null);
            if (clause != null) {
                code.body(c, clause, "return false;");
            }
            for (Param v : w.portVars(p.port())) {
                c.line("e." + EventsWriter.dataField(jName, v.name()) + " = " + w.boundField(p.port(), v.name()) + ";");
            }
            for (DataDecl d : t.data()) {
                c.line("e." + EventsWriter.connectorDataField(d.name()) + " = d_" + d.name() + ";");
            }
            c.line("break;").close();
        }
        c.line("default: return false;");
        c.close();
        c.line("fire(g, i, " + w.port(p) + ");");
        c.line("bus.deliver(e);");
        c.line("return true;");
        c.close().blank();
    }

    void receive(Code c, BusPlan.PortPlan p) {
        ConnectorType t = p.connector();
        String type = w.events.eventClass(t);
        BusPlan.ConnectorPlan cp = w.plan.plan(t);
        c.line("/** A broadcast of " + t.name() + " arrived: synchron port " + p.port().name() + " joins if ready. */");
        c.open("private void receive" + BehaviourWriter.suffix(p) + "(Group g, " + type + " e)");
        c.open("for (int i = 0; i < g.atoms.length; i++)");
        c.open("if (ROLE_" + BehaviourWriter.suffix(p) + "[i] != " + BehaviourWriter.roleCode(BusPlan.Role.RECEIVER) + " || e.connector == null"
                + " || !e.connector.equals(CONNECTOR_" + BehaviourWriter.suffix(p) + "[i]) || g.waiting[i] != null)")
                .line("continue;").close();
        c.line("enter(g, i);");
        c.open("if (!g.atoms[i].enabledPorts().contains(" + w.port(p) + "))").line("continue;").close();
        c.line("boolean joins = false;");
        c.open("switch (PARAM_" + BehaviourWriter.suffix(p) + "[i])");
        for (int r : distinct(p, BusPlan.Role.RECEIVER)) {
            String rName = t.ports().get(r).name();
            c.open("case " + r + ":");
            for (int j = 0; j < t.ports().size(); j++) {
                if ((cp.initiators() & (1L << j)) == 0 || j == r) {
                    continue;
                }
                String jName = t.ports().get(j).name();
                ConnectorType.Interaction clause = receiverClause(t, j, r);
                c.open("if (" + JavaNames.literal(jName) + ".equals(e.initiator))");
                ConnectorCode code = new ConnectorCode(w, p, rName, Set.of(jName, rName), "receiver");
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
        c.line("fire(g, i, " + w.port(p) + ");");
        c.line("run(g, i);");
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

    void participate(Code c, BusPlan.PortPlan p) {
        ConnectorType t = p.connector();
        String offer = w.events.offerClass(t);
        String type = w.events.eventClass(t);
        c.line("/** Port " + p.port().name() + " is ready: offer it to the coordinator of " + t.name() + " and wait. */");
        c.open("private boolean offer" + BehaviourWriter.suffix(p) + "(Group g, int i)");
        c.open("if (CONNECTOR_" + BehaviourWriter.suffix(p) + "[i] == null)").line("return false;").close();
        c.line(offer + " o = new " + offer + "();");
        c.line("o.group = g.wire;");
        c.line("o.connector = CONNECTOR_" + BehaviourWriter.suffix(p) + "[i];");
        c.line("o.component = COMPONENTS[i];");
        c.open("switch (PARAM_" + BehaviourWriter.suffix(p) + "[i])");
        for (int j : distinct(p, BusPlan.Role.PARTICIPANT)) {
            String jName = t.ports().get(j).name();
            c.open("case " + j + ":");
            c.line("o.port = " + JavaNames.literal(jName) + ";");
            for (Param v : w.portVars(p.port())) {
                c.line("o." + EventsWriter.dataField(jName, v.name()) + " = " + w.boundField(p.port(), v.name()) + ";");
            }
            c.line("break;").close();
        }
        c.line("default: return false;");
        c.close();
        c.line("g.waiting[i] = o.connector;");
        c.line("bus.deliver(o);");
        c.line("return true;");
        c.close().blank();
        c.line("/** The coordinator of " + t.name() + " fired: take part if this instance was in the interaction. */");
        c.open("private void complete" + BehaviourWriter.suffix(p) + "(Group g, " + type + " e)");
        c.open("for (int i = 0; i < g.atoms.length; i++)");
        c.open("if (ROLE_" + BehaviourWriter.suffix(p) + "[i] != " + BehaviourWriter.roleCode(BusPlan.Role.PARTICIPANT) + " || e.connector == null"
                + " || !e.connector.equals(g.waiting[i]) || !e.connector.equals(CONNECTOR_" + BehaviourWriter.suffix(p) + "[i]))")
                .line("continue;").close();
        c.open("switch (PARAM_" + BehaviourWriter.suffix(p) + "[i])");
        for (int j : distinct(p, BusPlan.Role.PARTICIPANT)) {
            String jName = t.ports().get(j).name();
            c.open("case " + j + ":");
            c.open("if (!e.participants.contains(" + JavaNames.literal(jName) + "))").line("continue;").close();
            for (Param v : w.portVars(p.port())) {
                c.line(w.boundField(p.port(), v.name()) + " = e." + EventsWriter.dataField(jName, v.name()) + ";");
            }
            c.line("break;").close();
        }
        c.line("default: continue;");
        c.close();
        c.line("g.waiting[i] = null;");
        c.line("fire(g, i, " + w.port(p) + ");");
        c.line("run(g, i);");
        c.close().close().blank();
    }

    void coordinate(Code c, BusPlan.PortPlan p) {
        ConnectorType t = p.connector();
        BusPlan.ConnectorPlan cp = w.plan.plan(t);
        String offer = w.events.offerClass(t);
        String type = w.events.eventClass(t);
        int self = cp.coordinator();
        String selfName = t.ports().get(self).name();
        List<Long> candidates = cp.interactions().stream().filter(m -> (m & (1L << self)) != 0).toList();
        c.line("/** An offer for " + t.name() + " arrived: keep it (the latest per port) and see whether to fire. */");
        c.open("private void collect" + BehaviourWriter.suffix(p) + "(Group g, " + offer + " o)");
        c.open("for (int i = 0; i < g.atoms.length; i++)");
        c.open("if (ROLE_" + BehaviourWriter.suffix(p) + "[i] != " + BehaviourWriter.roleCode(BusPlan.Role.COORDINATOR) + " || o.connector == null"
                + " || !o.connector.equals(CONNECTOR_" + BehaviourWriter.suffix(p) + "[i]))").line("continue;").close();
        c.line("int param = paramIndex" + BehaviourWriter.suffix(p) + "(o.port);");
        c.open("if (param < 0 || param == " + self + ")");
        c.line("LOG.log(System.Logger.Level.WARNING, \"offer for unknown port {0} of {1} ignored\", o.port, o.connector);");
        c.line("continue;").close();
        c.line("g.offers" + BehaviourWriter.suffix(p) + "[i][param] = o;");
        c.line("run(g, i);");
        c.close().close().blank();
        c.open("private static int paramIndex" + BehaviourWriter.suffix(p) + "(String port)");
        c.open("switch (String.valueOf(port))");
        for (int k = 0; k < t.ports().size(); k++) {
            c.line("case " + JavaNames.literal(t.ports().get(k).name()) + ": return " + k + ";");
        }
        c.line("default: return -1;");
        c.close().close().blank();
        c.line("/** Fires the largest complete interaction of " + t.name() + " (round robin among equals), if any. */");
        c.open("private boolean coordinate" + BehaviourWriter.suffix(p) + "(Group g, int i)");
        c.open("if (CONNECTOR_" + BehaviourWriter.suffix(p) + "[i] == null)").line("return false;").close();
        int k = 0;
        while (k < candidates.size()) {
            int size = Long.bitCount(candidates.get(k));
            int end = k;
            while (end < candidates.size() && Long.bitCount(candidates.get(end)) == size) {
                end++;
            }
            int count = end - k;
            c.open("for (int n = 0; n < " + count + "; n++)");
            c.line("int m = " + k + " + (g.rotation" + BehaviourWriter.suffix(p) + "[i] + n) % " + count + ";");
            c.open("if (interaction" + BehaviourWriter.suffix(p) + "(g, i, m))");
            c.line("g.rotation" + BehaviourWriter.suffix(p) + "[i] = m - " + k + " + 1;");
            c.line("return true;").close();
            c.close();
            k = end;
        }
        c.line("return false;");
        c.close().blank();
        c.open("private boolean interaction" + BehaviourWriter.suffix(p) + "(Group g, int i, int m)");
        c.line(offer + "[] offers = g.offers" + BehaviourWriter.suffix(p) + "[i];");
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
            ConnectorCode code = new ConnectorCode(w, p, selfName, new LinkedHashSet<>(members), "coordinator");
            code.coordinatorLocals(c, mask, self);
            ConnectorType.Interaction clause = Interactions.clause(t, mask);
            if (clause != null) {
                code.body(c, clause, "return false;");
            }
            for (Param v : w.portVars(p.port())) {
                c.line(w.boundField(p.port(), v.name()) + " = " + ConnectorCode.local(selfName, v.name()) + ";");
            }
            c.line(type + " e = new " + type + "();");
        c.line("e.group = g.wire;");
            c.line("e.connector = CONNECTOR_" + BehaviourWriter.suffix(p) + "[i];");
            c.line("e.initiator = " + JavaNames.literal(selfName) + ";");
            for (String member : members) {
                c.line("e.participants.add(" + JavaNames.literal(member) + ");");
                Param param = t.ports().get(Interactions.index(t, member));
                for (Param v : w.events.portType(t, param).params()) {
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
            c.line("fire(g, i, " + w.port(p) + ");");
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
}
