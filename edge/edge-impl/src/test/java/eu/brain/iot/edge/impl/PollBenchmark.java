package eu.brain.iot.edge.impl;

import java.io.IOException;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.LongAdder;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * The edge's polling benchmark (BENCHMARKS.md, "Edge polling"). Not a test: nothing is asserted, and the
 * name keeps Surefire away from it. Run it with {@code edge/bench/poll-bench.sh}.
 * <p>
 * For each fleet size it starts robot-sim as a separate process on a generated map (clock running, 0.5 s steps),
 * so that the edge's CPU is measured apart from the simulator's, then an {@link Edge} in this JVM that discovers
 * the fleet ({@code GET /}) and polls every robot and door at the configured period, with an event sink that
 * counts what would go to the bus. After a warm-up the poll counters are reset and a measured window follows.
 * Printed per fleet size: polls/s answered, the share of polls on time (request within period &plusmn; 10% of the
 * previous answered poll's), late, failed and skipped polls, the deviation |interval &minus; period| (p50, p99),
 * events/s, the edge's process CPU (and its fleet thread's and HTTP threads'), the simulator's process CPU, GC,
 * and the load average at start and end.
 */
public final class PollBenchmark {

    static final String USAGE = """
            Usage: edge/bench/poll-bench.sh [options]      (edge polling benchmark; not a test)
              --robots LIST        fleet sizes, comma separated (default 100,1000,10000)
              --warmup S           seconds polled before measuring (default 20)
              --duration S         seconds measured (default 30)
              --period-ms N        poll period of each device (default 500)
              --timeout-ms N       request timeout (default 1000)
              --connections N      keep-alive connections to the fleet (default 64)
              --io-threads N       edge HTTP client threads (default 1)
              --moving F           share of robots kept moving: one per docking column, back and forth
                                   between corridor and storage (default 0.1; 0 = every robot idle)
              --seed N             which docking columns move (default 1)
              --nodes N            N edges in this JVM, node K polling share K/N of the fleet (robot number
                                   modulo N, the doors on node 1), as N fabric nodes sharing it (default 1)
              --sim-jar FILE       robot-sim jar (default robot-sim/target/robot-sim.jar)
              --sim-io-threads N   simulator HTTP threads (default: the simulator's, one per core)
              --sim-java-opts S    extra JVM options of the simulator process (default none)
              --width N --height N map size for every fleet size (default: 60x40 up to 100 robots,
                                   200x100 up to 1,000, 2002x60 up to 10,000)
              --help               this text
            Prints one block per fleet size, then a summary table. Exit code 2 on a bad option, 1 when a run
            could not be done.
            """;

    private static final ObjectMapper JSON = new ObjectMapper();

    private final PollBenchmarkOptions o;

    private PollBenchmark(PollBenchmarkOptions o) {
        this.o = o;
    }

    public static void main(String[] args) throws Exception {
        PollBenchmarkOptions o;
        try {
            o = PollBenchmarkOptions.parse(args);
        } catch (IllegalArgumentException e) {
            System.out.println("poll-bench: " + e.getMessage());
            System.out.print(USAGE);
            System.exit(2);
            return;
        }
        if (o == null) {
            System.out.print(USAGE);
            return;
        }
        System.exit(new PollBenchmark(o).runAll());
    }

    private int runAll() throws Exception {
        System.out.printf(Locale.ROOT, "poll-bench: %d cores (%s), %s %s, max heap %d MB; robot-sim %s%n",
                Runtime.getRuntime().availableProcessors(), cpuModel(), System.getProperty("java.vm.name"),
                System.getProperty("java.runtime.version"), Runtime.getRuntime().maxMemory() >> 20, o.simJar);
        System.out.printf(Locale.ROOT, "settings: period %d ms, timeout %d ms, %d connections, %d HTTP thread(s)%s; "
                        + "warm-up %d s, measured %d s; %.0f%% of robots moving%n", o.periodMillis, o.timeoutMillis,
                o.connections, o.ioThreads, o.nodes == 1 ? "" : " per edge, " + o.nodes + " edges",
                o.warmup, o.duration, 100 * o.moving);
        List<Result> results = new ArrayList<>();
        for (int robots : o.robots) {
            try {
                results.add(run(robots));
            } catch (Exception e) {
                System.out.println("poll-bench: the run with " + robots + " robots failed: " + e);
                e.printStackTrace(System.out);
                return 1;
            }
            System.gc();
        }
        System.out.println();
        System.out.println("| robots | polls/s | on time | late | failed | skipped | |dev| p50 / p99 ms | events/s "
                + "| edge CPU (1 core / machine) | µs/poll | fleet thread | HTTP threads | sim CPU | load start / end |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
        for (Result r : results) {
            System.out.println(r.row());
        }
        return 0;
    }

    private Result run(int robots) throws Exception {
        String loadStart = loadAverage();
        int[] size = mapSize(robots);
        Path dir = Files.createTempDirectory("poll-bench");
        Path map = dir.resolve("fleet-" + robots + ".map");
        Path simLog = dir.resolve("robot-sim.log");
        System.out.printf(Locale.ROOT, "%n== %,d robots (map %dx%d), load average %s%n", robots, size[0], size[1],
                loadStart);
        generate(robots, size, map);
        SimulatorProcess sim = SimulatorProcess.start(o, map, simLog);
        try {
            if (o.moving > 0) {
                long t0 = System.nanoTime();
                int sent = sendErrands(sim.base, robots);
                System.out.printf(Locale.ROOT, "%,d robots move back and forth (GoTo missions queued in %.1f s)%n",
                        sent, (System.nanoTime() - t0) / 1e9);
            }
            CountingSink sink = new CountingSink();
            FleetSettings settings = FleetSettings.of(sim.base.toString(), List.of(), List.of(), o.periodMillis,
                    o.timeoutMillis, o.connections, o.ioThreads, 3, Math.max(8_000, o.periodMillis));
            long started = System.nanoTime();
            try (SharedFleetEdges edges = SharedFleetEdges.start(settings, o.nodes, sink)) {
                edges.awaitFirstRound(robots);
                int devices = edges.devices();
                System.out.printf(Locale.ROOT, "%s: %,d devices (robots and doors), %,d answers after %.1f s; "
                        + "warming up %d s%n", o.nodes == 1 ? "edge" : o.nodes + " edges, each its share",
                        devices, edges.merged().answered(), (System.nanoTime() - started) / 1e9, o.warmup);
                TimeUnit.SECONDS.sleep(o.warmup);

                Cpu before = Cpu.now(sim.process);
                long[] nodeCpuBefore = edges.threadCpuNanos();
                long eventsBefore = sink.total.sum();
                edges.resetPollStats();
                TimeUnit.SECONDS.sleep(o.duration);
                PollStats.Snapshot s = edges.merged();
                List<PollStats.Snapshot> perNode = edges.nodes().stream().map(n -> n.edge().pollStats()).toList();
                long[] nodeCpuAfter = edges.threadCpuNanos();
                Cpu after = Cpu.now(sim.process);
                long events = sink.total.sum() - eventsBefore;
                Result r = new Result(robots, devices, o.periodMillis, s, events, before, after, loadStart, loadAverage());
                r.print(sink);
                for (int i = 0; o.nodes > 1 && i < perNode.size(); i++) {
                    PollStats.Snapshot n = perNode.get(i);
                    SharedFleetEdges.Node node = edges.nodes().get(i);
                    System.out.printf(Locale.ROOT, "  %s (share %d/%d): %,d devices, %,.0f polls/s, on time "
                                    + "%.2f%%, late %,d, failed %,d, skipped %,d; |interval - period| p99 %.1f ms; "
                                    + "its edge's threads %.1f%% of one core%n", node.name(), i + 1, o.nodes,
                            node.edge().providers().size(), n.pollsPerSecond(), 100 * n.onTimeShare(), n.late(),
                            n.failed(), n.skipped(), n.deviationP99Millis(),
                            r.percentOfCore(nodeCpuBefore[i], nodeCpuAfter[i]));
                }
                return r;
            }
        } finally {
            sim.stop();
            Files.deleteIfExists(map);
        }
    }

    private int[] mapSize(int robots) {
        if (o.width > 0) {
            return new int[] {o.width, o.height};
        }
        if (robots <= 100) {
            return new int[] {60, 40};
        }
        if (robots <= 1_000) {
            return new int[] {200, 100};
        }
        if (robots <= 10_000) {
            return new int[] {2002, 60}; // 1,000 docking columns: room for 10% movers
        }
        throw new IllegalArgumentException("more than 10,000 robots: give --width and --height");
    }

    private void generate(int robots, int[] size, Path map) throws IOException, InterruptedException {
        Process p = new ProcessBuilder("java", "-jar", o.simJar.toString(), "generate", "--robots",
                String.valueOf(robots), "--carts", String.valueOf(Math.min(2 * robots, 2_000)), "--width",
                String.valueOf(size[0]), "--height", String.valueOf(size[1]), "--out", map.toString())
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (p.waitFor() != 0) {
            throw new IOException("generating the map failed: " + out);
        }
    }

    /**
     * Keeps a share of the robots moving for the whole run, without robots blocking each other: in each chosen
     * docking column, the robot nearest the corridor is given a queue of GoTo missions back and forth between the
     * corridor and the far end of the storage area straight below it (one mover per column, so no two movers
     * meet; robots do not plan around others). Each leg ends a mission, so the edge also sees mission ends.
     *
     * @return how many robots move
     */
    private int sendErrands(URI base, int robots) throws IOException, InterruptedException {
        HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        HttpResponse<String> world = http.send(HttpRequest.newBuilder(base.resolve("world")).build(),
                HttpResponse.BodyHandlers.ofString());
        JsonNode w = JSON.readTree(world.body());
        List<String> rows = new ArrayList<>();
        w.path("map").forEach(r -> rows.add(r.asText()));
        Map<Integer, JsonNode> front = new HashMap<>(); // column -> the robot nearest the corridor
        for (JsonNode r : w.path("robots")) {
            JsonNode f = front.get(r.path("x").asInt());
            if (f == null || r.path("y").asInt() > f.path("y").asInt()) {
                front.put(r.path("x").asInt(), r);
            }
        }
        List<int[]> lanes = new ArrayList<>(); // {x, top, bottom}
        List<String> movers = new ArrayList<>();
        for (Map.Entry<Integer, JsonNode> e : front.entrySet()) {
            int x = e.getKey();
            int y = e.getValue().path("y").asInt() + 1;
            while (y < rows.size() && cell(rows, x, y) == 'd') {
                y++;
            }
            int top = y;
            while (y < rows.size() && cell(rows, x, y) == '.') {
                y++;
            }
            while (y < rows.size() && cell(rows, x, y) == 's') {
                y++;
            }
            int bottom = y - 1;
            if (cell(rows, x, top) == '.' && bottom > top + 1) {
                lanes.add(new int[] {x, top, bottom});
                movers.add(e.getValue().path("id").asText());
            }
        }
        Random random = new Random(o.seed);
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < lanes.size(); i++) {
            order.add(i);
        }
        java.util.Collections.shuffle(order, random);
        int count = Math.min(lanes.size(), (int) Math.round(o.moving * robots));
        if (count < Math.round(o.moving * robots)) {
            System.out.printf(Locale.ROOT, "only %d docking columns: %d robots move instead of %.0f%n", lanes.size(),
                    count, o.moving * robots);
        }
        long runSeconds = o.warmup + o.duration + 30L; // and the time to start
        java.util.concurrent.Semaphore inFlight = new java.util.concurrent.Semaphore(32);
        List<java.util.concurrent.CompletableFuture<?>> pending = new ArrayList<>();
        int legsMax = 0;
        for (int i = 0; i < count; i++) {
            int[] lane = lanes.get(order.get(i));
            legsMax = Math.max(legsMax, (int) (runSeconds * 2 / (lane[2] - lane[1])) + 2);
        }
        for (int leg = 0; leg < legsMax; leg++) { // every robot's missions in order: one leg of all at a time
            for (int i = 0; i < count; i++) {
                int[] lane = lanes.get(order.get(i));
                URI add = base.resolve(movers.get(order.get(i))
                        + "/robot_local_control/NavigationComponent/GoToComponent/add");
                String goal = "{\"x\":" + lane[0] + ",\"y\":" + (leg % 2 == 0 ? lane[2] : lane[1]) + "}";
                inFlight.acquire();
                pending.add(http.sendAsync(HttpRequest.newBuilder(add).header("Content-Type", "application/json")
                        .POST(HttpRequest.BodyPublishers.ofString(goal))
                        .build(), HttpResponse.BodyHandlers.ofString()).whenComplete((a, error) -> {
                            inFlight.release();
                            if (error != null || a.statusCode() != 200) {
                                System.out.println("poll-bench: " + add + " " + goal + ": "
                                        + (error != null ? error : a.statusCode() + " " + a.body()));
                            }
                        }));
            }
            for (java.util.concurrent.CompletableFuture<?> f : pending) {
                f.join();
            }
            pending.clear();
        }
        return count;
    }

    private static char cell(List<String> rows, int x, int y) {
        return y < rows.size() && x < rows.get(y).length() ? rows.get(y).charAt(x) : '#';
    }

    static String loadAverage() {
        try {
            String[] f = Files.readString(Paths.get("/proc/loadavg")).trim().split(" ");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (IOException e) {
            return String.format(Locale.ROOT, "%.2f", ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        }
    }

    private static String cpuModel() {
        try {
            for (String line : Files.readAllLines(Paths.get("/proc/cpuinfo"))) {
                if (line.startsWith("model name")) {
                    return line.substring(line.indexOf(':') + 1).trim();
                }
            }
        } catch (IOException e) {
            // not Linux
        }
        return System.getProperty("os.arch");
    }

    /** What the bus would be handed: counted, by type. */
    private static final class CountingSink implements EventSink {
        final LongAdder total = new LongAdder();
        final Map<String, LongAdder> byType = new ConcurrentHashMap<>();

        @Override
        public boolean offer(BrainIoTEvent event) {
            total.increment();
            byType.computeIfAbsent(event.getClass().getSimpleName(), k -> new LongAdder()).increment();
            return true;
        }
    }

    /** CPU time of this process, of its threads by group, and of the simulator process, at one instant. */
    private record Cpu(long wallNanos, long edgeNanos, long fleetNanos, long httpNanos, long simNanos, long gcCount,
            long gcMillis) {

        static Cpu now(Process sim) {
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            long fleet = 0;
            long http = 0;
            for (ThreadInfo t : threads.getThreadInfo(threads.getAllThreadIds())) {
                if (t == null) {
                    continue;
                }
                long cpu = threads.getThreadCpuTime(t.getThreadId());
                if (cpu < 0) {
                    continue;
                }
                if (t.getThreadName().startsWith("edge-fleet-")) {
                    fleet += cpu;
                } else if (t.getThreadName().startsWith("edge-http-")) {
                    http += cpu;
                }
            }
            long gcCount = 0;
            long gcMillis = 0;
            for (GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
                gcCount += Math.max(0, gc.getCollectionCount());
                gcMillis += Math.max(0, gc.getCollectionTime());
            }
            return new Cpu(System.nanoTime(), cpuNanos(ProcessHandle.current()), fleet, http,
                    cpuNanos(sim.toHandle()), gcCount, gcMillis);
        }

        private static long cpuNanos(ProcessHandle p) {
            return p.info().totalCpuDuration().map(Duration::toNanos).orElse(-1L);
        }
    }

    private record Result(int robots, int devices, long periodMillis, PollStats.Snapshot s, long events, Cpu before, Cpu after, String loadStart,
            String loadEnd) {

        double wallSeconds() {
            return (after.wallNanos - before.wallNanos) / 1e9;
        }

        double percentOfCore(long beforeNanos, long afterNanos) {
            return beforeNanos < 0 || afterNanos < 0 ? Double.NaN
                    : 100.0 * (afterNanos - beforeNanos) / (after.wallNanos - before.wallNanos);
        }

        double edgeCore() {
            return percentOfCore(before.edgeNanos, after.edgeNanos);
        }

        double simCore() {
            return percentOfCore(before.simNanos, after.simNanos);
        }

        void print(CountingSink sink) {
            int cores = Runtime.getRuntime().availableProcessors();
            long due = s.onTime() + s.late() + s.failed() + s.skipped();
            System.out.printf(Locale.ROOT, "measured %.1f s: polls sent %,d, answered %,d = %,.0f polls/s (expected %,.0f)%n",
                    s.seconds(), s.sent(), s.answered(), s.pollsPerSecond(), devices * 1000.0 / periodMillis);
            System.out.printf(Locale.ROOT, "on time %.2f%% (%,d of %,d due); late %,d, failed %,d, skipped %,d; "
                            + "|interval - period| p50 %.1f ms, p99 %.1f ms%n", 100 * s.onTimeShare(), s.onTime(), due,
                    s.late(), s.failed(), s.skipped(), s.deviationP50Millis(), s.deviationP99Millis());
            Map<String, Long> types = new HashMap<>();
            sink.byType.forEach((k, v) -> types.put(k, v.sum()));
            System.out.printf(Locale.ROOT, "events %,d = %,.0f/s (since start, by type: %s)%n", events,
                    events / wallSeconds(), types);
            System.out.printf(Locale.ROOT, "edge CPU %.1f%% of one core = %.1f%% of the machine (%d cores), %.1f µs per "
                            + "answered poll; fleet thread %.1f%%, HTTP threads %.1f%%, other (GC, JIT, ...) %.1f%%; "
                            + "GC %d collections, %d ms%n",
                    edgeCore(), edgeCore() / cores, cores, microsPerPoll(), fleetCore(), httpCore(),
                    edgeCore() - fleetCore() - httpCore(), after.gcCount - before.gcCount,
                    after.gcMillis - before.gcMillis);
            System.out.printf(Locale.ROOT, "robot-sim CPU %.1f%% of one core; load average %s at start, %s at end%n",
                    simCore(), loadStart, loadEnd);
        }

        double microsPerPoll() {
            return s.answered() == 0 ? Double.NaN : (after.edgeNanos - before.edgeNanos) / 1e3 / s.answered();
        }

        double fleetCore() {
            return percentOfCore(before.fleetNanos, after.fleetNanos);
        }

        double httpCore() {
            return percentOfCore(before.httpNanos, after.httpNanos);
        }

        String row() {
            int cores = Runtime.getRuntime().availableProcessors();
            return String.format(Locale.ROOT, "| %,d | %,.0f | %.2f%% | %,d | %,d | %,d | %.1f / %.1f | %,.0f "
                            + "| %.0f%% / %.0f%% | %.0f | %.0f%% | %.0f%% | %.0f%% | %s / %s |", robots, s.pollsPerSecond(),
                    100 * s.onTimeShare(), s.late(), s.failed(), s.skipped(), s.deviationP50Millis(),
                    s.deviationP99Millis(), events / wallSeconds(), edgeCore(), edgeCore() / cores, microsPerPoll(),
                    fleetCore(),
                    httpCore(), simCore(), loadStart, loadEnd);
        }
    }
}
