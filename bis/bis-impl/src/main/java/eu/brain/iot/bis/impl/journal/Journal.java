package eu.brain.iot.bis.impl.journal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The installer's journal, in a directory outside the framework's cache (which a node wipes at each start):
 * {@code journal.tsv} holds what is installed now and which behaviours an operator removed (rewritten atomically
 * after each change); {@code history.log} appends one line per install, uninstall, removal and allowance, for people.
 * Not thread-safe by itself: its one user, the installer's ledger, calls it under the ledger's lock; {@link #load}
 * runs before the installer starts.
 */
public final class Journal {

    private static final String HEADER = "# BRAIN-IoT Bundle Installer journal, format 1: tab-separated; written by"
            + " the node, do not edit while it runs";
    private static final String BEHAVIOUR = "behaviour";
    private static final String BLOCKED = "blocked";

    private final Path directory;
    private final Path file;
    private final Path history;

    public Journal(Path directory) {
        this.directory = directory;
        this.file = directory.resolve("journal.tsv");
        this.history = directory.resolve("history.log");
    }

    public Path directory() {
        return directory;
    }

    public Path file() {
        return file;
    }

    /** An I/O error in words: its message, or its kind when it has none (a NoSuchFileException's is the path). */
    public static String describe(IOException e) {
        String message = e.getMessage();
        String kind = e.getClass().getSimpleName();
        if (message == null || message.isBlank()) {
            return kind;
        }
        return e.getClass() == IOException.class ? message : message + " (" + kind + ")";
    }

    /** What the journal holds: installed behaviours (oldest first) and the operator's removals (name to reason). */
    public record State(List<BehaviourRecord> behaviours, Map<String, String> blocked) {
    }

    /**
     * @throws IOException with the file and line of a line it cannot read
     */
    public State load() throws IOException {
        List<BehaviourRecord> behaviours = new ArrayList<>();
        Map<String, String> blocked = new LinkedHashMap<>();
        if (!Files.exists(file)) {
            return new State(behaviours, blocked);
        }
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.isBlank() || line.startsWith("#")) {
                continue;
            }
            String[] f = line.split("\t", -1);
            try {
                if (BEHAVIOUR.equals(f[0]) && f.length == 8) {
                    behaviours.add(new BehaviourRecord(unescape(f[1]), f[2], split(unescape(f[3]), ","),
                            unescape(f[4]), Long.parseLong(f[5]), unescape(f[6]), bundles(f[7])));
                } else if (BLOCKED.equals(f[0]) && f.length == 3) {
                    blocked.put(unescape(f[1]), unescape(f[2]));
                } else {
                    throw new IllegalArgumentException("unknown record or wrong number of fields");
                }
            } catch (RuntimeException e) {
                throw new IOException(file + ":" + (i + 1) + ": cannot read this line (" + e.getMessage()
                        + "); fix or delete the line (the node then forgets that behaviour)");
            }
        }
        return new State(behaviours, blocked);
    }

    public void save(State state) throws IOException {
        Files.createDirectories(directory);
        StringBuilder out = new StringBuilder(HEADER).append('\n');
        for (BehaviourRecord r : state.behaviours()) {
            out.append(String.join("\t", BEHAVIOUR, escape(r.symbolicName()), r.version(),
                    escape(String.join(",", r.consumed())), escape(r.repository()), Long.toString(r.installedAt()),
                    escape(r.reason()), bundles(r.bundles()))).append('\n');
        }
        state.blocked().forEach((name, reason) -> out.append(String.join("\t", BLOCKED, escape(name), escape(reason)))
                .append('\n'));
        Path temp = directory.resolve(file.getFileName() + ".tmp");
        try {
            // written and forced to the disk before it replaces the journal: a full disk fails here, not later
            try (java.nio.channels.FileChannel channel = java.nio.channels.FileChannel.open(temp,
                    StandardOpenOption.CREATE, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING)) {
                java.nio.ByteBuffer bytes = StandardCharsets.UTF_8.encode(out.toString());
                while (bytes.hasRemaining()) {
                    channel.write(bytes);
                }
                channel.force(true);
            }
            try {
                Files.move(temp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, file, StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (IOException e) {
            try {
                Files.deleteIfExists(temp); // no half-written or empty file left beside the journal
            } catch (IOException alsoFailed) {
                e.addSuppressed(alsoFailed);
            }
            throw e;
        }
    }

    /**
     * Locks the journal's folder for this installer (an exclusive lock on {@code journal.lock}, released by the
     * returned handle or when the process ends): two installers writing one journal would lose entries.
     *
     * @throws IOException saying which process holds it, when another does
     */
    public AutoCloseable lock() throws IOException {
        Files.createDirectories(directory);
        Path lockFile = directory.resolve("journal.lock");
        java.nio.channels.FileChannel channel = java.nio.channels.FileChannel.open(lockFile, StandardOpenOption.CREATE,
                StandardOpenOption.READ, StandardOpenOption.WRITE);
        java.nio.channels.FileLock lock;
        try {
            lock = channel.tryLock();
        } catch (java.nio.channels.OverlappingFileLockException e) {
            lock = null;
        }
        if (lock == null) {
            String holder = new String(Files.readAllBytes(lockFile), StandardCharsets.UTF_8).trim();
            channel.close();
            throw new IOException("the journal folder " + directory + " is in use by another Bundle Installer ("
                    + (holder.isEmpty() ? "process unknown" : holder) + "): each node needs a state folder of its own;"
                    + " start this node with --state=DIR or --name=NAME, or set journal.dir of eu.brain.iot.bis");
        }
        channel.truncate(0);
        channel.write(java.nio.ByteBuffer.wrap(("process " + ProcessHandle.current().pid() + "\n")
                .getBytes(StandardCharsets.UTF_8)), 0);
        java.nio.channels.FileLock held = lock;
        return () -> {
            try {
                held.release();
            } finally {
                channel.close();
            }
        };
    }

    /** Appends a line for people: time, what, which behaviour, why. */
    public void history(String what, String symbolicName, String version, String why) throws IOException {
        Files.createDirectories(directory);
        String line = Instant.now() + "\t" + what + "\t" + symbolicName + "\t" + (version == null ? "" : version) + "\t"
                + escape(why) + "\n";
        Files.writeString(history, line, StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
    }

    private static String bundles(List<BundleFact> bundles) {
        List<String> parts = new ArrayList<>();
        for (BundleFact b : bundles) {
            parts.add(escape(b.symbolicName()) + " " + b.version() + " " + b.sha256() + " " + escape(b.location()));
        }
        return String.join(",", parts);
    }

    private static List<BundleFact> bundles(String field) {
        List<BundleFact> bundles = new ArrayList<>();
        for (String part : split(field, ",")) {
            String[] f = part.split(" ", -1);
            if (f.length != 4) {
                throw new IllegalArgumentException("a bundle needs name, version, sha256 and location: " + part);
            }
            bundles.add(new BundleFact(unescape(f[0]), f[1], f[2], unescape(f[3])));
        }
        if (bundles.isEmpty()) {
            throw new IllegalArgumentException("a behaviour without bundles");
        }
        return bundles;
    }

    private static List<String> split(String text, String separator) {
        return text.isEmpty() ? List.of() : Arrays.asList(text.split(separator));
    }

    /** Percent-escapes what would break a field: %, tab, newline, comma and space. */
    static String escape(String text) {
        if (text == null) {
            return "";
        }
        StringBuilder out = new StringBuilder();
        for (char c : text.toCharArray()) {
            switch (c) {
            case '%', '\t', '\n', '\r', ',', ' ' -> out.append('%').append(String.format("%02X", (int) c));
            default -> out.append(c);
            }
        }
        return out.toString();
    }

    static String unescape(String text) {
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '%' && i + 2 < text.length()) {
                out.append((char) Integer.parseInt(text.substring(i + 1, i + 3), 16));
                i += 2;
            } else {
                out.append(c);
            }
        }
        return out.toString();
    }
}
