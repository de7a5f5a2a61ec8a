package eu.brain.iot.scenario;

import java.io.IOException;
import java.io.PrintStream;
import java.util.List;

/** {@code java -jar warehouse-scenario.jar [options]}: exit 0 passed, 1 failed, 2 bad options. */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    static int run(String[] args, PrintStream out, PrintStream err) {
        Options options;
        try {
            options = OptionsParser.parse(args);
        } catch (UsageException e) {
            return badOption(e, err);
        }
        if (options == null) {
            out.print(OptionsParser.USAGE);
            return 0;
        }
        try {
            return new ScenarioRunner(options, List.of(args), out).run();
        } catch (UsageException e) {
            return badOption(e, err);
        } catch (IOException e) {
            err.println("warehouse-scenario: " + e.getMessage());
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            err.println("warehouse-scenario: interrupted");
            return 1;
        }
    }

    /** A bad option: what was wrong on one line, and where the options are listed (the usage would scroll it away). */
    private static int badOption(UsageException e, PrintStream err) {
        err.println("warehouse-scenario: " + e.getMessage());
        err.println("(./warehouse-scenario --help lists the options)");
        return 2;
    }
}
