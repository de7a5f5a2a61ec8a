package eu.brain.iot.bip.cli;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.Toolchain;
import eu.brain.iot.bip.diag.Diagnostic;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.print.Printer;

/**
 * The command-line tool: {@code java -jar bip-core.jar check FILE...}, {@code generate FILE... -o DIR} and
 * {@code print FILE}, {@code smc FILE... --property QUERY}. Exit code 0 when there is no error, 1 when the models have errors, 2 for a bad command line.
 * Problems are printed as {@code file:line:col: error: message}; an internal failure is reported in one line,
 * never as a stack trace.
 */
public final class Main {

    static final String USAGE = """
            usage: bip check FILE... [-I DIR]...
                   bip generate FILE... -o DIR [-I DIR]... [--root COMPOUND] [--strict]
                   bip print FILE [-I DIR]...
                   bip smc FILE... --property QUERY ... (bip smc --help for its options)
              check     parse and check the models; print every problem as file:line:col: severity: message
              generate  check, then write Java: one class per atom type, an extern interface per atom type, and,
                        for the root compound, event types and one OSGi smart behaviour per atom type
              print     print the model as canonical BIP
              smc       statistical model checking of PBLTL queries on the root compound
              -I DIR    where 'use'd packages are found (as <Package>.bip)
              --root    the compound type that is the system (default: the last compound type of the files)
              --strict  a system that cannot run on the event bus (e.g. hierarchical connectors) is an error;
                        by default it is a warning and only the atom classes and extern interfaces are written
            """;

    private Main() {
    }

    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /** Runs the tool; returns the exit code. */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        try {
            return runUnchecked(args, out, err);
        } catch (RuntimeException | Error e) {
            err.println("bip: internal error: " + e + " (please report it with the model that caused it)");
            return 3;
        }
    }

    private static int runUnchecked(String[] args, PrintStream out, PrintStream err) {
        if (args.length == 0 || args[0].equals("-h") || args[0].equals("--help")) {
            (args.length == 0 ? err : out).print(USAGE);
            return args.length == 0 ? 2 : 0;
        }
        String command = args[0];
        if (command.equals("smc")) {
            try {
                return SmcCommand.run(args, out, err);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                err.println("bip: interrupted");
                return 3;
            }
        }
        List<Path> files = new ArrayList<>();
        List<Path> includes = new ArrayList<>();
        Path output = null;
        String root = null;
        boolean strict = false;
        for (int i = 1; i < args.length; i++) {
            String a = args[i];
            if ((a.equals("-I") || a.equals("-o") || a.equals("--root")) && i + 1 >= args.length) {
                err.println("bip: " + a + " needs a value\n" + USAGE);
                return 2;
            }
            switch (a) {
                case "-I" -> includes.add(Path.of(args[++i]));
                case "-o" -> output = Path.of(args[++i]);
                case "--root" -> root = args[++i];
                case "--strict" -> strict = true;
                default -> {
                    if (a.startsWith("-")) {
                        err.println("bip: unknown option " + a + "\n" + USAGE);
                        return 2;
                    }
                    files.add(Path.of(a));
                }
            }
        }
        if (files.isEmpty()) {
            err.println("bip: no model file given\n" + USAGE);
            return 2;
        }
        for (Path f : files) {
            if (f.getParent() != null && !includes.contains(f.getParent())) {
                includes.add(f.getParent());
            }
        }
        Diagnostics diagnostics = new Diagnostics();
        Toolchain tool = Toolchain.load(files, includes, diagnostics, root);
        int code;
        switch (command) {
            case "check" -> {
                tool.check();
                code = report(diagnostics, err);
                if (code == 0) {
                    out.println("bip: " + files.size() + " file(s) checked, no errors");
                }
            }
            case "generate" -> {
                if (output == null) {
                    err.println("bip: generate needs -o DIR\n" + USAGE);
                    return 2;
                }
                int written = tool.generate(output, root, strict);
                code = report(diagnostics, err);
                if (code == 0) {
                    out.println("bip: wrote " + written + " Java file(s) to " + output + ":");
                    tool.summary().forEach(line -> out.println("  " + line));
                    RootHint.lines(tool.atomsWithoutRoot(), includes).forEach(line -> out.println("  " + line));
                }
            }
            case "print" -> {
                code = report(diagnostics, err);
                if (code == 0) {
                    tool.workspace().ownPackages().forEach(p -> out.print(Printer.print(p)));
                }
            }
            default -> {
                err.println("bip: unknown command " + command + "\n" + USAGE);
                return 2;
            }
        }
        return code;
    }

    private static int report(Diagnostics diagnostics, PrintStream err) {
        for (Diagnostic d : diagnostics.sorted()) {
            err.println(d);
        }
        if (diagnostics.hasErrors()) {
            err.println("bip: " + diagnostics.errorCount() + " error(s), " + diagnostics.warningCount()
                    + " warning(s)" + (diagnostics.hiddenCount() == 0 ? "" : " (and " + diagnostics.hiddenCount()
                            + " unknown name(s) in packages that use a package not found, not shown)"));
            return 1;
        }
        return 0;
    }
}
