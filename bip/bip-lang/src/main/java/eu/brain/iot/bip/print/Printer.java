package eu.brain.iot.bip.print;

import java.util.List;
import java.util.stream.Collectors;

import eu.brain.iot.bip.model.Annotation;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.Block;
import eu.brain.iot.bip.model.CompoundType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.ConstDecl;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Decl;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.ExternFunction;
import eu.brain.iot.bip.model.ExternOperator;
import eu.brain.iot.bip.model.ExternType;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.model.PortExpr;
import eu.brain.iot.bip.model.PortType;
import eu.brain.iot.bip.model.Stmt;
import eu.brain.iot.bip.model.TypeRef;

/**
 * Prints a model as canonical BIP2 text (standard keywords, {@code ==} for equality, one declaration per name), such
 * that parsing the text gives back an equal model.
 */
public final class Printer {

    private final StringBuilder out = new StringBuilder();
    private int indent;

    private Printer() {
    }

    public static String print(BipPackage pkg) {
        Printer p = new Printer();
        p.pkg(pkg);
        return p.out.toString();
    }

    public static String print(Expr e) {
        return expr(e);
    }

    private void line(String text) {
        out.append("  ".repeat(indent)).append(text).append('\n');
    }

    private void pkg(BipPackage pkg) {
        pkg.annotations().forEach(a -> line(annotation(a)));
        line("package " + pkg.name());
        indent++;
        pkg.uses().forEach(u -> line("use " + u.packageName()));
        for (Decl d : pkg.decls()) {
            if (d instanceof AtomType || d instanceof ConnectorType || d instanceof CompoundType) {
                out.append('\n');
            }
            d.annotations().forEach(a -> line(annotation(a)));
            decl(d);
        }
        indent--;
        line("end");
    }

    static String annotation(Annotation a) {
        if (a.params().isEmpty()) {
            return "@" + a.name();
        }
        return "@" + a.name() + "(" + a.params().stream().map(p -> p.value() == null ? p.key()
                : p.key() + "=" + (p.quoted() ? quote(p.value()) : p.value())).collect(Collectors.joining(", ")) + ")";
    }

    private void decl(Decl d) {
        if (d instanceof ConstDecl c) {
            line("const data " + c.type().name() + " " + c.name() + " = " + expr(c.value()));
        } else if (d instanceof ExternType t) {
            line("extern data type " + t.name() + (t.refines().isEmpty() ? "" : " refine " + String.join(", ", t.refines()))
                    + (t.backendName() == null ? "" : " as " + quote(t.backendName())));
        } else if (d instanceof ExternFunction f) {
            line("extern function " + (f.returnType() == null ? "" : f.returnType().name() + " ") + f.name()
                    + params(f.params()));
        } else if (d instanceof ExternOperator o) {
            line("extern operator " + o.returnType().name() + " " + o.operator() + "("
                    + o.params().stream().map(TypeRef::name).collect(Collectors.joining(", ")) + ")");
        } else if (d instanceof PortType p) {
            line("port type " + p.name() + params(p.params()));
        } else if (d instanceof AtomType a) {
            atom(a);
        } else if (d instanceof ConnectorType c) {
            connector(c);
        } else if (d instanceof CompoundType c) {
            compound(c);
        }
    }

    private static String params(List<Param> params) {
        return "(" + params.stream().map(p -> (p.constant() ? "const " : "") + p.type().name()
                + (p.name() == null ? "" : " " + p.name())).collect(Collectors.joining(", ")) + ")";
    }

    private void atom(AtomType a) {
        line("atom type " + a.name() + params(a.params()));
        indent++;
        for (DataDecl d : a.data()) {
            data(d);
        }
        for (AtomType.ClockDecl c : a.clocks()) {
            line("clock " + c.name() + (c.unit() == null ? "" : " unit " + c.unit()));
        }
        for (PortDecl p : a.ports()) {
            port(p);
        }
        if (!a.places().isEmpty()) {
            line("place " + a.places().stream().map(AtomType.Place::name).collect(Collectors.joining(", ")));
        }
        if (a.initial() != null) {
            line("initial to " + String.join(", ", a.initial().to()) + action("do", a.initial().action()));
        }
        for (AtomType.Transition t : a.transitions()) {
            t.annotations().forEach(x -> line(annotation(x)));
            line((t.internal() ? "internal" : "on " + t.port()) + " from " + String.join(", ", t.from()) + " to "
                    + String.join(", ", t.to()) + guard(t.guard())
                    + (t.urgency() == AtomType.Urgency.NONE ? "" : " " + t.urgency().name().toLowerCase(java.util.Locale.ROOT))
                    + action("do", t.action()) + (t.resume() ? " resume" : ""));
        }
        for (AtomType.Priority p : a.priorities()) {
            line("priority " + p.name() + " " + p.low() + " < " + p.high() + guard(p.guard()));
        }
        for (AtomType.Invariant i : a.invariants()) {
            line("invariant " + i.name() + (i.places().isEmpty() ? "" : " at " + String.join(", ", i.places()))
                    + " provided (" + expr(i.condition()) + ")");
        }
        indent--;
        line("end");
    }

    private void data(DataDecl d) {
        d.annotations().forEach(a -> line(annotation(a)));
        line((d.exported() ? "export " : "") + "data " + d.type().name() + " " + d.name()
                + (d.init() == null ? "" : " = " + expr(d.init())));
    }

    private void port(PortDecl p) {
        p.annotations().forEach(a -> line(annotation(a)));
        String extern = "";
        if (p.isExtern()) {
            extern = (p.extern().event() == null ? "" : " as " + quote(p.extern().event(), false))
                    + (p.extern().policy() == PortDecl.Policy.NONE ? ""
                            : " " + p.extern().policy().name().toLowerCase(java.util.Locale.ROOT));
        }
        line((p.exported() ? "export " : "") + (p.isExtern() ? "extern " : "") + "port " + p.portType() + " "
                + p.name() + "(" + String.join(", ", p.boundData()) + ")"
                + (p.mergedAs() == null ? "" : " as " + p.mergedAs()) + extern);
    }

    private static String guard(Expr guard) {
        return guard == null ? "" : " provided (" + expr(guard) + ")";
    }

    private String action(String keyword, Block block) {
        if (block == null) {
            return "";
        }
        return " " + keyword + " " + block(block);
    }

    private static String block(Block block) {
        if (block.stmts().isEmpty()) {
            return "{ }";
        }
        return "{ " + block.stmts().stream().map(Printer::stmt).collect(Collectors.joining(" ")) + " }";
    }

    private void connector(ConnectorType c) {
        line("connector type " + c.name() + params(c.ports()));
        indent++;
        c.data().forEach(this::data);
        if (c.exportPort() != null) {
            port(c.exportPort());
        }
        if (c.define() != null) {
            line("define " + portExprItems(c.define().items()));
        }
        for (ConnectorType.Interaction i : c.interactions()) {
            line("on " + String.join(" ", i.ports()) + guard(i.guard()) + action("up", i.up())
                    + action("down", i.down()));
        }
        indent--;
        line("end");
    }

    private static String portExprItems(List<PortExpr> items) {
        return items.stream().map(Printer::portExpr).collect(Collectors.joining(" "));
    }

    private static String portExpr(PortExpr e) {
        if (e instanceof PortExpr.Group g) {
            return "(" + portExprItems(g.items()) + ")" + (g.trigger() ? "'" : "");
        }
        PortExpr.Ref r = (PortExpr.Ref) e;
        return r.port() + (r.trigger() ? "'" : "");
    }

    private void compound(CompoundType c) {
        line("compound type " + c.name() + params(c.params()));
        indent++;
        for (CompoundType.Component k : c.components()) {
            k.annotations().forEach(a -> line(annotation(a)));
            line("component " + k.type() + " " + k.name() + "("
                    + k.args().stream().map(Printer::expr).collect(Collectors.joining(", ")) + ")");
        }
        for (CompoundType.Connector k : c.connectors()) {
            k.annotations().forEach(a -> line(annotation(a)));
            line("connector " + k.type() + " " + k.name() + "(" + refs(k.ports()) + ")");
        }
        for (CompoundType.Priority p : c.priorities()) {
            line("priority " + p.name() + " " + spec(p.low()) + " < " + spec(p.high()) + guard(p.guard()));
        }
        for (CompoundType.PortExport e : c.portExports()) {
            line("export port " + refs(e.ports()) + " as " + e.name());
        }
        for (CompoundType.DataExport e : c.dataExports()) {
            line("export data " + e.data() + " as " + e.name());
        }
        indent--;
        line("end");
    }

    private static String refs(List<CompoundType.PortRef> refs) {
        return refs.stream().map(CompoundType.PortRef::toString).collect(Collectors.joining(", "));
    }

    private static String spec(CompoundType.InteractionSpec s) {
        return s.connector() + ":" + (s.ports() == null ? "*" : refs(s.ports()));
    }

    // ---------------------------------------------------------------- actions

    static String stmt(Stmt s) {
        if (s instanceof Stmt.Assign a) {
            return a.target().text() + (a.primed() ? "'" : "") + " = " + expr(a.value()) + ";";
        }
        if (s instanceof Stmt.Call c) {
            return expr(c.call()) + ";";
        }
        Stmt.If i = (Stmt.If) s;
        return "if (" + expr(i.condition()) + ") then "
                + i.then().stream().map(Printer::stmt).collect(Collectors.joining(" "))
                + (i.otherwise().isEmpty() ? "" : " else "
                        + i.otherwise().stream().map(Printer::stmt).collect(Collectors.joining(" ")))
                + " fi";
    }

    static String expr(Expr e) {
        if (e instanceof Expr.IntLit i) {
            return Long.toString(i.value());
        } else if (e instanceof Expr.FloatLit f) {
            return Double.toString(f.value());
        } else if (e instanceof Expr.BoolLit b) {
            return Boolean.toString(b.value());
        } else if (e instanceof Expr.StringLit s) {
            return quote(s.value());
        } else if (e instanceof Expr.Var v) {
            return v.text();
        } else if (e instanceof Expr.Call c) {
            return c.text() + "(" + c.args().stream().map(Printer::expr).collect(Collectors.joining(", ")) + ")";
        } else if (e instanceof Expr.Unary u) {
            return u.op().symbol + (u.operand() instanceof Expr.Binary || u.operand() instanceof Expr.Unary
                    ? "(" + expr(u.operand()) + ")" : expr(u.operand()));
        }
        Expr.Binary b = (Expr.Binary) e;
        return operand(b.left(), b.op().prec, false) + " " + b.op().symbol + " " + operand(b.right(), b.op().prec, true);
    }

    private static String operand(Expr e, int prec, boolean right) {
        if (e instanceof Expr.Binary b && (b.op().prec < prec || (right && b.op().prec == prec))) {
            return "(" + expr(e) + ")";
        }
        return expr(e);
    }

    static String quote(String s) {
        return quote(s, false);
    }

    /**
     * A double-quoted literal with {@code \\ \" \n \t \r \0} escaped, as BIP and Java both read it.
     *
     * @param asciiOnly whether other characters outside printable ASCII become unicode escapes (for Java)
     */
    public static String quote(String s, boolean asciiOnly) {
        StringBuilder q = new StringBuilder("\"");
        for (char c : s.toCharArray()) {
            switch (c) {
                case '"' -> q.append("\\\"");
                case '\\' -> q.append("\\\\");
                case '\n' -> q.append("\\n");
                case '\t' -> q.append("\\t");
                case '\r' -> q.append("\\r");
                case '\0' -> q.append("\\0");
                default -> {
                    if (asciiOnly && (c < 0x20 || c > 0x7e)) {
                        q.append(String.format("\\u%04x", (int) c));
                    } else {
                        q.append(c);
                    }
                }
            }
        }
        return q.append('"').toString();
    }
}
