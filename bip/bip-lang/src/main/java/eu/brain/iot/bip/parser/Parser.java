package eu.brain.iot.bip.parser;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Annotation;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.ConstDecl;
import eu.brain.iot.bip.model.Decl;
import eu.brain.iot.bip.model.ExternFunction;
import eu.brain.iot.bip.model.ExternOperator;
import eu.brain.iot.bip.model.ExternType;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.model.PortType;
import eu.brain.iot.bip.model.TypeRef;
import eu.brain.iot.bip.parser.Token.Kind;
import eu.brain.iot.bip.parser.TokenCursor.SyntaxError;

/**
 * Hand-written recursive-descent parser for BIP2 and the BRAIN-IoT dialect. It never stops at the first problem:
 * each declaration and each item inside a type is parsed on its own, and after an error the parser skips to the
 * next place where a declaration or item can start, so one run reports every problem of a file.
 */
public final class Parser {

    private final TokenCursor in;
    private final ActionParser actions;
    private final BodyParser bodies;

    private Parser(List<Token> tokens, Diagnostics diagnostics) {
        this.in = new TokenCursor(tokens, diagnostics);
        this.actions = new ActionParser(in);
        this.bodies = new BodyParser(in, actions, this);
    }

    /**
     * Parses one file. Problems go to {@code diagnostics}; the result holds everything that could be read and is
     * null only when the file has no {@code package} at all.
     */
    public static BipPackage parse(String file, String source, Diagnostics diagnostics) {
        return new Parser(Lexer.tokenize(file, source, diagnostics), diagnostics).file();
    }

    private BipPackage file() {
        List<Annotation> annotations = annotationsSafely();
        Pos pos = in.pos();
        if (!in.acceptWord("package")) {
            in.fail("expected 'package <name>' at the start of the file, found " + in.peek().describe()
                    + (in.atWord("model") ? " (a BIP1 model: this toolchain reads BIP2, where a file is "
                            + "'package <name> ... end' and the system is a compound type)" : ""));
            while (!in.atEnd() && !in.atWord("package")) {
                in.next();
            }
            if (!in.acceptWord("package")) {
                return null;
            }
        }
        String name;
        try {
            name = in.qualifiedName("the package name after 'package'");
        } catch (SyntaxError e) {
            name = "<missing>";
        }
        List<BipPackage.Use> uses = new ArrayList<>();
        while (in.atWord("use")) {
            Pos usePos = in.pos();
            in.next();
            try {
                uses.add(new BipPackage.Use(usePos, in.qualifiedName("a package name after 'use'")));
            } catch (SyntaxError e) {
                syncToDeclaration();
            }
        }
        List<Decl> decls = new ArrayList<>();
        while (!in.atEnd()) {
            if (in.atWord("end")) {
                if (endsPackage() || !(atDeclarationStart(1) || in.peek(1).isWord("end"))) {
                    break;
                }
                // a stray 'end' (of a type whose header was broken and skipped): already reported, go on
                in.next();
                continue;
            }
            int start = in.mark();
            try {
                declaration(decls);
            } catch (SyntaxError e) {
                in.resetDepth();
                in.syncUntil(() -> atDeclarationStart(0) || in.atWord("end"), true, start);
            }
        }
        if (in.atEnd()) {
            in.error(in.pos(), "expected 'end' to close package " + name + ", found end of file");
        } else {
            in.next();
            if (!in.atEnd()) {
                in.error(in.pos(), "unexpected " + in.peek().describe() + " after the 'end' of package " + name);
            }
        }
        return new BipPackage(pos, annotations, name, uses, decls);
    }

    /** @return whether the token {@code ahead} of the cursor can start a declaration */
    boolean atDeclarationStart(int ahead) {
        Token t = in.peek(ahead);
        if (t.is(Kind.AT)) {
            return true;
        }
        if (!t.is(Kind.IDENT)) {
            return false;
        }
        return switch (t.text()) {
            case "const" -> in.peek(ahead + 1).isWord("data");
            case "extern" -> !in.peek(ahead + 1).isWord("port");
            case "port", "atom", "atomic", "connector", "compound" -> in.peek(ahead + 1).isWord("type");
            default -> false;
        };
    }

    void syncToDeclaration() {
        in.syncUntil(() -> atDeclarationStart(0) || in.atWord("end"), true);
    }

    /** @return whether the 'end' at the cursor is the last word of the file (the package's own end) */
    private boolean endsPackage() {
        return in.peek(1).is(Kind.EOF);
    }

    private void declaration(List<Decl> decls) {
        List<Annotation> annotations = annotations();
        Pos pos = in.pos();
        if (in.atWord("const")) {
            in.next();
            in.expectWord("data", "after 'const' (write 'const data <type> <name> = <value>')");
            TypeRef type = type("a type after 'const data'");
            do {
                Pos namePos = in.pos();
                String name = in.ident("a constant name");
                in.expect(Kind.ASSIGN, "after constant " + name + " (a constant needs a value)");
                decls.add(new ConstDecl(namePos, annotations, type, name, actions.expression()));
            } while (in.accept(Kind.COMMA));
        } else if (in.atWord("extern")) {
            in.next();
            decls.add(extern(pos, annotations));
        } else if (in.atWord("port", "type")) {
            in.next();
            in.next();
            String name = in.qualifiedName("a port type name after 'port type'");
            decls.add(new PortType(pos, annotations, name, params("port type " + name, true)));
        } else if (in.atWord("atom", "type") || in.atWord("atomic", "type")) {
            in.next();
            in.next();
            decls.add(bodies.atomType(pos, annotations));
        } else if (in.atWord("connector", "type")) {
            in.next();
            in.next();
            decls.add(bodies.connectorType(pos, annotations));
        } else if (in.atWord("compound", "type")) {
            in.next();
            in.next();
            decls.add(bodies.compoundType(pos, annotations));
        } else {
            throw in.fail("expected a declaration ('const data', 'extern', 'port type', 'atom type', 'connector type', "
                    + "'compound type' or the package's 'end'), found " + in.peek().describe());
        }
    }

    private Decl extern(Pos pos, List<Annotation> annotations) {
        if (in.acceptWord("data")) {
            in.expectWord("type", "after 'extern data'");
            String name = in.qualifiedName("a type name after 'extern data type'");
            List<String> refines = new ArrayList<>();
            if (in.acceptWord("refine")) {
                refines.add(in.qualifiedName("a type name after 'refine'"));
                while (in.accept(Kind.COMMA)) {
                    refines.add(in.qualifiedName("a type name after ','"));
                }
            }
            String backend = null;
            if (in.acceptWord("as")) {
                backend = in.expect(Kind.STRING, "after 'as' (the back-end type name, in quotes)").text();
            }
            return new ExternType(pos, annotations, name, refines, backend);
        }
        if (in.acceptWord("operator")) {
            TypeRef result = type("the result type of the operator");
            Token op = in.next();
            if (op.kind().symbol == null || op.is(Kind.LPAREN)) {
                throw in.fail("expected an operator symbol after the result type, found " + op.describe());
            }
            in.expect(Kind.LPAREN, "after operator " + op.text());
            List<TypeRef> params = new ArrayList<>();
            if (!in.at(Kind.RPAREN)) {
                do {
                    params.add(type("a parameter type"));
                } while (in.accept(Kind.COMMA));
            }
            in.expect(Kind.RPAREN, "to close the parameters of operator " + op.text());
            return new ExternOperator(pos, annotations, result, op.text(), params);
        }
        // 'extern function [type] name(...)' or the paper's 'extern type name(...)'
        boolean keyword = in.acceptWord("function");
        TypeRef result = null;
        if (!(in.at(Kind.IDENT) && in.peek(1).is(Kind.LPAREN))) {
            result = type(keyword ? "a result type or function name after 'extern function'"
                    : "'data type', 'function', 'operator' or a result type after 'extern'");
        } else if (!keyword) {
            in.error(in.pos(), "expected 'function', 'data type' or 'operator' after 'extern', found "
                    + in.peek().describe());
        }
        String name = in.ident("a function name");
        return new ExternFunction(pos, annotations, result, name, params("function " + name, false));
    }

    /** {@code '(' type name, ... ')'}; names are optional unless {@code named}. */
    List<Param> params(String owner, boolean named) {
        Pos open = in.pos();
        in.expect(Kind.LPAREN, "after " + owner);
        List<Param> params = new ArrayList<>();
        if (!in.at(Kind.RPAREN)) {
            do {
                Pos pos = in.pos();
                if (atDeclarationStart(0)) {
                    throw in.fail("expected a parameter type of " + owner + ", found " + in.peek().describe());
                }
                boolean constant = in.acceptWord("const");
                TypeRef type = type("a parameter type of " + owner);
                String name = null;
                if (in.at(Kind.IDENT)) {
                    name = in.next().text();
                } else if (named) {
                    throw in.fail("expected a parameter name after type " + type.name() + " of " + owner + ", found "
                            + in.peek().describe());
                }
                params.add(new Param(pos, type, name, constant));
            } while (in.accept(Kind.COMMA));
        }
        in.expect(Kind.RPAREN, "to close the parameters of " + owner + " opened at " + open.line() + ":"
                + open.column());
        return params;
    }

    TypeRef type(String what) {
        Pos pos = in.pos();
        return new TypeRef(pos, in.qualifiedName(what));
    }

    /** Annotations before an item; a broken one is reported and skipped. */
    List<Annotation> annotationsSafely() {
        try {
            return annotations();
        } catch (SyntaxError e) {
            while (!in.atEnd() && !in.at(Kind.RPAREN) && !in.atWord("package")) {
                in.next();
            }
            in.accept(Kind.RPAREN);
            return annotationsSafely();
        }
    }

    List<Annotation> annotations() {
        List<Annotation> list = new ArrayList<>();
        while (in.at(Kind.AT)) {
            Pos pos = in.pos();
            in.next();
            String name = in.ident("an annotation name after '@'");
            List<Annotation.Param> params = new ArrayList<>();
            if (in.accept(Kind.LPAREN)) {
                if (!in.at(Kind.RPAREN)) {
                    do {
                        String key = in.ident("an annotation key");
                        String value = null;
                        boolean quoted = false;
                        if (in.accept(Kind.ASSIGN)) {
                            Token v = in.peek();
                            quoted = v.is(Kind.STRING);
                            if (v.is(Kind.STRING) || v.is(Kind.INT) || v.is(Kind.FLOAT)) {
                                value = in.next().text();
                            } else if (v.is(Kind.IDENT)) {
                                value = in.qualifiedName("an annotation value");
                            } else {
                                throw in.fail("expected a value after '" + key + "=', found " + v.describe());
                            }
                        }
                        params.add(new Annotation.Param(key, value, quoted));
                    } while (in.accept(Kind.COMMA));
                }
                in.expect(Kind.RPAREN, "to close annotation @" + name);
            }
            list.add(new Annotation(pos, name, params));
        }
        return list;
    }
}
