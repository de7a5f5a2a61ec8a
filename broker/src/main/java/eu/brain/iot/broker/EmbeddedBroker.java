package eu.brain.iot.broker;

import com.hivemq.embedded.EmbeddedHiveMQ;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * One HiveMQ Community Edition broker, embedded, started from {@link BrokerOptions}. Its data folder holds
 * {@code conf/config.xml} (written at each start), {@code data/} (HiveMQ's persistence) and an empty
 * {@code extensions/} folder.
 *
 * <p>Threads: {@link #start} and {@link #close} are called by the thread that owns the broker (the launcher's main
 * thread or a test); HiveMQ runs its own threads, which this class never touches.
 */
public final class EmbeddedBroker implements AutoCloseable {
    /** How long HiveMQ may take to open its listener (it takes 1-3 s on 2 cores; more on a loaded machine). */
    public static final Duration START_TIMEOUT = Duration.ofSeconds(60);
    private static final Duration STOP_TIMEOUT = Duration.ofSeconds(30);

    private final BrokerOptions options;
    private final EmbeddedHiveMQ hivemq;
    private boolean running;

    private EmbeddedBroker(BrokerOptions options, EmbeddedHiveMQ hivemq) {
        this.options = options;
        this.hivemq = hivemq;
    }

    /**
     * Starts a broker and returns once it accepts connections.
     *
     * @throws BrokerStartException saying why it could not start (port taken, folder not writable, time-out)
     */
    public static EmbeddedBroker start(BrokerOptions options) throws BrokerStartException {
        checkPortFree(options);
        Path data = options.dataDir();
        try {
            Path conf = BrokerConfigFile.write(data.resolve("conf"), options);
            Path extensions = Files.createDirectories(data.resolve("extensions"));
            Path store = Files.createDirectories(data.resolve("data"));
            EmbeddedHiveMQ hivemq = EmbeddedHiveMQ.builder()
                    .withConfigurationFolder(conf)
                    .withDataFolder(store)
                    .withExtensionsFolder(extensions)
                    .build();
            EmbeddedBroker broker = new EmbeddedBroker(options, hivemq);
            broker.awaitStart();
            return broker;
        } catch (IOException e) {
            throw new BrokerStartException("cannot prepare the broker's state folder " + data + ": " + e
                    + " (choose another with --data DIR)", e);
        }
    }

    private void awaitStart() throws BrokerStartException {
        try {
            hivemq.start().get(START_TIMEOUT.toMillis(), TimeUnit.MILLISECONDS);
            running = true;
        } catch (TimeoutException e) {
            closeQuietly();
            throw new BrokerStartException("the broker did not start within " + START_TIMEOUT.toSeconds() + " s", e);
        } catch (ExecutionException e) {
            closeQuietly();
            throw new BrokerStartException("the broker failed to start: " + e.getCause(), e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            closeQuietly();
            throw new BrokerStartException("interrupted while the broker started", e);
        }
    }

    private static void checkPortFree(BrokerOptions options) throws BrokerStartException {
        try (ServerSocket probe = new ServerSocket()) {
            probe.setReuseAddress(true);
            probe.bind(new InetSocketAddress(InetAddress.getByName(options.bind()), options.port()));
        } catch (IOException e) {
            throw new BrokerStartException("cannot listen on " + options.bind() + ":" + options.port() + " (" + e
                    .getMessage() + "): is another broker running there? Choose another port with --port N", e);
        }
    }

    public BrokerOptions options() {
        return options;
    }

    /** {@code tcp://<bind>:<port>}, with 127.0.0.1 for a wildcard bind. */
    public String uri() {
        String host = options.bind().equals("0.0.0.0") || options.bind().equals("::") ? "127.0.0.1" : options.bind();
        return "tcp://" + (host.contains(":") && !host.startsWith("[") ? "[" + host + "]" : host) + ":"
                + options.port();
    }

    /** Stops the broker (its file persistence is kept for the next start). */
    @Override
    public void close() {
        if (!running) {
            return;
        }
        running = false;
        try {
            hivemq.stop().get(STOP_TIMEOUT.toMillis(), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException | TimeoutException e) {
            System.err.println("broker: did not stop cleanly: " + e);
        }
        closeQuietly();
    }

    private void closeQuietly() {
        try {
            hivemq.close();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException | RuntimeException e) {
            System.err.println("broker: did not close cleanly: " + e);
        }
    }
}
