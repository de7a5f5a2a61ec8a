package eu.brain.iot.bip.cli;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import eu.brain.iot.bip.diag.Diagnostic;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.generate.Toolchain;
import eu.brain.iot.bip.print.Printer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code bip check}, {@code bip generate} and {@code bip print}: load the files and what they use, check them, then
 * report, write Java or print canonical BIP. The three take the same options (an option another of them needs is
 * accepted and has no effect).
 */
@Command
final class ModelCommand implements Callable<Integer> {

    /** Which of the three commands. */
    enum Kind {
        CHECK, GENERATE, PRINT;

        String command() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    private final Kind kind;
    private final PrintStream out;
    private final PrintStream err;

    @Parameters(arity = "0..*")
    private List<Path> files = new ArrayList<>();

    @Option(names = "-I")
    private List<Path> includes = new ArrayList<>();

    @Option(names = "-o")
    private Path output;

    @Option(names = "--root")
    private String root;

    @Option(names = "--strict")
    private boolean strict;

    ModelCommand(Kind kind, PrintStream out, PrintStream err) {
        this.kind = kind;
        this.out = out;
        this.err = err;
    }

    @Override
    public Integer call() {
        if (files.isEmpty()) {
            err.println("bip: no model file given\n" + Main.USAGE);
            return Exit.USAGE;
        }
        if (kind == Kind.GENERATE && output == null) {
            err.println("bip: generate needs -o DIR\n" + Main.USAGE);
            return Exit.USAGE;
        }
        List<Path> modelPath = withFolders(files, includes);
        Diagnostics diagnostics = new Diagnostics();
        Toolchain tool = Toolchain.load(files, modelPath, diagnostics, root);
        return switch (kind) {
            case CHECK -> {
                tool.check();
                int code = report(diagnostics, err);
                if (code == Exit.OK) {
                    out.println("bip: " + files.size() + " file(s) checked, no errors");
                }
                yield code;
            }
            case GENERATE -> {
                int written = tool.generate(output, root, strict);
                int code = report(diagnostics, err);
                if (code == Exit.OK) {
                    out.println("bip: wrote " + written + " Java file(s) to " + output + ":");
                    tool.summary().forEach(line -> out.println("  " + line));
                    RootHint.lines(tool.atomsWithoutRoot(), modelPath).forEach(line -> out.println("  " + line));
                }
                yield code;
            }
            case PRINT -> {
                int code = report(diagnostics, err);
                if (code == Exit.OK) {
                    tool.workspace().ownPackages().forEach(p -> out.print(Printer.print(p)));
                }
                yield code;
            }
        };
    }

    /** @return the model path: the {@code -I} folders, then the folder of each file given (its neighbours) */
    static List<Path> withFolders(List<Path> files, List<Path> includes) {
        List<Path> path = new ArrayList<>(includes);
        for (Path f : files) {
            if (f.getParent() != null && !path.contains(f.getParent())) {
                path.add(f.getParent());
            }
        }
        return path;
    }

    private static int report(Diagnostics diagnostics, PrintStream err) {
        for (Diagnostic d : diagnostics.sorted()) {
            err.println(d);
        }
        if (diagnostics.hasErrors()) {
            err.println("bip: " + diagnostics.errorCount() + " error(s), " + diagnostics.warningCount()
                    + " warning(s)" + (diagnostics.hiddenCount() == 0 ? "" : " (and " + diagnostics.hiddenCount()
                            + " unknown name(s) in packages that use a package not found, not shown)"));
            return Exit.PROBLEMS;
        }
        return Exit.OK;
    }
}
