package eu.brain.iot.bip.parser;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.model.Annotation;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.AtomType.ClockDecl;
import eu.brain.iot.bip.model.AtomType.InitialTransition;
import eu.brain.iot.bip.model.AtomType.Invariant;
import eu.brain.iot.bip.model.AtomType.Place;
import eu.brain.iot.bip.model.AtomType.Priority;
import eu.brain.iot.bip.model.AtomType.Transition;
import eu.brain.iot.bip.model.AtomType.Urgency;
import eu.brain.iot.bip.model.Block;
import eu.brain.iot.bip.model.CompoundType;
import eu.brain.iot.bip.model.CompoundType.InteractionSpec;
import eu.brain.iot.bip.model.CompoundType.PortRef;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;
import eu.brain.iot.bip.model.PortExpr;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.model.TypeRef;
import eu.brain.iot.bip.parser.Token.Kind;
import eu.brain.iot.bip.parser.TokenCursor.SyntaxError;

/**
 * The bodies of atom, connector and compound types. Items may come in any order (real models mix them); each item
 * is parsed on its own so that an error in one does not hide errors in the next.
 */
final class BodyParser {

    private static final Set<String> ATOM_ITEMS = Set.of("data", "export", "port", "place", "places", "initial", "on",
            "internal", "priority", "clock", "invariant", "extern", "end", "@");
    private static final Set<String> CONNECTOR_ITEMS = Set.of("data", "export", "define", "on", "end", "@");
    private static final Set<String> COMPOUND_ITEMS = Set.of("component", "connector", "priority", "export", "end", "@");
    private static final Set<String> TRANSITION_CLAUSES = Set.of("from", "to", "provided", "do", "eager", "lazy",
            "delayable", "resume");
    private static final Set<String> POLICIES = Set.of("remember", "ignore", "error");

    private final TokenCursor in;
    private final ActionParser actions;
    private final Parser decls;

    BodyParser(TokenCursor in, ActionParser actions, Parser decls) {
        this.in = in;
        this.actions = actions;
        this.decls = decls;
    }

    /** Runs {@code item}; on a syntax error skips to the next item start. @return false at the type's end */
    private boolean item(Set<String> itemWords, Runnable item) {
        int start = in.mark();
        try {
            item.run();
        } catch (SyntaxError e) {
            in.resetDepth();
            in.syncUntil(() -> in.peek().is(Kind.IDENT) && itemWords.contains(in.peek().text())
                    || decls.atDeclarationStart(0), true, start);
        }
        return true;
    }

    /** @return true when the body continues; reports a missing 'end' when a new declaration starts instead */
    private boolean bodyContinues(String owner) {
        if (in.atWord("end")) {
            in.next();
            return false;
        }
        if (in.atEnd() || (decls.atDeclarationStart(0) && !in.at(Kind.AT))) {
            in.error(in.pos(), "expected 'end' to close " + owner + ", found " + in.peek().describe());
            return false;
        }
        return true;
    }

    // ---------------------------------------------------------------- atom types

    AtomType atomType(Pos pos, List<Annotation> annotations) {
        String name = in.qualifiedName("an atom type name after 'atom type'");
        String owner = "atom type " + name;
        List<Param> params = decls.params(owner, true);
        List<DataDecl> data = new ArrayList<>();
        List<ClockDecl> clocks = new ArrayList<>();
        List<PortDecl> ports = new ArrayList<>();
        List<Place> places = new ArrayList<>();
        List<InitialTransition> initial = new ArrayList<>();
        List<Transition> transitions = new ArrayList<>();
        List<Priority> priorities = new ArrayList<>();
        List<Invariant> invariants = new ArrayList<>();
        while (bodyContinues(owner)) {
            item(ATOM_ITEMS, () -> {
                List<Annotation> itemAnnotations = decls.annotations();
                Pos itemPos = in.pos();
                boolean exported = in.acceptWord("export");
                if (in.acceptWord("data")) {
                    data.addAll(dataDecl(itemPos, itemAnnotations, exported));
                } else if (in.acceptWord("port")) {
                    ports.addAll(portDecl(itemPos, itemAnnotations, exported, true));
                } else if (in.acceptWord("extern")) {
                    in.expectWord("port", "after 'extern' in an atom (write 'extern port T p(x) as \"event\"')");
                    ports.addAll(externPortDecl(itemPos, itemAnnotations, exported));
                } else if (exported) {
                    throw in.fail("expected 'data', 'port' or 'extern port' after 'export', found "
                            + in.peek().describe());
                } else if (in.acceptWord("place") || in.acceptWord("places")) {
                    do {
                        Pos placePos = in.pos();
                        places.add(new Place(placePos, in.ident("a place name")));
                    } while (in.accept(Kind.COMMA));
                } else if (in.acceptWord("initial")) {
                    in.expectWord("to", "after 'initial'");
                    List<String> to = in.identList("an initial place after 'initial to'");
                    Block action = in.acceptWord("do") ? actions.block("after 'do'") : null;
                    initial.add(new InitialTransition(itemPos, to, action));
                } else if (in.acceptWord("on")) {
                    String port = in.ident("a port name after 'on'");
                    transitions.add(transition(itemPos, itemAnnotations, port));
                } else if (in.acceptWord("internal")) {
                    transitions.add(transition(itemPos, itemAnnotations, null));
                } else if (in.acceptWord("priority")) {
                    priorities.add(atomPriority(itemPos));
                } else if (in.acceptWord("clock")) {
                    List<String> names = in.identList("a clock name");
                    String unit = in.acceptWord("unit") ? in.ident("a time unit after 'unit'") : null;
                    names.forEach(n -> clocks.add(new ClockDecl(itemPos, n, unit)));
                } else if (in.acceptWord("invariant")) {
                    String invName = in.ident("an invariant name");
                    List<String> at = List.of();
                    if (in.acceptWord("at") || in.acceptWord("from")) {
                        if (in.atWord("provided")) {
                            throw in.fail("expected a place name of invariant " + invName + ", found 'provided'");
                        }
                        at = in.identList("a place name of invariant " + invName);
                    }
                    in.expectWord("provided", "in invariant " + invName + " (write 'invariant " + invName
                            + " [at P1, P2] provided (condition)')");
                    invariants.add(new Invariant(itemPos, invName, at, actions.expression()));
                } else {
                    throw in.fail("expected an atom item ('data', 'port', 'extern port', 'place', 'initial', 'on', "
                            + "'internal', 'priority', 'clock', 'invariant' or 'end'), found " + in.peek().describe());
                }
            });
        }
        if (initial.size() > 1) {
            in.error(initial.get(1).pos(), owner + " has more than one initial transition");
        }
        InitialTransition init = initial.isEmpty() ? null : initial.get(0);
        return new AtomType(pos, annotations, name, params, data, clocks, ports, places, init, transitions, priorities,
                invariants);
    }

    private List<DataDecl> dataDecl(Pos pos, List<Annotation> annotations, boolean exported) {
        TypeRef type = decls.type("a data type after 'data'");
        List<DataDecl> list = new ArrayList<>();
        do {
            Pos namePos = in.pos();
            String name = in.ident("a data name after type " + type.name());
            Expr init = in.accept(Kind.ASSIGN) ? actions.expression() : null;
            list.add(new DataDecl(namePos, annotations, exported, type, name, init));
        } while (in.accept(Kind.COMMA));
        return list;
    }

    /** {@code PortType p(x, y), q(z) [as merged]}; parentheses may be left out when no data is bound. */
    private List<PortDecl> portDecl(Pos pos, List<Annotation> annotations, boolean exported, boolean several) {
        String type = in.qualifiedName("a port type after 'port'");
        List<String[]> named = new ArrayList<>();
        List<List<String>> bound = new ArrayList<>();
        do {
            String name = in.ident("a port name after port type " + type);
            List<String> data = new ArrayList<>();
            if (in.accept(Kind.LPAREN)) {
                if (!in.at(Kind.RPAREN)) {
                    data.addAll(in.identList("a data name bound to port " + name));
                }
                in.expect(Kind.RPAREN, "to close the data of port " + name);
            }
            named.add(new String[] {name});
            bound.add(data);
        } while (several && in.accept(Kind.COMMA));
        String merged = in.acceptWord("as") ? in.ident("the merged port name after 'as'") : null;
        List<PortDecl> list = new ArrayList<>();
        for (int i = 0; i < named.size(); i++) {
            list.add(new PortDecl(pos, annotations, exported, type, named.get(i)[0], bound.get(i), merged));
        }
        return list;
    }

    /**
     * {@code extern port PortType p(x) [as "event"] [remember|ignore|error]}: one port, fed by the environment. The
     * policy says what becomes of an event that arrives when the port cannot take it.
     */
    private List<PortDecl> externPortDecl(Pos pos, List<Annotation> annotations, boolean exported) {
        String type = in.qualifiedName("a port type after 'extern port'");
        String name = in.ident("a port name after port type " + type);
        List<String> data = new ArrayList<>();
        if (in.accept(Kind.LPAREN)) {
            if (!in.at(Kind.RPAREN)) {
                data.addAll(in.identList("a data name bound to port " + name));
            }
            in.expect(Kind.RPAREN, "to close the data of port " + name);
        }
        String event = null;
        if (in.acceptWord("as")) {
            event = in.expect(Kind.STRING, "after 'as' in extern port " + name + " (the event's name, in quotes)")
                    .text();
        }
        PortDecl.Policy policy = PortDecl.Policy.NONE;
        if (in.atAnyWord(POLICIES)) {
            policy = PortDecl.Policy.valueOf(in.next().text().toUpperCase(java.util.Locale.ROOT));
        }
        return List.of(new PortDecl(pos, annotations, exported, type, name, data, null,
                new PortDecl.Extern(event, policy)));
    }

    /** The clauses after {@code on p} or {@code internal}, in any order (the paper writes 'provided' first). */
    private Transition transition(Pos pos, List<Annotation> annotations, String port) {
        String what = port == null ? "internal transition" : "transition on " + port;
        List<String> from = null;
        List<String> to = null;
        Expr guard = null;
        Urgency urgency = Urgency.NONE;
        Block action = null;
        boolean resume = false;
        while (in.atAnyWord(TRANSITION_CLAUSES)) {
            Token clause = in.next();
            switch (clause.text()) {
                case "resume" -> resume = true;
                case "from" -> from = in.identList("a place name after 'from'");
                case "to" -> to = in.identList("a place name after 'to'");
                case "provided" -> guard = actions.expression();
                case "do" -> action = actions.block("after 'do'");
                default -> urgency = Urgency.valueOf(clause.text().toUpperCase(java.util.Locale.ROOT));
            }
        }
        if (from == null || to == null) {
            throw in.fail("expected '" + (from == null ? "from" : "to") + "' in the " + what + ", found "
                    + in.peek().describe());
        }
        return new Transition(pos, annotations, port, from, to, guard, urgency, action, resume);
    }

    private Priority atomPriority(Pos pos) {
        String name = in.ident("a priority name after 'priority'");
        Expr guard = in.acceptWord("provided") ? actions.expression() : null;
        String low = portOrStar("a port name or '*' in priority " + name);
        in.expect(Kind.LT, "between the ports of priority " + name);
        String high = portOrStar("a port name or '*' after '<' in priority " + name);
        if (guard == null && in.acceptWord("provided")) {
            guard = actions.expression();
        }
        return new Priority(pos, name, low, high, guard);
    }

    private String portOrStar(String what) {
        if (in.accept(Kind.STAR)) {
            return "*";
        }
        return in.ident(what);
    }

    // ---------------------------------------------------------------- connector types

    ConnectorType connectorType(Pos pos, List<Annotation> annotations) {
        String name = in.qualifiedName("a connector type name after 'connector type'");
        String owner = "connector type " + name;
        List<Param> ports = decls.params(owner, true);
        List<DataDecl> data = new ArrayList<>();
        List<PortDecl> exports = new ArrayList<>();
        List<PortExpr.Group> defines = new ArrayList<>();
        List<ConnectorType.Interaction> interactions = new ArrayList<>();
        while (bodyContinues(owner)) {
            item(CONNECTOR_ITEMS, () -> {
                List<Annotation> itemAnnotations = decls.annotations();
                Pos itemPos = in.pos();
                if (in.acceptWord("data")) {
                    data.addAll(dataDecl(itemPos, itemAnnotations, false));
                } else if (in.acceptWord("export")) {
                    in.expectWord("port", "after 'export' in a connector type");
                    exports.addAll(portDecl(itemPos, itemAnnotations, true, false));
                } else if (in.acceptWord("define")) {
                    List<PortExpr> items = portExprItems(itemPos);
                    if (items.isEmpty()) {
                        throw in.fail("expected port names after 'define', found " + in.peek().describe());
                    }
                    defines.add(new PortExpr.Group(itemPos, items, false));
                } else if (in.acceptWord("on")) {
                    interactions.add(interaction(itemPos));
                } else {
                    throw in.fail("expected a connector item ('data', 'export port', 'define', 'on' or 'end'), found "
                            + in.peek().describe());
                }
            });
        }
        if (exports.size() > 1) {
            in.error(exports.get(1).pos(), owner + " exports more than one port");
        }
        if (defines.size() > 1) {
            in.error(defines.get(1).pos(), owner + " has more than one 'define'");
        }
        return new ConnectorType(pos, annotations, name, ports, data, exports.isEmpty() ? null : exports.get(0),
                defines.isEmpty() ? null : defines.get(0), interactions);
    }

    private List<PortExpr> portExprItems(Pos open) {
        List<PortExpr> items = new ArrayList<>();
        while (true) {
            Pos pos = in.pos();
            if (in.at(Kind.IDENT) && !CONNECTOR_ITEMS.contains(in.peek().text())) {
                String port = in.next().text();
                items.add(new PortExpr.Ref(pos, port, in.accept(Kind.QUOTE)));
            } else if (in.at(Kind.LPAREN)) {
                in.next();
                in.enter();
                try {
                    List<PortExpr> inner = portExprItems(pos);
                    in.expect(Kind.RPAREN, "to close the group opened at " + pos.line() + ":" + pos.column());
                    items.add(new PortExpr.Group(pos, inner, in.accept(Kind.QUOTE)));
                } finally {
                    in.leave();
                }
            } else {
                return items;
            }
        }
    }

    private ConnectorType.Interaction interaction(Pos pos) {
        List<String> ports = new ArrayList<>();
        while (in.at(Kind.IDENT) && !in.atAnyWord(Set.of("provided", "up", "down", "on", "end", "data", "export",
                "define"))) {
            ports.add(in.next().text());
        }
        if (ports.isEmpty()) {
            throw in.fail("expected port names after 'on', found " + in.peek().describe());
        }
        Expr guard = in.acceptWord("provided") ? actions.expression() : null;
        Block up = in.acceptWord("up") ? actions.block("after 'up'") : null;
        Block down = in.acceptWord("down") ? actions.block("after 'down'") : null;
        return new ConnectorType.Interaction(pos, ports, guard, up, down);
    }

    // ---------------------------------------------------------------- compound types

    CompoundType compoundType(Pos pos, List<Annotation> annotations) {
        String name = in.qualifiedName("a compound type name after 'compound type'");
        String owner = "compound type " + name;
        List<Param> params = decls.params(owner, true);
        List<CompoundType.Component> components = new ArrayList<>();
        List<CompoundType.Connector> connectors = new ArrayList<>();
        List<CompoundType.Priority> priorities = new ArrayList<>();
        List<CompoundType.PortExport> portExports = new ArrayList<>();
        List<CompoundType.DataExport> dataExports = new ArrayList<>();
        while (bodyContinues(owner)) {
            item(COMPOUND_ITEMS, () -> {
                List<Annotation> itemAnnotations = decls.annotations();
                Pos itemPos = in.pos();
                if (in.acceptWord("component")) {
                    String type = in.qualifiedName("a component type after 'component'");
                    do {
                        Pos namePos = in.pos();
                        String instance = in.ident("a component name after type " + type);
                        List<Expr> args = new ArrayList<>();
                        if (in.accept(Kind.LPAREN)) {
                            if (!in.at(Kind.RPAREN)) {
                                do {
                                    args.add(actions.expression());
                                } while (in.accept(Kind.COMMA));
                            }
                            in.expect(Kind.RPAREN, "to close the arguments of component " + instance);
                        }
                        components.add(new CompoundType.Component(namePos, itemAnnotations, type, instance, args));
                    } while (in.accept(Kind.COMMA));
                } else if (in.acceptWord("connector")) {
                    String type = in.qualifiedName("a connector type after 'connector'");
                    boolean first = true;
                    do {
                        // BIP2 declares several connectors of one type at once: connector T c1(A.p), c2(B.q)
                        Pos namePos = first ? itemPos : in.pos();
                        first = false;
                        String instance = in.ident("a connector name after type " + type);
                        in.expect(Kind.LPAREN, "after connector " + instance + " (its ports, e.g. (A.p, B.q))");
                        List<PortRef> ports = new ArrayList<>();
                        if (!in.at(Kind.RPAREN)) {
                            do {
                                ports.add(portRef("a port 'component.port' of connector " + instance));
                            } while (in.accept(Kind.COMMA));
                        }
                        in.expect(Kind.RPAREN, "to close the ports of connector " + instance);
                        connectors.add(new CompoundType.Connector(namePos, itemAnnotations, type, instance, ports));
                    } while (in.accept(Kind.COMMA));
                } else if (in.acceptWord("priority")) {
                    priorities.add(compoundPriority(itemPos));
                } else if (in.acceptWord("export")) {
                    if (in.acceptWord("port")) {
                        List<PortRef> refs = new ArrayList<>();
                        do {
                            refs.add(portRef("a port 'component.port' after 'export port'"));
                        } while (in.accept(Kind.COMMA));
                        in.expectWord("as", "after the exported ports (write 'export port A.p as name')");
                        portExports.add(new CompoundType.PortExport(itemPos, refs, in.ident("an exported port name")));
                    } else if (in.acceptWord("data")) {
                        PortRef ref = portRef("a data 'component.data' after 'export data'");
                        in.expectWord("as", "after the exported data (write 'export data A.x as name')");
                        dataExports.add(new CompoundType.DataExport(itemPos, ref, in.ident("an exported data name")));
                    } else {
                        throw in.fail("expected 'port' or 'data' after 'export', found " + in.peek().describe());
                    }
                } else {
                    throw in.fail("expected a compound item ('component', 'connector', 'priority', 'export' or "
                            + "'end'), found " + in.peek().describe());
                }
            });
        }
        return new CompoundType(pos, annotations, name, params, components, connectors, priorities, portExports,
                dataExports);
    }

    private PortRef portRef(String what) {
        Pos pos = in.pos();
        String component = in.ident(what);
        in.expect(Kind.DOT, "after '" + component + "' (a port is written component.port)");
        return new PortRef(pos, component, in.ident(what));
    }

    private CompoundType.Priority compoundPriority(Pos pos) {
        String name = in.ident("a priority name after 'priority'");
        Expr guard = in.acceptWord("provided") ? actions.expression() : null;
        InteractionSpec low = interactionSpec(name);
        in.expect(Kind.LT, "between the interactions of priority " + name);
        InteractionSpec high = interactionSpec(name);
        if (guard == null && in.acceptWord("provided")) {
            guard = actions.expression();
        }
        return new CompoundType.Priority(pos, name, low, high, guard);
    }

    private InteractionSpec interactionSpec(String priority) {
        Pos pos = in.pos();
        String connector = in.accept(Kind.STAR) ? "*" : in.ident("a connector name or '*' in priority " + priority);
        in.expect(Kind.COLON, "after '" + connector + "' in priority " + priority + " (write C:* or C:A.p,B.q)");
        if (in.accept(Kind.STAR)) {
            return new InteractionSpec(pos, connector, null);
        }
        List<PortRef> ports = new ArrayList<>();
        do {
            ports.add(portRef("a port 'component.port' in priority " + priority));
        } while (in.accept(Kind.COMMA));
        return new InteractionSpec(pos, connector, ports);
    }
}
