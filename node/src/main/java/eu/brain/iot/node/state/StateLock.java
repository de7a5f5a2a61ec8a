package eu.brain.iot.node.state;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * The lock that makes a state folder one node's: an exclusive {@link FileLock} on {@value #FILE} in the folder, held
 * as long as the node runs (the operating system releases it when the process ends, however it ends), with the
 * holder's process id and name written in the file for whoever is refused. Not thread-safe: its one user, the
 * {@link NodeState} component, takes it at activation and releases it at deactivation.
 */
final class StateLock implements AutoCloseable {

    static final String FILE = "node.lock";

    private final FileChannel channel;
    private final FileLock lock;

    private StateLock(FileChannel channel, FileLock lock) {
        this.channel = channel;
        this.lock = lock;
    }

    /** Refused: another process (or this one) holds the folder's lock. */
    static final class Held extends Exception {
        private static final long serialVersionUID = 1L;
        private final String holder;

        Held(String holder) {
            super(holder);
            this.holder = holder;
        }

        /** What the lock file says of its holder, e.g. {@code process 1234 (node "node")}; or "unknown". */
        String holder() {
            return holder;
        }
    }

    /**
     * @param who written in the lock file for a node that is refused, e.g. {@code process 1234 (node "node")}
     * @throws Held when another holds the lock
     * @throws IOException when the folder or the file cannot be made or opened
     */
    static StateLock take(Path folder, String who) throws Held, IOException {
        Files.createDirectories(folder);
        Path file = folder.resolve(FILE);
        FileChannel channel = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.READ,
                StandardOpenOption.WRITE);
        FileLock lock;
        try {
            lock = channel.tryLock();
        } catch (OverlappingFileLockException e) {
            lock = null; // held by this very process (another framework in this JVM)
        } catch (IOException e) {
            channel.close();
            throw e;
        }
        if (lock == null) {
            String holder = holder(channel);
            channel.close();
            throw new Held(holder);
        }
        channel.truncate(0);
        channel.write(ByteBuffer.wrap((who + "\n").getBytes(StandardCharsets.UTF_8)), 0);
        channel.force(true);
        return new StateLock(channel, lock);
    }

    private static String holder(FileChannel channel) {
        try {
            ByteBuffer buffer = ByteBuffer.allocate(512);
            channel.read(buffer, 0);
            String text = new String(buffer.array(), 0, buffer.position(), StandardCharsets.UTF_8).trim();
            return text.isEmpty() ? "unknown" : text.lines().findFirst().orElse("unknown");
        } catch (IOException e) {
            return "unknown";
        }
    }

    @Override
    public void close() throws IOException {
        try {
            lock.release();
        } finally {
            channel.close();
        }
    }
}
