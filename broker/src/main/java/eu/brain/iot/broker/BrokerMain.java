package eu.brain.iot.broker;

import java.lang.management.ManagementFactory;
import java.util.concurrent.CountDownLatch;

/**
 * {@code java -jar broker.jar [--port N] [--bind ADDR] [--data DIR] [--in-memory] [--max-queued N]}: starts the
 * broker, prints one line once clients can connect, and runs until SIGTERM or Ctrl-C (a shutdown hook stops it).
 * Exit codes: 2 for a bad command line, 1 when the broker cannot start.
 */
public final class BrokerMain {
    /** The line's first words, which scripts and tests wait for. */
    public static final String READY_PREFIX = "broker listening on ";

    private BrokerMain() {
    }

    public static void main(String[] args) throws InterruptedException {
        if (CommandLine.wantsHelp(args)) {
            System.out.print(CommandLine.USAGE);
            return;
        }
        BrokerOptions options;
        try {
            options = CommandLine.parse(args);
        } catch (UsageException e) {
            System.err.println("broker: " + e.getMessage());
            System.err.print(CommandLine.USAGE);
            System.exit(2);
            return;
        }
        EmbeddedBroker broker;
        try {
            broker = EmbeddedBroker.start(options);
        } catch (BrokerStartException e) {
            System.err.println("broker: " + e.getMessage());
            System.exit(1);
            return;
        }
        long startedMs = System.currentTimeMillis() - ManagementFactory.getRuntimeMXBean().getStartTime();
        System.out.println(READY_PREFIX + options.bind() + ":" + options.port() + " (" + broker.uri()
                + "; MQTT 3.1.1 and 5; persistence " + options.persistence().hivemqName() + ", state "
                + options.dataDir() + ") in " + startedMs + " ms from JVM start; pid "
                + ProcessHandle.current().pid());
        System.out.flush();
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            broker.close();
            stopped.countDown();
        }, "broker-shutdown"));
        stopped.await();
    }
}
