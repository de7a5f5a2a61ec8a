package eu.brain.iot.broker;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Objects;

/**
 * What the broker is started with: where it listens, where it keeps its state and how much it queues for an
 * offline client.
 *
 * @param bind        the address its MQTT listener binds (loopback by default: other machines reach it only when
 *                    this is set to one of their interfaces)
 * @param port        its MQTT port
 * @param dataDir     its state: sessions, queued and retained messages (file persistence), its configuration file
 * @param persistence whether sessions and queued messages survive a restart
 * @param maxQueued   messages the broker keeps per offline client with a persistent session before it drops new ones
 */
public record BrokerOptions(String bind, int port, Path dataDir, Persistence persistence, long maxQueued) {

    /** The MQTT port: the IANA one. */
    public static final int DEFAULT_PORT = 1883;
    public static final String DEFAULT_BIND = "127.0.0.1";
    /**
     * Per offline client: HiveMQ's own default is 1,000, which a node's persistent session outgrows within a
     * second at fabric rates; the publishing nodes keep every unacknowledged event themselves, this only spares
     * them resending.
     */
    public static final long DEFAULT_MAX_QUEUED = 100_000;

    /** How the broker keeps sessions, queued and retained messages. */
    public enum Persistence {
        /** On disk under the data folder: they survive a restart. */
        FILE("file"),
        /** In memory only: a restart forgets them. */
        IN_MEMORY("in-memory");

        private final String hivemqName;

        Persistence(String hivemqName) {
            this.hivemqName = hivemqName;
        }

        /** The value of HiveMQ's {@code <persistence><mode>}. */
        public String hivemqName() {
            return hivemqName;
        }
    }

    public BrokerOptions {
        Objects.requireNonNull(bind, "bind");
        Objects.requireNonNull(dataDir, "dataDir");
        Objects.requireNonNull(persistence, "persistence");
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("port must be 1..65535, was " + port);
        }
        if (maxQueued < 1) {
            throw new IllegalArgumentException("maxQueued must be at least 1, was " + maxQueued);
        }
    }

    /** The default state folder: {@code ${user.home}/.local/state/brain-iot/broker}, beside the nodes' state. */
    public static Path defaultDataDir() {
        return Path.of(System.getProperty("user.home"), ".local", "state", "brain-iot", "broker");
    }

    /** Loopback, the MQTT port, the default state folder, file persistence. */
    public static BrokerOptions defaults() {
        return new BrokerOptions(DEFAULT_BIND, DEFAULT_PORT, defaultDataDir(), Persistence.FILE, DEFAULT_MAX_QUEUED);
    }

    public BrokerOptions withPort(int newPort) {
        return new BrokerOptions(bind, newPort, dataDir, persistence, maxQueued);
    }

    public BrokerOptions withBind(String newBind) {
        return new BrokerOptions(newBind, port, dataDir, persistence, maxQueued);
    }

    public BrokerOptions withDataDir(Path newDataDir) {
        return new BrokerOptions(bind, port, newDataDir, persistence, maxQueued);
    }

    public BrokerOptions withPersistence(Persistence newPersistence) {
        return new BrokerOptions(bind, port, dataDir, newPersistence, maxQueued);
    }

    public BrokerOptions withMaxQueued(long newMaxQueued) {
        return new BrokerOptions(bind, port, dataDir, persistence, newMaxQueued);
    }

    /** A path from the command line, or a usage error naming the flag. */
    static Path path(String flag, String value) throws UsageException {
        try {
            return Path.of(value).toAbsolutePath();
        } catch (InvalidPathException e) {
            throw new UsageException(flag + " needs a folder, found '" + value + "': " + e.getReason());
        }
    }
}
