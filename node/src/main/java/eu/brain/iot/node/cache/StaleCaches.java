package eu.brain.iot.node.cache;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.util.Comparator;
import java.util.Optional;
import java.util.stream.Stream;

import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;

/**
 * Removes the framework caches that nodes killed without stopping left behind, and marks this node's own.
 * <p>
 * bnd's launcher runs the framework in a fresh temporary folder ({@code osgi.<number>.fw} in {@code java.io.tmpdir})
 * and deletes it in a shutdown hook: after a {@code kill -9} (or a crash, or a power cut) the hook never runs, and
 * each such run leaves a copy of every bundle behind (about 16 MB). So each node writes {@value #MARKER} into its
 * cache ({@code <pid> <process start, epoch ms>}) and holds a lock on it as long as it runs (the operating system
 * releases it when the process dies, however it dies); at start it deletes the caches beside its own whose marker is
 * not locked. Where locks are not available, the marker's process decides: gone, or its pid now used by a process
 * with another start time. A folder without a marker is left alone: another tool's, or a node still starting.
 * Nothing that must survive a restart is kept there: the Bundle Installer's journal, for one, is in the user's state
 * folder ({@code ~/.local/state/brain-iot/<node>}).
 * <p>
 * It looks once, at activation, on SCR's thread, at start level 1 (a stale cache costs a few tens of milliseconds),
 * and releases its lock when deactivated, as the framework stops.
 */
@Component
public final class StaleCaches {

    /** The open marker holding this node's lock; {@code null} if it could not be written. Only SCR's threads. */
    private FileChannel ownMarker;

    /** The file in a node's framework cache that says which process owns it. */
    public static final String MARKER = "fabric-node.pid";
    /** The folders bnd's launcher creates for a framework cache ({@code File.createTempFile("osgi.", ".fw")}). */
    static final String CACHE_GLOB = "osgi.*.fw";

    @Activate
    public StaleCaches(BundleContext context, @Reference(service = LoggerFactory.class) Logger log) {
        String storage = context.getProperty(Constants.FRAMEWORK_STORAGE);
        if (storage == null) {
            return;
        }
        Path own = Path.of(storage).toAbsolutePath().normalize();
        try {
            ownMarker = FileChannel.open(own.resolve(MARKER), StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING);
            // locked before it says anything: a marker with content is one whose lock was taken
            lock(ownMarker, false);
            ownMarker.write(ByteBuffer.wrap(marker(ProcessHandle.current()).getBytes(StandardCharsets.US_ASCII)));
        } catch (IOException e) {
            log.warn("cannot mark the framework cache " + own + " as this node's (" + e + "): a later node will not "
                    + "remove it if this one is killed");
        }
        Path parent = own.getParent();
        if (parent == null) {
            return;
        }
        try (DirectoryStream<Path> caches = Files.newDirectoryStream(parent, CACHE_GLOB)) {
            for (Path cache : caches) {
                if (!cache.equals(own)) {
                    removeIfStale(cache, log);
                }
            }
        } catch (IOException | UncheckedIOException e) {
            log.debug("cannot look for stale framework caches in " + parent + ": " + e);
        }
    }

    @Deactivate
    void deactivate() {
        if (ownMarker != null) {
            try {
                ownMarker.close(); // releases the lock
            } catch (IOException e) {
                // the process ends soon, which releases it too
            }
        }
    }

    /** Locks the marker; {@code false} if another process holds it, {@code null} if locks are not available. */
    private static Boolean lock(FileChannel channel, boolean shared) {
        try {
            return channel.tryLock(0, Long.MAX_VALUE, shared) != null;
        } catch (IOException | UnsupportedOperationException e) {
            return null;
        }
    }

    private static void removeIfStale(Path cache, Logger log) {
        Optional<String> owner = owner(cache);
        if (owner.isEmpty()) {
            return;
        }
        Boolean free;
        try (FileChannel channel = FileChannel.open(cache.resolve(MARKER), StandardOpenOption.READ)) {
            free = lock(channel, true); // released when the channel closes, before the folder is deleted
        } catch (IOException e) {
            return; // cannot open it: not ours to judge
        }
        if (Boolean.FALSE.equals(free) || (free == null && alive(owner.get()))) {
            return;
        }
        try (Stream<Path> files = Files.walk(cache)) {
            files.sorted(Comparator.reverseOrder()).forEach(file -> {
                try {
                    Files.delete(file);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
            log.info("removed the framework cache " + cache + " of node process " + owner.get().split(" ")[0]
                    + ", which ended without stopping (kill -9?)");
        } catch (IOException | UncheckedIOException e) {
            log.warn("cannot remove the stale framework cache " + cache + ": " + e);
        }
    }

    /** The marker's content, if the folder has one (a node's cache) that says something (a node marks it now). */
    private static Optional<String> owner(Path cache) {
        Path marker = cache.resolve(MARKER);
        if (!Files.isRegularFile(marker)) {
            return Optional.empty();
        }
        try {
            return Optional.of(Files.readString(marker, StandardCharsets.US_ASCII).trim()).filter(m -> !m.isEmpty());
        } catch (IOException e) {
            return Optional.empty(); // unreadable (another user's): not ours to remove
        }
    }

    /** {@code <pid> <start epoch ms>} of a process; the start is 0 where the system does not tell it. */
    static String marker(ProcessHandle process) {
        return process.pid() + " " + process.info().startInstant().map(Instant::toEpochMilli).orElse(0L);
    }

    /**
     * Whether the process a marker names still runs: its pid is in use by a process that started when the marker
     * says (or whose start is unknown: then the pid alone decides, and a cache may stay until the pid is free).
     * A marker that cannot be read counts as alive: never remove what may be another node's.
     */
    static boolean alive(String marker) {
        String[] parts = marker.split(" ");
        long pid;
        long started;
        try {
            pid = Long.parseLong(parts[0]);
            started = parts.length > 1 ? Long.parseLong(parts[1]) : 0;
        } catch (NumberFormatException e) {
            return true;
        }
        Optional<ProcessHandle> process = ProcessHandle.of(pid).filter(ProcessHandle::isAlive);
        if (process.isEmpty()) {
            return false;
        }
        long actual = process.get().info().startInstant().map(Instant::toEpochMilli).orElse(0L);
        return started == 0 || actual == 0 || actual == started;
    }
}
