package eu.brain.iot.bip.cli;

import java.io.PrintStream;
import java.util.concurrent.Callable;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The command-line tool: {@code java -jar bip.jar check FILE...}, {@code generate FILE... -o DIR},
 * {@code print FILE} and {@code smc FILE... --property QUERY}. Exit codes are those of {@link Exit}: 0 when there is
 * no error, 1 when the models have errors, 2 for a bad command line, 3 for an internal failure. Problems are printed
 * as {@code file:line:col: error: message}; an internal failure is reported in one line, never as a stack trace.
 * picocli parses the command line; the usage texts and messages are this tool's own.
 */
@Command(name = "bip")
public final class Main implements Callable<Integer> {

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

    private final PrintStream out;
    private final PrintStream err;

    @Option(names = {"-h", "--help"})
    private boolean help;

    private Main(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
    }

    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /** Runs the tool; returns the exit code. */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        try {
            return commandLine(out, err).execute(args);
        } catch (RuntimeException | Error e) {
            return internalError(e, err);
        }
    }

    /** No command: the usage, on stdout when asked for with {@code -h}, else on stderr as an error. */
    @Override
    public Integer call() {
        (help ? out : err).print(USAGE);
        return help ? Exit.OK : Exit.USAGE;
    }

    private static CommandLine commandLine(PrintStream out, PrintStream err) {
        CommandLine cl = new CommandLine(new Main(out, err));
        for (ModelCommand.Kind kind : ModelCommand.Kind.values()) {
            cl.addSubcommand(kind.command(), new ModelCommand(kind, out, err));
        }
        cl.addSubcommand("smc", new SmcCommand(out, err));
        // the arguments as written: no @file expansion, a later value of an option replaces an earlier one, and an
        // option's value is the next argument whatever it looks like
        cl.setExpandAtFiles(false);
        cl.setOverwrittenOptionsAllowed(true);
        cl.setAllowOptionsAsOptionParameters(true);
        cl.setAllowSubcommandsAsOptionParameters(true);
        cl.setParameterExceptionHandler(new UsageErrors(err));
        cl.setExecutionStrategy(parsed -> {
            if (((Main) parsed.commandSpec().userObject()).help) {
                out.print(USAGE);
                return Exit.OK;
            }
            return new CommandLine.RunLast().execute(parsed);
        });
        cl.setExecutionExceptionHandler((e, line, parsed) -> internalError(e, err));
        return cl;
    }

    private static int internalError(Throwable e, PrintStream err) {
        err.println("bip: internal error: " + e + " (please report it with the model that caused it)");
        return Exit.INTERNAL;
    }
}
