package eu.brain.iot.robotsim.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine;
import picocli.CommandLine.MaxValuesExceededException;
import picocli.CommandLine.MissingParameterException;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.OverwrittenOptionException;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * How robot-sim's commands (and the benchmark drivers built on them) report a bad command line: one line
 * {@code PROGRAM: what is wrong}, then the usage of the command concerned, on standard error, exit code
 * {@value #BAD_USAGE}; a file that cannot be read or written is one line and exit code {@value #FAILED}. Never a
 * stack trace.
 */
public final class CliErrors {
    public static final int BAD_USAGE = 2;
    public static final int FAILED = 1;

    private static final Pattern SWITCH_WITH_VALUE = Pattern.compile("option '(--[^']+)' should be specified without");

    private CliErrors() {
    }

    /**
     * Sets the streams and the error handlers of {@code commandLine} (and its subcommands).
     *
     * @param program the name before every error message
     * @param topLevelCommands true when a bare word first on the line would name a subcommand
     */
    public static CommandLine install(CommandLine commandLine, String program, boolean topLevelCommands,
                                      PrintStream out, PrintStream err) {
        commandLine.setOut(new PrintWriter(out, true, StandardCharsets.UTF_8));
        commandLine.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
        commandLine.setParameterExceptionHandler((ex, args) -> {
            err.println(program + ": " + message(ex, topLevelCommands && ex.getCommandLine() == commandLine));
            err.print(ex.getCommandLine().getUsageMessage());
            err.flush();
            return BAD_USAGE;
        });
        commandLine.setExecutionExceptionHandler((ex, cl, parsed) -> {
            if (ex instanceof UsageException) {
                err.println(program + ": " + ex.getMessage());
                err.print(cl.getUsageMessage());
                err.flush();
                return BAD_USAGE;
            }
            if (ex instanceof IOException) {
                err.println(program + ": " + ex.getMessage());
                err.flush();
                return FAILED;
            }
            throw ex;
        });
        return commandLine;
    }

    /** The one line for a command line picocli could not read. */
    static String message(ParameterException ex, boolean bareWordIsCommand) {
        if (ex instanceof UnmatchedArgumentException u && !u.getUnmatched().isEmpty()) {
            String first = u.getUnmatched().get(0);
            if (first.startsWith("--") && first.length() > 2) {
                return "unknown option " + first;
            }
            return bareWordIsCommand && !first.startsWith("-") ? "unknown command '" + first + "'"
                    : "unexpected argument '" + first + "'";
        }
        if (ex instanceof MissingParameterException m) {
            List<ArgSpec> missing = m.getMissing();
            if (!missing.isEmpty() && missing.get(0) instanceof OptionSpec o) {
                return o.longestName() + " needs a value";
            }
        }
        if (ex instanceof OverwrittenOptionException o && o.getOverwritten() instanceof OptionSpec option) {
            return option.longestName() + " given more than once";
        }
        if (ex instanceof MaxValuesExceededException) {
            Matcher m = SWITCH_WITH_VALUE.matcher(ex.getMessage());
            if (m.find()) {
                return m.group(1) + " takes no value";
            }
        }
        return ex.getMessage();
    }
}
