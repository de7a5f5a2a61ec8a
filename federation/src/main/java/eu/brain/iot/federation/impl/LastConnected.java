package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * When this node was last connected to the broker, kept in {@value #FILE} in its state folder (written at most every
 * {@link #periodMillis} while it is connected), so that a node that was away for half of
 * {@link Settings#offlineGiveUpMillis} or more connects with a clean broker session: its peers may have given up on
 * the events they kept for it ({@link GivingUp}) and published them again elsewhere, and the copies its old session
 * still queues would reach it too. A clean session loses nothing: every peer sends again what it keeps for this node
 * and was not acknowledged. A time written late only makes a clean start likelier.
 * <p>
 * Threads: the sender thread, which writes the node's files, tells it while connected ({@link #connected}); the
 * inbound thread asks it before connecting; under this object's monitor.
 */
final class LastConnected {

    static final String FILE = "connected.at";

    private final Path file;
    private final long giveUpMillis;
    /** The last time known to be connected (epoch ms), -1 if never. */
    private long lastMillis;
    /** When the file was last written (epoch ms). */
    private long writtenMillis = Long.MIN_VALUE / 2;
    private boolean warned;

    LastConnected(Path stateDir, long giveUpMillis) {
        this.file = stateDir.resolve(FILE);
        this.giveUpMillis = giveUpMillis;
        this.lastMillis = read(file);
    }

    private static long read(Path file) {
        try {
            return Long.parseLong(Files.readString(file, StandardCharsets.US_ASCII).strip());
        } catch (IOException | NumberFormatException e) {
            return -1;
        }
    }

    /** How often the time is written while connected. */
    long periodMillis() {
        return Math.max(1000, giveUpMillis / 6);
    }

    /** Connected now: remember it, and write it to the file when the last write is {@link #periodMillis} old. */
    synchronized void connected(long nowMillis, Host host, String fabric) {
        lastMillis = nowMillis;
        if (nowMillis - writtenMillis < periodMillis()) {
            return;
        }
        writtenMillis = nowMillis;
        try {
            Files.writeString(file, Long.toString(nowMillis), StandardCharsets.US_ASCII);
            warned = false;
        } catch (IOException e) {
            if (!warned) {
                host.warn("Fabric {}: {} cannot be written ({}): after a restart this node may not know how long "
                        + "it was away, and keep a broker session its peers gave up on", fabric, file, e.getMessage());
                warned = true;
            }
        }
    }

    /** @return how long ago this node was last connected, -1 if never */
    synchronized long awayMillis(long nowMillis) {
        return lastMillis < 0 ? -1 : Math.max(0, nowMillis - lastMillis);
    }

    /** @return whether the next connection starts a clean broker session */
    synchronized boolean cleanStart(long nowMillis) {
        return lastMillis >= 0 && nowMillis - lastMillis >= giveUpMillis / 2;
    }
}
