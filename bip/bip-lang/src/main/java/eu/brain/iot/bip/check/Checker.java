package eu.brain.iot.bip.check;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.CompoundType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.ConstDecl;
import eu.brain.iot.bip.model.Decl;
import eu.brain.iot.bip.model.ExternFunction;
import eu.brain.iot.bip.model.ExternOperator;
import eu.brain.iot.bip.model.ExternType;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.model.PortType;
import eu.brain.iot.bip.model.TypeRef;

/**
 * Checks the packages of a workspace: every name resolves, types agree, connectors fit their ports; warns about
 * places unreachable from the initial place and transitions that can never fire. Problems go to the workspace's
 * {@link Diagnostics}.
 */
public final class Checker {

    private final Workspace workspace;
    private final Diagnostics diagnostics;

    private Checker(Workspace workspace) {
        this.workspace = workspace;
        this.diagnostics = workspace.diagnostics();
    }

    /** Checks every package of the workspace (own and used). */
    public static void check(Workspace workspace) {
        Checker checker = new Checker(workspace);
        for (BipPackage pkg : workspace.packages()) {
            checker.checkPackage(pkg);
        }
    }

    private void checkPackage(BipPackage pkg) {
        PackageScope scope = new PackageScope(workspace, pkg);
        ExprTyper typer = new ExprTyper(scope, diagnostics);
        duplicates(pkg);
        for (Decl d : pkg.decls()) {
            if (d instanceof ConstDecl c) {
                Type t = nativeType(scope, c.type(), "constant " + c.name());
                int errorsBefore = diagnostics.errors().size();
                Type v = typer.type(c.value(), LocalNames.constants(scope));
                boolean typed = diagnostics.errors().size() == errorsBefore;
                if (t != null && !scope.assignable(t, v)) {
                    diagnostics.error(c.value().pos(), "constant " + c.name() + " of type " + t
                            + " cannot hold a value of type " + v);
                } else if (t != null && typed && ConstantFolder.fold(c.value(), scope) == null) {
                    diagnostics.error(c.value().pos(), "the value of constant " + c.name() + " cannot be computed "
                            + "when the model is compiled: write it with literals, operators and other constants "
                            + "(no function call, no cycle, no integer division by zero)");
                }
            } else if (d instanceof ExternType t) {
                t.refines().forEach(r -> {
                    if (scope.externType(r).isEmpty()) {
                        diagnostics.error(t.pos(), "extern type " + t.name() + " refines unknown type " + r);
                    }
                });
            } else if (d instanceof ExternFunction f) {
                if (f.returnType() != null) {
                    type(scope, f.returnType(), "the result of function " + f.name());
                }
                f.params().forEach(p -> type(scope, p.type(), "a parameter of function " + f.name()));
            } else if (d instanceof ExternOperator o) {
                type(scope, o.returnType(), "the result of operator " + o.operator());
                o.params().forEach(p -> type(scope, p, "a parameter of operator " + o.operator()));
            } else if (d instanceof PortType p) {
                params(scope, p.params(), "port type " + p.name());
            } else if (d instanceof AtomType a) {
                new AtomChecker(scope, typer, diagnostics).check(a);
            } else if (d instanceof ConnectorType c) {
                new ConnectorChecker(scope, typer, diagnostics).check(c);
            } else if (d instanceof CompoundType c) {
                new CompoundChecker(scope, typer, diagnostics).check(c);
            }
        }
    }

    private void duplicates(BipPackage pkg) {
        Map<String, Decl> types = new HashMap<>();
        Map<String, Decl> constants = new HashMap<>();
        Set<String> functions = new HashSet<>();
        for (Decl d : pkg.decls()) {
            if (d instanceof ExternFunction f) {
                String sig = f.name() + f.params().stream().map(p -> p.type().name()).toList();
                if (!functions.add(sig)) {
                    diagnostics.warning(f.pos(), "extern function " + f.name() + " is declared twice with the same "
                            + "parameter types");
                }
                continue;
            }
            if (d instanceof ExternOperator) {
                continue;
            }
            Map<String, Decl> names = d instanceof ConstDecl ? constants : types;
            Decl previous = names.putIfAbsent(d.name(), d);
            if (previous != null) {
                diagnostics.error(d.pos(), d.kind() + " " + d.name() + " is already declared as " + previous.kind()
                        + " at " + previous.pos());
            }
        }
    }

    static Type type(PackageScope scope, TypeRef ref, String what) {
        Type t = scope.resolveType(ref.name());
        if (t == null) {
            scope.workspace().diagnostics().error(ref.pos(), "unknown type '" + ref.name() + "' for " + what
                    + ": use int, float, double, bool, string or an 'extern data type'");
            return Type.ERROR;
        }
        return t;
    }

    private Type nativeType(PackageScope scope, TypeRef ref, String what) {
        Type t = type(scope, ref, what);
        if (t.kind() == Type.Kind.EXTERN) {
            diagnostics.error(ref.pos(), what + " must have a native type (int, float, bool or string), not " + t);
            return null;
        }
        return t;
    }

    /** Checks typed, named parameters: known types, distinct names. */
    static void params(PackageScope scope, List<Param> params, String owner) {
        Set<String> seen = new HashSet<>();
        for (Param p : params) {
            type(scope, p.type(), "parameter " + p.name() + " of " + owner);
            if (!seen.add(p.name())) {
                scope.workspace().diagnostics().error(p.pos(), owner + " has two parameters named " + p.name());
            }
        }
    }

    /** Reports a name declared twice in one type. */
    static void unique(Diagnostics diagnostics, Map<String, Pos> seen, String name, Pos pos, String what) {
        Pos previous = seen.putIfAbsent(name, pos);
        if (previous != null) {
            diagnostics.error(pos, what + " '" + name + "' is declared twice (first at " + previous + ")");
        }
    }
}
