package eu.brain.iot.bip.cli;

import java.io.PrintStream;
import java.util.List;

import picocli.CommandLine;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.ParameterException;

/**
 * A bad command line, in the tool's words: {@code bip: unknown option X}, {@code bip: unknown command X},
 * {@code bip: X needs a value}, then the usage of the command that was being parsed; exit code 2.
 */
final class UsageErrors implements CommandLine.IParameterExceptionHandler {

    private final PrintStream err;

    UsageErrors(PrintStream err) {
        this.err = err;
    }

    @Override
    public int handleParseException(ParameterException e, String[] args) {
        boolean smc = e.getCommandLine().getCommandSpec().userObject() instanceof SmcCommand;
        err.println("bip: " + message(e) + "\n" + (smc ? SmcCommand.USAGE : Main.USAGE));
        return Exit.USAGE;
    }

    private static String message(ParameterException e) {
        if (e instanceof CommandLine.UnmatchedArgumentException u && !u.getUnmatched().isEmpty()) {
            String first = u.getUnmatched().get(0);
            boolean topLevel = e.getCommandLine().getCommandSpec().userObject() instanceof Main;
            return (first.startsWith("-") || !topLevel ? "unknown option " : "unknown command ") + first;
        }
        if (e instanceof CommandLine.MissingParameterException m) {
            List<ArgSpec> missing = m.getMissing();
            if (!missing.isEmpty() && missing.get(0) instanceof OptionSpec o) {
                return o.longestName() + " needs a value";
            }
        }
        return e.getMessage();
    }
}
