package eu.brain.iot.benchmarks.fabric;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/**
 * How busy the JIT compilers of this benchmark's JVMs are: the CPU time of the threads named {@code C1 CompilerThre…}
 * and {@code C2 CompilerThre…} of this process and of every process it started (nodes, broker, subscriber), read
 * from Linux's {@code /proc}. A fabric node loads far more code than a bare client, and on two cores its C2 compiler
 * still took a third of a core a minute into a run: latency measured then is the JIT's, not the fabric's.
 * <p>
 * Not thread-safe: the benchmark's main thread owns it.
 */
final class JitActivity {
    /** Linux's clock ticks per second for a thread's CPU time in {@code /proc} (USER_HZ). */
    static final double TICKS_PER_SECOND = 100;
    private static final Path PROC = Path.of("/proc");

    private long lastTicks;
    private long lastNanos;

    JitActivity() {
        lastTicks = compilerTicks();
        lastNanos = System.nanoTime();
    }

    /** Whether this machine shows threads' CPU time ({@code /proc}, Linux). */
    static boolean available() {
        return Files.isReadable(PROC.resolve("self/task"));
    }

    /** @return the share of one core the compilers used since the last call (or since this object was made) */
    double shareSinceLast() {
        long ticks = compilerTicks();
        long now = System.nanoTime();
        double seconds = Math.max(1e-3, (now - lastNanos) / 1e9);
        double share = (ticks - lastTicks) / TICKS_PER_SECOND / seconds;
        lastTicks = ticks;
        lastNanos = now;
        return Math.max(0, share);
    }

    private static long compilerTicks() {
        long sum = 0;
        try (Stream<ProcessHandle> all = Stream.concat(Stream.of(ProcessHandle.current()),
                ProcessHandle.current().descendants())) {
            for (ProcessHandle p : (Iterable<ProcessHandle>) all::iterator) {
                sum += compilerTicks(PROC.resolve(Long.toString(p.pid())).resolve("task"));
            }
        }
        return sum;
    }

    /** The user and system ticks of the compiler threads under one {@code /proc/<pid>/task}; 0 once it is gone. */
    static long compilerTicks(Path tasks) {
        long sum = 0;
        try (Stream<Path> threads = Files.list(tasks)) {
            for (Path t : (Iterable<Path>) threads::iterator) {
                sum += threadTicks(t);
            }
        } catch (IOException | RuntimeException e) {
            return sum; // the process (or a thread) ended while it was read: it compiles no more
        }
        return sum;
    }

    private static long threadTicks(Path thread) {
        try {
            String comm = Files.readString(thread.resolve("comm")).strip();
            if (!comm.startsWith("C1 Compiler") && !comm.startsWith("C2 Compiler")) {
                return 0;
            }
            return ticksOfStat(Files.readString(thread.resolve("stat")));
        } catch (IOException e) {
            return 0;
        }
    }

    /** utime + stime of a {@code stat} line: fields 14 and 15, counted after the command's closing parenthesis. */
    static long ticksOfStat(String stat) {
        String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        return Long.parseLong(f[11]) + Long.parseLong(f[12]);
    }
}
