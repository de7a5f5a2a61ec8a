package eu.brain.iot.bip.generate;

import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.check.ConstantFolder;
import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.LocalNames;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Symbol;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortType;

/**
 * Writes the guard, up and down of a connector clause for one role. Port data become locals
 * ({@code v_p1_position}), connector data {@code d_name}; what a role may not see is reported.
 */
final class ConnectorCode {
    private final BehaviourWriter w;
    private final BusPlan.PortPlan p;
    private final String own;
    private final Set<String> visible;
    private final String role;
    private final PackageScope scope;
    private final ExprTyper typer;
    private final LocalNames names;
    private String eventVar;

    ConnectorCode(BehaviourWriter w, BusPlan.PortPlan p, String own, Set<String> visible, String role) {
        this.w = w;
        this.p = p;
        this.own = own;
        this.visible = visible;
        this.role = role;
        this.scope = w.events.scope(p.connector());
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
            PortType pt = w.events.portType(t, param);
            PackageScope ptScope = new PackageScope(scope.workspace(), scope.owner(pt));
            for (Param v : pt.params()) {
                String value = q == self ? w.boundField(p.port(), v.name())
                        : "offers[" + q + "]." + EventsWriter.dataField(param.name(), v.name());
                c.line(javaType(v.type().name(), ptScope) + " " + local(param.name(), v.name()) + " = " + value + ";");
            }
        }
        for (DataDecl d : t.data()) {
            c.line(javaType(d.type().name(), scope) + " d_" + d.name() + " = " + defaultValue(d.type().name()) + ";");
        }
    }

    private String defaultValue(String bipType) {
        return JavaNames.defaultLiteral(scope.resolveType(bipType));
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
                return JavaNames.value(ConstantFolder.fold(v, scope));
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
                return w.boundField(p.port(), v.name());
            }
            if (visible.contains(v.qualifier()) && eventVar != null) {
                return eventVar + "." + EventsWriter.dataField(v.qualifier(), v.name());
            }
            w.diagnostics.error(v.pos(), "cannot generate the " + role + " side of connector type "
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
