package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;

/**
 * For one atom type, what the statistical model checker compiles beside the deployed atom class (which it uses
 * unchanged): a bridge in the atom's Java package ({@code RobotSmc}: the enabled ports as a bit mask, firing a port
 * by index, static reads and writes of the package-private data fields) and an implementation of the atom's extern
 * interface that draws the built-in stochastic functions from the trace's random source and hands every other call
 * to the model's {@code SimulationExterns}.
 */
final class SimulationAtomWriter {

    static final String RT = "eu.brain.iot.bip.smc.runtime.";
    static final int INTERNAL_BIT = 62;

    final AtomType atom;
    final PackageScope scope;
    final ExprTyper typer;
    final String javaPackage;
    final String atomClass;
    final String externs;
    final List<ResolvedCall> calls;
    final SimulationBuiltins builtins;

    SimulationAtomWriter(AtomType atom, PackageScope scope, Diagnostics diagnostics, SimulationBuiltins builtins) {
        this.atom = atom;
        this.builtins = builtins;
        this.scope = scope;
        this.typer = new ExprTyper(scope, new Diagnostics());
        this.javaPackage = JavaNames.javaPackage(scope.pkg());
        this.atomClass = JavaNames.type(atom.name());
        this.externs = atomClass + "Externs";
        this.calls = ExternsWriter.distinct(AtomWriter.calls(atom, scope, typer), atom, diagnostics);
    }

    String qualified(String simple) {
        return javaPackage.isEmpty() ? simple : javaPackage + "." + simple;
    }

    String bridge() {
        return qualified(atomClass + "Smc");
    }

    String javaType(String bipType) {
        Type t = scope.resolveType(bipType);
        return JavaNames.javaType(t == null ? Type.ERROR : t, scope);
    }

    boolean hasExterns() {
        return !calls.isEmpty();
    }

    List<JavaFile> files() {
        List<JavaFile> files = new ArrayList<>();
        files.add(new JavaFile(javaPackage, atomClass,
                new AtomWriter(atom, scope, typer, atomClass, externs).write(javaPackage, hasExterns())));
        if (hasExterns()) {
            files.add(new JavaFile(javaPackage, externs, ExternsWriter.write(javaPackage, externs, atom, calls, scope)));
            files.add(new JavaFile(javaPackage, atomClass + "SmcExterns", externsImpl()));
        }
        files.add(new JavaFile(javaPackage, atomClass + "Smc", bridgeSource()));
        return files;
    }

    private String bridgeSource() {
        Code c = new Code();
        c.line("package " + javaPackage + ";").blank();
        c.line("/** Statistical model checking's view of {@code " + atomClass + "}, generated: do not edit. */");
        c.open("public final class " + atomClass + "Smc");
        c.open("private " + atomClass + "Smc()").close();
        c.line("/** @return the enabled ports (after priorities) as bits in declaration order; bit "
                + INTERNAL_BIT + ": an internal transition is enabled */");
        c.open("public static long mask(" + atomClass + " a)");
        c.line("long m = a.isInternalEnabled() ? 1L << " + INTERNAL_BIT + " : 0L;");
        if (atom.priorities().isEmpty()) {
            for (int i = 0; i < atom.ports().size(); i++) {
                c.open("if (a.isEnabled(" + atomClass + ".Port." + JavaNames.id(atom.ports().get(i).name()) + "))");
                c.line("m |= 1L << " + i + ";").close();
            }
        } else {
            c.open("for (" + atomClass + ".Port p : a.enabledPorts())").line("m |= 1L << p.ordinal();").close();
        }
        c.line("return m;").close();
        c.line("/** Fires port {@code index} (declaration order). */");
        c.open("public static boolean fire(" + atomClass + " a, int index)");
        c.open("switch (index)");
        List<PortDecl> ports = atom.ports();
        for (int i = 0; i < ports.size(); i++) {
            c.line("case " + i + ": return a." + AtomWriter.portMethod(ports.get(i).name()) + "();");
        }
        c.line("default: return false;");
        c.close().close();
        c.open("public static String state(" + atomClass + " a)");
        c.line("StringBuilder s = new StringBuilder(\"[\");");
        c.line("String sep = \"\";");
        c.open("for (" + atomClass + ".Place p : a.marking())").line("s.append(sep).append(p.name());")
                .line("sep = \", \";").close();
        c.line("return s.append(\"] \").append(a.data()).toString();").close();
        List<String> names = new ArrayList<>();
        atom.params().forEach(p -> names.add(p.name()));
        atom.data().forEach(d -> names.add(d.name()));
        for (Param p : atom.params()) {
            c.open("public static " + javaType(p.type().name()) + " get_" + p.name() + "(" + atomClass + " a)")
                    .line("return a." + AtomWriter.field(p.name()) + ";").close();
        }
        for (DataDecl d : atom.data()) {
            String t = javaType(d.type().name());
            c.open("public static " + t + " get_" + d.name() + "(" + atomClass + " a)")
                    .line("return a." + AtomWriter.field(d.name()) + ";").close();
            c.open("public static void set_" + d.name() + "(" + atomClass + " a, " + t + " v)")
                    .line("a." + AtomWriter.field(d.name()) + " = v;").close();
        }
        c.close();
        return c.toString();
    }

    private String externsImpl() {
        Code c = new Code();
        c.line("package " + javaPackage + ";").blank();
        c.line("/** The simulation of {@code " + externs + "} for statistical model checking, generated: do not edit. */");
        c.open("public final class " + atomClass + "SmcExterns implements " + externs);
        c.line("private final " + RT + "TraceRandom random;");
        c.line("private final " + RT + "SimulationExterns simulation;");
        c.open("public " + atomClass + "SmcExterns(" + RT + "TraceRandom random, " + RT + "SimulationExterns simulation)");
        c.line("this.random = random;").line("this.simulation = simulation;").close();
        for (ResolvedCall call : calls) {
            List<String> params = new ArrayList<>();
            List<String> args = new ArrayList<>();
            for (int i = 0; i < call.params().size(); i++) {
                params.add(JavaNames.javaType(call.params().get(i), scope) + " arg" + i);
                args.add("arg" + i);
            }
            String result = JavaNames.javaType(call.result(), scope);
            c.line("@Override");
            c.open("public " + result + " " + JavaNames.id(call.name()) + "(" + String.join(", ", params) + ")");
            c.line(SimulationCode.callBody(call, args, scope, "random", "simulation", builtins));
            c.close();
        }
        c.close();
        return c.toString();
    }
}
