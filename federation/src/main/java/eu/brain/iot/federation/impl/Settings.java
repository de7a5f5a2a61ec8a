package eu.brain.iot.federation.impl;

import java.nio.file.Path;
import java.util.regex.Pattern;

/**
 * A node's fabric settings, checked: what {@link FabricConfig} says, with the defaults resolved.
 *
 * @param brokerUri the broker's URI
 * @param fabric the fabric's name
 * @param node this node's name
 * @param username broker user name, empty for none
 * @param password broker password
 * @param tls whether to connect with TLS
 * @param trustStore trust store path, empty for the JVM's default trust
 * @param trustStorePassword its password
 * @param keyFile the signing key file
 * @param stateDir the folder of the node's fabric state
 * @param keepAliveSeconds MQTT keep-alive
 * @param sessionExpirySeconds how long the broker keeps the session
 * @param resendTimeoutMillis when unacknowledged events are sent again
 * @param maxPending events kept per remote node
 * @param maxAgeMillis oldest signature accepted
 * @param batchMaxEvents most events per MQTT message
 * @param bidMillis how long a node asking the fabric which node installs a behaviour waits for the answers
 * @param installTimeoutMillis how long an install order to another node may take, its interest included
 * @param offlineGiveUpMillis how long a node may stay offline before the events kept for it are published again
 *        here, for whoever takes them then ({@link GivingUp})
 */
public record Settings(String brokerUri, String fabric, String node, String username, String password, boolean tls,
        String trustStore, String trustStorePassword, Path keyFile, Path stateDir, int keepAliveSeconds,
        long sessionExpirySeconds, long resendTimeoutMillis, int maxPending, long maxAgeMillis, int batchMaxEvents,
        long bidMillis, long installTimeoutMillis, long offlineGiveUpMillis) {

    /** @return whether a message signed at {@code sent} is young enough at {@code at} (epoch milliseconds) */
    boolean inTime(long sent, long at) {
        return Math.abs(at - sent) <= maxAgeMillis;
    }

    /** Names usable as one MQTT topic level and one file name. */
    static final Pattern NAME = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");

    public Settings {
        check(NAME.matcher(fabric).matches(), "fabric.name", fabric, "letters, digits, '.', '_', '-' (at most 64)");
        check(NAME.matcher(node).matches(), "node.name", node, "letters, digits, '.', '_', '-' (at most 64)");
        check(brokerUri.startsWith("tcp://") || brokerUri.startsWith("ssl://"), "broker.uri", brokerUri,
                "tcp://host:port or ssl://host:port");
        check(keepAliveSeconds >= 1, "keep.alive.s", keepAliveSeconds, "at least 1");
        check(maxPending >= 1, "max.pending", maxPending, "at least 1");
        check(batchMaxEvents >= 1, "batch.max.events", batchMaxEvents, "at least 1");
        check(resendTimeoutMillis >= 100, "resend.timeout.ms", resendTimeoutMillis, "at least 100");
        check(maxAgeMillis >= 1000, "max.age.ms", maxAgeMillis, "at least 1000");
        check(bidMillis >= 1, "install.bid.ms", bidMillis, "at least 1");
        check(installTimeoutMillis >= 1000, "install.timeout.ms", installTimeoutMillis, "at least 1000");
        check(offlineGiveUpMillis >= 1000, "offline.giveup.ms", offlineGiveUpMillis, "at least 1000");
    }

    private static void check(boolean ok, String key, Object value, String expected) {
        if (!ok) {
            throw new IllegalArgumentException("fabric configuration (PID " + FabricConfig.PID + "): " + key + "="
                    + value + " is not valid; expected " + expected);
        }
    }

    /** Settings for a node with defaults for everything but its identity and folders (tests, tools). */
    public static Settings of(String brokerUri, String fabric, String node, Path keyFile, Path stateDir) {
        return new Settings(brokerUri, fabric, node, "", "", false, "", "", keyFile, stateDir, 10, 3600, 5000,
                100_000, 300_000, 256, 100, 120_000, 30_000);
    }

    /** The same settings with another resend timeout. */
    public Settings withResendTimeout(long millis) {
        return new Settings(brokerUri, fabric, node, username, password, tls, trustStore, trustStorePassword, keyFile,
                stateDir, keepAliveSeconds, sessionExpirySeconds, millis, maxPending, maxAgeMillis, batchMaxEvents,
                bidMillis, installTimeoutMillis, offlineGiveUpMillis);
    }

    /** The same settings with another keep-alive. */
    public Settings withKeepAlive(int seconds) {
        return new Settings(brokerUri, fabric, node, username, password, tls, trustStore, trustStorePassword, keyFile,
                stateDir, seconds, sessionExpirySeconds, resendTimeoutMillis, maxPending, maxAgeMillis,
                batchMaxEvents, bidMillis, installTimeoutMillis, offlineGiveUpMillis);
    }

    /** The same settings with another bid deadline and install timeout. */
    public Settings withInstall(long bid, long timeout) {
        return new Settings(brokerUri, fabric, node, username, password, tls, trustStore, trustStorePassword, keyFile,
                stateDir, keepAliveSeconds, sessionExpirySeconds, resendTimeoutMillis, maxPending, maxAgeMillis,
                batchMaxEvents, bid, timeout, offlineGiveUpMillis);
    }

    /** The same settings with another give-up time for offline nodes. */
    public Settings withOfflineGiveUp(long millis) {
        return new Settings(brokerUri, fabric, node, username, password, tls, trustStore, trustStorePassword, keyFile,
                stateDir, keepAliveSeconds, sessionExpirySeconds, resendTimeoutMillis, maxPending, maxAgeMillis,
                batchMaxEvents, bidMillis, installTimeoutMillis, millis);
    }
}
