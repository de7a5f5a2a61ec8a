package eu.brain.iot.scenario;

import eu.brain.iot.behaviours.warehouse.CartBudget;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.world.SimRules;
import eu.brain.iot.robotsim.world.WarehouseMap;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * One scenario run: robot-sim (embedded, on a free loopback port, its clock at the asked speed and its deadlock
 * threshold at the wait limit), a bare fabric node (own JVM) pointed at it, or several sharing the fleet through a
 * broker ({@link NodeGroup}); then, every 100 ms of wall time, a look at robot-sim's ground truth: faults injected
 * when due, a progress line every few seconds, until every cart is in storage and every robot back in docking, the
 * deadline, or the end of every node. Then the verdict, the summary and the report; every process stopped, also on
 * Ctrl-C (a shutdown hook).
 * <p>
 * Threads: {@link #run} runs on the caller's thread, which owns everything here; the shutdown hook only stops the
 * nodes (then the broker) and closes the simulator, all idempotent.
 */
final class ScenarioRunner {
    private static final Duration NODE_READY_TIMEOUT = Duration.ofSeconds(180);
    private static final Duration EDGE_TIMEOUT = Duration.ofSeconds(60);
    private static final long LOOK_EVERY_MS = 100;
    /** How long the bus counters may take to show an outcome for every command published before the run ended. */
    private static final Duration BUS_SETTLE = Duration.ofSeconds(5);
    /** How long the end of a run waits for a node started again to own its share (its start and a lease period). */
    private static final Duration RESTARTED_SETTLE = Duration.ofSeconds(30);

    private final Options options;
    private final List<String> arguments;
    private final PrintStream out;

    ScenarioRunner(Options options, List<String> arguments, PrintStream out) {
        this.options = options;
        this.arguments = List.copyOf(arguments);
        this.out = out;
    }

    /** The robot behaviour's default planning window ({@code traffic.window}), in steps. */
    private static final int TRAFFIC_WINDOW = 16;

    /** @return the exit code: 0 passed, 1 failed (or could not run) */
    int run() throws UsageException, IOException, InterruptedException {
        WarehouseMap map = Warehouses.of(options);
        checkFaultRobots(map);
        checkCartBudget(map);
        checkTraffic(map);
        Files.createDirectories(options.runDir());
        long wall0 = System.nanoTime();
        SimConfig config = SimConfig.builder().map(map)
                .rules(new SimRules(options.seed(), 2, 2, options.waitLimitSteps(), -1))
                .speed(options.speed()).port(0).build();
        try (RobotSim sim = RobotSim.start(config)) {
            out.printf("robot-sim: warehouse '%s' %dx%d, %d robots, %d carts, %d doors, seed %d, speed x%s, at %s%n",
                    map.name(), map.width(), map.height(), map.robots().size(), map.carts().size(),
                    map.doors().size(), options.seed(), options.speed(), sim.baseUri());
            NodeGroup nodes = NodeGroup.start(options, sim.baseUri(), out);
            Thread hook = new Thread(() -> {
                System.err.println("warehouse-scenario: stopped before the end; stopping the "
                        + (nodes.fabricOfNodes() ? "nodes, the broker" : "node") + " and robot-sim");
                nodes.stop();
                sim.close();
            }, "scenario-shutdown");
            Runtime.getRuntime().addShutdownHook(hook);
            try {
                WorldSnapshot start;
                long startNanos;
                try {
                    nodes.awaitReady(NODE_READY_TIMEOUT);
                    // the run starts when the nodes are up: their edges poll from then on, and behaviours may act
                    // at once, before their REST APIs answer
                    start = new WorldSnapshot(sim.worldDocument());
                    startNanos = System.nanoTime();
                    nodes.markStart(startNanos);
                    List<String> devices = new ArrayList<>(sim.robotIds());
                    devices.addAll(sim.doorIds());
                    nodes.awaitDevices(devices, EDGE_TIMEOUT);
                } catch (IOException e) {
                    out.println("scenario: the " + (nodes.fabricOfNodes() ? "nodes" : "node") + " did not start: "
                            + e.getMessage());
                    return 1;
                }
                return observe(sim, nodes, new Start(start, startNanos, startNanos - wall0));
            } finally {
                nodes.stop();
                try {
                    Runtime.getRuntime().removeShutdownHook(hook);
                } catch (IllegalStateException e) {
                    // already shutting down: the hook runs anyway
                }
            }
        }
    }

    /**
     * With the traffic planner (the default), a map the planner cannot guarantee progress on is refused before
     * anything starts; {@code --no-traffic} runs it without the planner.
     */
    private void checkTraffic(WarehouseMap map) throws UsageException {
        if (!options.traffic()) {
            return;
        }
        var traffic = eu.brain.iot.behaviours.warehouse.traffic.TrafficMap.parse(String.join("\n", map.terrainRows()));
        var why = eu.brain.iot.behaviours.warehouse.traffic.MapCheck.refusal(traffic, TRAFFIC_WINDOW);
        if (why.isPresent()) {
            throw new UsageException("the traffic planner refuses the map '" + map.name() + "': " + why.get()
                    + " (--no-traffic runs it without the planner)");
        }
    }

    /**
     * A warehouse with more carts than its robots' behaviours may lift could never end: refused before anything
     * starts (without behaviours nothing lifts a cart anyway).
     */
    private void checkCartBudget(WarehouseMap map) throws UsageException {
        if (!options.behaviours()) {
            return;
        }
        int robots = map.robots().size();
        int carts = map.carts().size();
        if (carts > CartBudget.cartsFor(robots)) {
            throw new UsageException(String.format("the warehouse '%s' has %d carts, but its %d robots can move at most "
                    + "%d: the robot model lets each robot lift %d (Robot.bip, data int cart = %d), then it stays "
                    + "docked. Use at least %d robots or at most %d carts (--robots and --carts, or a map with fewer carts)",
                    map.name(), carts,
                    robots, CartBudget.cartsFor(robots), CartBudget.PER_ROBOT, CartBudget.PER_ROBOT,
                    CartBudget.robotsFor(carts), CartBudget.cartsFor(robots)));
        }
    }

    private void checkFaultRobots(WarehouseMap map) throws UsageException {
        List<String> ids = map.robots().stream().map(p -> p.id()).toList();
        for (PlannedFault f : options.faults()) {
            try {
                f.check(ids);
            } catch (IllegalArgumentException e) {
                throw new UsageException(e.getMessage());
            }
        }
    }

    /**
     * The run's start: when the nodes were up.
     *
     * @param world          robot-sim's world then
     * @param nanos          {@link System#nanoTime()} then
     * @param nodeStartNanos from the runner's start until then
     */
    private record Start(WorldSnapshot world, long nanos, long nodeStartNanos) {
    }

    private int observe(RobotSim sim, NodeGroup nodes, Start begin) throws IOException, InterruptedException {
        WorldSnapshot start = begin.world();
        long wall0 = begin.nanos();
        long nodeStartNanos = begin.nodeStartNanos();
        FabricNode node = nodes.first();
        out.printf("%s after %.1f s (the run starts at robot-sim step %d), %s the fleet; wait limit "
                        + "%s, deadline %s of warehouse time%n",
                nodes.fabricOfNodes() ? "every node up" : "node up", nodeStartNanos / 1e9, start.step(),
                nodes.fabricOfNodes() ? "their edges see" : "its edge sees",
                WarehouseTime.format(options.waitLimitMs()), WarehouseTime.format(options.deadlineMs()));
        FaultInjector faults = new FaultInjector(sim, nodes, options.faults());
        WorldSnapshot now = start;
        long deliveredAfter = -1;
        long nextProgress = 0;
        Judge.RunEnd how = Judge.RunEnd.FINISHED;
        while (true) {
            now = new WorldSnapshot(sim.worldDocument());
            long t = Figures.elapsedMs(start, now);
            faults.apply(t).forEach(out::println);
            nodes.look(System.nanoTime()).forEach(out::println);
            if (deliveredAfter < 0 && now.allDelivered()) {
                deliveredAfter = t;
            }
            long wall = (System.nanoTime() - wall0) / 1_000_000;
            boolean finished = now.finished();
            if (wall >= nextProgress || finished) {
                out.println(ProgressLine.of(start, now));
                nextProgress = wall + options.progressMs();
            }
            if (finished) {
                break;
            }
            if (t >= options.deadlineMs()) {
                how = Judge.RunEnd.DEADLINE;
                break;
            }
            if (nodes.allEnded()) {
                how = Judge.RunEnd.NODE_ENDED;
                out.println(nodes.fabricOfNodes() ? "scenario: every node ended during the run"
                        : "scenario: the node ended during the run (exit code " + node.exitCode() + "; its log: "
                        + node.log() + ")");
                break;
            }
            Thread.sleep(LOOK_EVERY_MS);
        }
        long endNanos = System.nanoTime();
        long wallMs = (endNanos - wall0) / 1_000_000;
        nodes.endRun(endNanos);
        long cpuMs = nodes.cpuMs();
        for (String late : faults.clear()) {
            // a fault due after the warehouse was done tests nothing: say so rather than pass quietly
            out.println("scenario: fault not done, the run ended first: " + late);
        }
        BusStats bus = null;
        List<Verdict.Check> extra = new ArrayList<>();
        if (nodes.fabricOfNodes()) {
            List<FabricNode> live = nodes.members().stream().map(m -> m.node).filter(FabricNode::alive).toList();
            if (!live.isEmpty()) {
                try {
                    bus = settledBusStats(live);
                } catch (IOException e) {
                    out.println("scenario: could not read the bus statistics: " + e.getMessage());
                }
                extra.addAll(behavioursBack(faults));
            }
            nodes.awaitRestartedOwning(RESTARTED_SETTLE);
            nodes.finalReadings();
            extra.add(FabricChecks.joined(nodes));
            extra.add(FabricChecks.ranUntilTheEnd(nodes));
            Verdict.Check back = FabricChecks.restartedTookAShare(nodes);
            if (back != null) {
                extra.add(back);
            }
        } else if (node.alive()) {
            try {
                bus = settledBusStats(List.of(node));
            } catch (IOException e) {
                out.println("scenario: could not read the bus statistics: " + e.getMessage());
            }
            extra.addAll(behavioursBack(faults));
            if (options.fabric() != null) {
                extra.add(joinedFabric(node));
            }
        } else {
            extra.add(new Verdict.Check("the node ran until the end", false, "it ended during the run (exit code "
                    + node.exitCode() + "; its log: " + node.log() + ")"));
        }
        Verdict judged = Judge.judge(now, options.waitLimitMs(), how, Figures.elapsedMs(start, now));
        List<Verdict.Check> checks = new ArrayList<>(judged.checks());
        checks.addAll(extra);
        Verdict verdict = new Verdict(List.copyOf(checks));
        ReportWriter.Run run = new ReportWriter.Run(arguments, options, start, now, verdict, wallMs,
                nodeStartNanos / 1_000_000, deliveredAfter, bus, cpuMs, faults.log(), node.log(), nodes.logs(),
                nodes.fabricOfNodes() ? nodes.reports() : List.of());
        ReportWriter.write(options.report(), ReportWriter.report(run));
        Summary.print(out, run);
        out.println("report: " + options.report());
        return verdict.passed() ? 0 : 1;
    }

    /**
     * The nodes' bus counters, summed, once every command published has its outcome. When the warehouse is done a
     * door's closing command may still be on its way, and {@code bus:stats} reads one type's counter after another,
     * so a command and its outcome can fall between two reads. Read again until they agree, for at most
     * {@link #BUS_SETTLE}; the last read goes into the report either way, so a command never answered shows.
     */
    private static BusStats settledBusStats(List<FabricNode> live) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + BUS_SETTLE.toNanos();
        BusStats bus = busStats(live);
        while (!bus.everyCommandAnswered() && System.nanoTime() < deadline) {
            Thread.sleep(LOOK_EVERY_MS);
            bus = busStats(live);
        }
        return bus;
    }

    private static BusStats busStats(List<FabricNode> live) throws IOException, InterruptedException {
        BusStats sum = BusStats.parse(List.of());
        for (FabricNode n : live) {
            sum = sum.plus(BusStats.parse(n.shell("bus:stats", Duration.ofSeconds(20))));
        }
        return sum;
    }

    /** With --broker: did the node join the fabric through it (its log says so), and if not, why not? */
    private Verdict.Check joinedFabric(FabricNode node) throws InterruptedException {
        String broker = options.fabric().broker();
        String name = "the node joined the fabric through " + broker;
        try {
            String joined = "Fabric " + Options.Fabric.NAME + ": node " + Options.Fabric.NODE + " joined through "
                    + broker;
            if (Files.readString(node.log()).contains(joined)) {
                return new Verdict.Check(name, true, Options.Fabric.NODE + " in fabric " + Options.Fabric.NAME);
            }
            return new Verdict.Check(name, false, String.join(" ", node.shell("fabric:nodes", Duration.ofSeconds(20)))
                    + " (its log: " + node.log() + ")");
        } catch (IOException e) {
            return new Verdict.Check(name, false, "unknown: " + e.getMessage());
        }
    }

    /** For each behaviour this run stopped: is it active again (brought back by the BMS)? */
    private List<Verdict.Check> behavioursBack(FaultInjector faults) throws InterruptedException {
        List<Verdict.Check> checks = new ArrayList<>();
        for (String name : faults.stoppedBundles()) {
            String state;
            try {
                Bundles.Bundle b = faults.bundle(name);
                state = b == null ? "not installed" : b.state();
            } catch (IOException e) {
                state = "unknown (" + e.getMessage() + ")";
            }
            checks.add(new Verdict.Check("stopped behaviour " + name + " brought back", state.equals("Active"),
                    "at the end: " + state));
        }
        return checks;
    }
}
