package eu.brain.iot.benchmarks;

import java.io.IOException;
import java.io.Serializable;
import java.lang.management.ManagementFactory;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Process-wide CPU time and context switches, read around a throughput round to show where a bus's time goes
 * (CPU burnt versus threads put to sleep and woken). Context switches come from Linux's per-thread
 * {@code /proc/self/task/N/status}; elsewhere they read as unknown (-1).
 */
record ProcessCost(long cpuNanos, long voluntarySwitches, long involuntarySwitches) implements Serializable {

    private static final Path TASKS = Path.of("/proc/self/task");

    static ProcessCost now() {
        long cpu = ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                ? os.getProcessCpuTime() : -1;
        long voluntary = 0;
        long involuntary = 0;
        try (DirectoryStream<Path> tasks = Files.newDirectoryStream(TASKS)) {
            for (Path task : tasks) {
                try {
                    for (String line : Files.readAllLines(task.resolve("status"))) {
                        if (line.startsWith("voluntary_ctxt_switches:")) {
                            voluntary += Long.parseLong(line.substring(line.indexOf(':') + 1).trim());
                        } else if (line.startsWith("nonvoluntary_ctxt_switches:")) {
                            involuntary += Long.parseLong(line.substring(line.indexOf(':') + 1).trim());
                        }
                    }
                } catch (IOException e) {
                    // the thread ended while we listed: its switches are lost from both readings alike
                }
            }
        } catch (IOException | UnsupportedOperationException e) {
            return new ProcessCost(cpu, -1, -1);
        }
        return new ProcessCost(cpu, voluntary, involuntary);
    }

    /** @return what was spent between {@code before} and this reading */
    ProcessCost since(ProcessCost before) {
        boolean switches = voluntarySwitches >= 0 && before.voluntarySwitches >= 0;
        return new ProcessCost(cpuNanos - before.cpuNanos,
                switches ? voluntarySwitches - before.voluntarySwitches : -1,
                switches ? involuntarySwitches - before.involuntarySwitches : -1);
    }

    ProcessCost plus(ProcessCost other) {
        boolean switches = voluntarySwitches >= 0 && other.voluntarySwitches >= 0;
        return new ProcessCost(cpuNanos + other.cpuNanos,
                switches ? voluntarySwitches + other.voluntarySwitches : -1,
                switches ? involuntarySwitches + other.involuntarySwitches : -1);
    }

    static ProcessCost zero() {
        return new ProcessCost(0, 0, 0);
    }
}
