package eu.brain.iot.robotsim.cli;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.load.PollLoad;
import eu.brain.iot.robotsim.load.StepBench;
import java.io.IOException;
import java.io.PrintStream;
import java.util.Arrays;
import java.util.concurrent.CountDownLatch;

/** {@code java -jar robot-sim.jar [generate|poll-load|step-bench] [options]}. Exit code 2 for a bad command line. */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        int code = run(args, System.out, System.err);
        if (code >= 0) {
            System.exit(code);
        }
    }

    /**
     * Runs a command. Returns its exit code, or -1 when a server was started and keeps running (until the JVM
     * stops).
     */
    static int run(String[] args, PrintStream out, PrintStream err) {
        String command = args.length > 0 && !args[0].startsWith("-") ? args[0] : "serve";
        String[] rest = command.equals("serve") ? args : Arrays.copyOfRange(args, 1, args.length);
        String usage = switch (command) {
            case "serve" -> ServeCommand.USAGE;
            case "generate" -> GenerateCommand.USAGE;
            case "poll-load" -> PollLoad.USAGE;
            case "step-bench" -> StepBench.USAGE;
            default -> null;
        };
        if (usage == null) {
            err.println("robot-sim: unknown command '" + command + "'");
            err.print(ServeCommand.USAGE);
            return 2;
        }
        if (ServeCommand.wantsHelp(rest)) {
            out.print(usage);
            return 0;
        }
        try {
            switch (command) {
                case "generate" -> GenerateCommand.run(rest, out);
                case "poll-load" -> {
                    return PollLoad.run(rest, out);
                }
                case "step-bench" -> StepBench.run(rest, out);
                default -> {
                    serve(rest, out);
                    return -1;
                }
            }
            return 0;
        } catch (UsageException e) {
            err.println("robot-sim: " + e.getMessage());
            err.print(usage);
            return 2;
        } catch (IOException e) {
            err.println("robot-sim: " + e.getMessage());
            return 1;
        }
    }

    private static void serve(String[] args, PrintStream out) throws UsageException, IOException {
        RobotSim sim = ServeCommand.start(args, out);
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            sim.close();
            stopped.countDown();
        }, "robot-sim-shutdown"));
        Thread keeper = new Thread(() -> {
            try {
                stopped.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "robot-sim-main");
        keeper.start();
    }
}
