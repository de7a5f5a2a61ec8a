package eu.brain.iot.benchmarks.fabric;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The compilers' CPU time as Linux's {@code /proc} shows it, on a hand-made task folder. */
class JitActivityTest {

    private static String stat(String comm, long utime, long stime) {
        return "4242 (" + comm + ") S 1 4200 4200 0 -1 4194368 12 0 0 0 " + utime + " " + stime
                + " 0 0 20 0 30 0 100 0 0\n";
    }

    @Test
    void utimeAndStimeAreReadAfterTheCommandWhateverItHolds() {
        assertThat(JitActivity.ticksOfStat(stat("C2 CompilerThre", 120, 7))).isEqualTo(127);
        assertThat(JitActivity.ticksOfStat(stat("odd ) name (", 3, 4))).isEqualTo(7);
    }

    @Test
    void onlyTheCompilerThreadsCount(@TempDir Path proc) throws Exception {
        thread(proc, 1, "main", 500, 50);
        thread(proc, 2, "C2 CompilerThre", 90, 10);
        thread(proc, 3, "C1 CompilerThre", 20, 0);
        thread(proc, 4, "brain-iot-fabric-in", 300, 30);
        assertThat(JitActivity.compilerTicks(proc)).isEqualTo(120);
    }

    @Test
    void aProcessThatEndedCompilesNothing(@TempDir Path proc) {
        assertThat(JitActivity.compilerTicks(proc.resolve("gone"))).isZero();
    }

    private static void thread(Path proc, int tid, String comm, long utime, long stime) throws Exception {
        Path t = Files.createDirectories(proc.resolve(Integer.toString(tid)));
        Files.writeString(t.resolve("comm"), comm + "\n");
        Files.writeString(t.resolve("stat"), stat(comm, utime, stime));
    }
}
