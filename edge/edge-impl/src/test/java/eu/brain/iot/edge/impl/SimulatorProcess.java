package eu.brain.iot.edge.impl;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.List;
import java.util.concurrent.TimeUnit;

/** The robot simulator in its own process, for {@link PollBenchmark}. */
final class SimulatorProcess {
    final Process process;
    final URI base;
    private final Deque<String> tail;

    private SimulatorProcess(Process process, URI base, Deque<String> tail) {
        this.process = process;
        this.base = base;
        this.tail = tail;
    }

    static SimulatorProcess start(PollBenchmarkOptions o, Path map, Path log) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of("java"));
        if (!o.simJavaOpts.isBlank()) {
            command.addAll(Arrays.asList(o.simJavaOpts.trim().split("\\s+")));
        }
        command.addAll(List.of("-jar", o.simJar.toString(), "--port", "0", "--map", map.toString(), "--quiet"));
        if (o.simIoThreads > 0) {
            command.addAll(List.of("--io-threads", String.valueOf(o.simIoThreads)));
        }
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        Deque<String> tail = new ArrayDeque<>();
        BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        URI base = null;
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        String line;
        while (base == null && (line = out.readLine()) != null) {
            remember(tail, line);
            if (line.startsWith("robot-sim:")) {
                System.out.println(line);
            }
            if (line.startsWith("listening on ")) {
                base = URI.create(line.substring("listening on ".length()).trim());
            }
            if (System.nanoTime() > deadline) {
                break;
            }
        }
        if (base == null) {
            p.destroyForcibly();
            throw new IOException("robot-sim did not start: " + String.join(" | ", tail));
        }
        Thread drain = new Thread(() -> {
            try {
                String l;
                while ((l = out.readLine()) != null) {
                    synchronized (tail) {
                        remember(tail, l);
                    }
                }
            } catch (IOException e) {
                // the process ended
            }
        }, "robot-sim-output");
        drain.setDaemon(true);
        drain.start();
        return new SimulatorProcess(p, base, tail);
    }

    private static void remember(Deque<String> tail, String line) {
        if (tail.size() == 20) {
            tail.removeFirst();
        }
        tail.addLast(line);
    }

    void stop() throws InterruptedException {
        if (!process.isAlive()) {
            synchronized (tail) {
                System.out.println("robot-sim had ended (exit " + process.exitValue() + "): "
                        + String.join(" | ", tail));
            }
            return;
        }
        process.destroy();
        if (!process.waitFor(10, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor();
        }
    }
}
