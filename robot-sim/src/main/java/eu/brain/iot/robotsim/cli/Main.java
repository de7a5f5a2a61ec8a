package eu.brain.iot.robotsim.cli;

import eu.brain.iot.robotsim.RobotSim;
import java.io.PrintStream;
import java.util.concurrent.CountDownLatch;
import picocli.CommandLine;

/** {@code java -jar robot-sim.jar [generate] [options]}. Exit code 2 for a bad command line. */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        ServeCommand serve = new ServeCommand(System.out);
        int code = run(serve, args, System.out, System.err);
        if (code == ServeCommand.RUNNING) {
            keepRunning(serve.started());
        } else {
            System.exit(code);
        }
    }

    /** Runs a command. Returns its exit code, or {@link ServeCommand#RUNNING} when a server was started. */
    static int run(ServeCommand serve, String[] args, PrintStream out, PrintStream err) {
        CommandLine commandLine = CliErrors.install(new CommandLine(serve), "robot-sim", true, out, err);
        return commandLine.execute(args);
    }

    /** Keeps the JVM alive until it is stopped; then closes the simulator. */
    private static void keepRunning(RobotSim sim) {
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
