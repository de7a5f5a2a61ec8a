package eu.brain.iot.federation.impl;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;

/**
 * The file in which a node keeps the events it sent to one other node until that node acknowledges them, so that a
 * restart of the publishing node loses none. One line per record: {@code EPOCH <id>} (first line: the sequence
 * stream's identity), {@code E <seq> <event JSON>}, {@code A <through>} (acknowledged up to), {@code S <seq>} (the
 * last sequence number given, after a compaction).
 * <p>
 * Records are handed to the operating system by the sender thread before their events go on the wire (no fsync): they
 * survive the node's process being killed, not a power cut. A journal with fewer than 10,000 pending events is
 * compacted when it passes {@link #COMPACT_BYTES}.
 * <p>
 * Not thread-safe: its {@link Outbox} calls it under its journal lock (the sender thread, and the outbox's close).
 */
final class Journal implements AutoCloseable {

    static final long COMPACT_BYTES = 8L << 20;
    private static final byte[] NL = { '\n' };

    /** What a journal held when it was opened. */
    record Loaded(String epoch, long lastSeq, long ackedThrough, List<Pending> pending) {
    }

    /** One event not acknowledged yet. */
    record Pending(long seq, byte[] json) {
    }

    private final Path file;
    private OutputStream out;
    private long written;

    private Journal(Path file, OutputStream out, long written) {
        this.file = file;
        this.out = out;
        this.written = written;
    }

    /** Open (or create) a journal and read what it holds. */
    static Journal open(Path file, List<Loaded> into) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        String epoch = null;
        long lastSeq = 0;
        long acked = 0;
        List<Pending> pending = new ArrayList<>();
        if (Files.exists(file)) {
            for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
                int sp = line.indexOf(' ');
                if (sp < 0) {
                    continue; // a line cut by a crash while it was written
                }
                String kind = line.substring(0, sp);
                String rest = line.substring(sp + 1);
                try {
                    switch (kind) {
                    case "EPOCH" -> epoch = rest;
                    case "S" -> lastSeq = Math.max(lastSeq, Long.parseLong(rest));
                    case "A" -> acked = Math.max(acked, Long.parseLong(rest));
                    case "E" -> {
                        int sp2 = rest.indexOf(' ');
                        long seq = Long.parseLong(rest.substring(0, sp2));
                        lastSeq = Math.max(lastSeq, seq);
                        pending.add(new Pending(seq, rest.substring(sp2 + 1).getBytes(StandardCharsets.UTF_8)));
                    }
                    default -> {
                        // an unknown or partial record: skipped
                    }
                    }
                } catch (RuntimeException partial) {
                    // a record cut by a crash while it was written: it was never sent
                }
            }
        }
        long through = acked;
        pending.removeIf(p -> p.seq() <= through);
        if (epoch == null) {
            epoch = UUID.randomUUID().toString();
            lastSeq = 0;
            pending.clear();
            Files.deleteIfExists(file);
        }
        into.add(new Loaded(epoch, lastSeq, acked, pending));
        Journal journal = new Journal(file, null, 0);
        journal.rewrite(epoch, lastSeq, pending);
        return journal;
    }

    void append(long seq, byte[] json) throws IOException {
        byte[] head = ("E " + seq + " ").getBytes(StandardCharsets.US_ASCII);
        out.write(head);
        out.write(json);
        out.write(NL);
        written += head.length + json.length + 1;
    }

    void acked(long through) throws IOException {
        byte[] line = ("A " + through + "\n").getBytes(StandardCharsets.US_ASCII);
        out.write(line);
        written += line.length;
    }

    /** Hand what was appended to the operating system. */
    void flush() throws IOException {
        out.flush();
    }

    boolean wantsCompaction() {
        return written > COMPACT_BYTES;
    }

    /** Replace the file by one holding only the epoch, the last sequence number and the pending events. */
    void rewrite(String epoch, long lastSeq, List<Pending> pending) throws IOException {
        if (out != null) {
            out.close();
        }
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        try (OutputStream o = new BufferedOutputStream(Files.newOutputStream(tmp))) {
            o.write(("EPOCH " + epoch + "\nS " + lastSeq + "\n").getBytes(StandardCharsets.US_ASCII));
            for (Pending p : pending) {
                o.write(("E " + p.seq() + " ").getBytes(StandardCharsets.US_ASCII));
                o.write(p.json());
                o.write(NL);
            }
        }
        Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        written = Files.size(file);
        out = new BufferedOutputStream(Files.newOutputStream(file, StandardOpenOption.APPEND), 1 << 16);
    }

    @Override
    public void close() throws IOException {
        out.close();
    }
}
