package eu.brain.iot.scenario;

import java.io.IOException;
import java.io.PrintStream;
import java.net.URI;
import java.nio.file.Files;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * The run's fabric nodes: one node alone (in the run's folder, as it always was), or node1..nodeN, each its own JVM
 * owning its leased share of the fleet, joined through a broker (the embedded one, started here on a free port,
 * unless {@code --broker} names one). Starts them, waits for them, kills one when a fault says so, reads each
 * node's figures (CPU, {@code fabric:stats}, the devices it owns, its behaviours) every few seconds and at the end,
 * and stops them all, then the broker.
 * <p>
 * Threads: confined to the runner's thread (the members' readings are not shared), except {@link #stop}, which the
 * shutdown hook may call too: it is synchronized and idempotent.
 */
final class NodeGroup {
    /** Wall time between two readings of every node of a fabric (CPU and {@code fabric:stats}). */
    static final Duration READING_EVERY = Duration.ofSeconds(5);
    /** A reading during the run waits this long for a node's shell; a busy node is read again later. */
    private static final Duration READING_SHELL_TIMEOUT = Duration.ofSeconds(5);
    /** How often the end of a run looks whether a node started again owns devices (wall ms). */
    private static final long RESTART_LOOK_MS = 200;
    private static final Duration SHELL_TIMEOUT = Duration.ofSeconds(20);

    /** One node and what is known of it. Confined to the runner's thread. */
    static final class Member {
        final NodeSpec spec;
        /** Its JVM: a new one once it is started again after a kill. */
        FabricNode node;
        final EdgeProbe probe;
        private final java.nio.file.Path configDir;
        private Duration cpu0 = Duration.ZERO;
        private Duration cpuLast;
        /** CPU time and fabric figures of its earlier lives (before a kill), added to the current one's. */
        private Duration cpuEarlier = Duration.ZERO;
        private FabricStats statsEarlier;
        /** The logs of its earlier lives, oldest first. */
        private final List<java.nio.file.Path> logsEarlier = new ArrayList<>();
        private long endNanos = -1;
        private Long killedAtMs;
        private Long restartedAtMs;
        private boolean endTold;
        private FabricStats stats;
        private List<String> owned;
        private List<String> behaviours;

        private Member(NodeSpec spec, FabricNode node, java.nio.file.Path configDir) {
            this.spec = spec;
            this.node = node;
            this.configDir = configDir;
            this.probe = new EdgeProbe(spec.httpPort());
        }

        /** Killed by the run and not started again. */
        boolean killed() {
            return killedAtMs != null && restartedAtMs == null;
        }

        /** Started again after the run killed it. */
        boolean restarted() {
            return restartedAtMs != null;
        }

        /** The devices its edge owned at the last reading, or null when unknown. */
        List<String> owned() {
            return owned;
        }

        private Duration cpuThisLife() {
            return cpuLast == null ? Duration.ZERO : cpuLast.minus(cpu0);
        }
    }

    /** The repository root the nodes run from. */
    private final java.nio.file.Path root;
    private final List<Member> members;
    private final BrokerProcess broker;
    private final NodeSetup.Join join;
    private long startNanos;
    private long nextReadingNanos;

    private NodeGroup(java.nio.file.Path root, List<Member> members, BrokerProcess broker, NodeSetup.Join join) {
        this.root = root;
        this.members = List.copyOf(members);
        this.broker = broker;
        this.join = join;
    }

    /**
     * Starts the broker if the run needs one of its own, writes each node's configuration and starts every node's
     * JVM (without waiting for them: {@link #awaitReady}). Prints a line per process.
     */
    static NodeGroup start(Options o, URI fleet, PrintStream out) throws IOException, InterruptedException {
        List<NodeSpec> specs = NodeSpec.forRun(o);
        BrokerProcess broker = null;
        NodeSetup.Join join = null;
        if (o.fabric() != null) {
            String uri = o.fabric().broker();
            if (uri != null) {
                BrokerReach.check(uri);
            } else {
                broker = BrokerProcess.start(o.root(), o.runDir());
                uri = broker.uri();
                out.printf("broker: embedded, %s (pid %d, log %s)%n", uri, broker.pid(), broker.log());
            }
            join = new NodeSetup.Join(uri, NodeSetup.key(o), o.fabric().name());
            if (specs.size() > 1) {
                out.printf("fabric: %s through %s, key %s, %d nodes%n", join.fabric(), uri, join.key(), specs.size());
            }
        }
        List<Member> members = new ArrayList<>();
        try {
            for (NodeSpec spec : specs) {
                Files.createDirectories(spec.folder());
                java.nio.file.Path configDir = NodeSetup.write(o, fleet, spec, join);
                FabricNode node = FabricNode.start(o.root(), configDir, spec.httpPort(), spec.log(), spec.name());
                members.add(new Member(spec, node, configDir));
                out.printf("%s: pid %d, REST API http://127.0.0.1:%d/sensinact, config %s, log %s%s%n", spec.label(),
                        node.pid(), spec.httpPort(), configDir, node.log(),
                        spec.shared() ? ", share " + spec.number() + "/" + spec.of()
                                + (spec.number() == NodeSetup.DOORS_OWNER ? " and the doors" : "") : "");
            }
        } catch (IOException | RuntimeException e) {
            new NodeGroup(o.root(), members, broker, join).stop();
            throw e;
        }
        return new NodeGroup(o.root(), members, broker, join);
    }

    /** Several nodes sharing the fleet (else one node alone). */
    boolean fabricOfNodes() {
        return members.size() > 1;
    }

    List<Member> members() {
        return members;
    }

    /** Every node's logs, each node's lives in order: node1's first. */
    List<java.nio.file.Path> logs() {
        List<java.nio.file.Path> logs = new ArrayList<>();
        for (Member m : members) {
            logs.addAll(m.logsEarlier);
            logs.add(m.node.log());
        }
        return logs;
    }

    /** The only node, or node1. */
    FabricNode first() {
        return members.get(0).node;
    }

    NodeSetup.Join join() {
        return join;
    }

    /** Waits until every node is up; the first that is not says why, named. */
    void awaitReady(Duration timeout) throws IOException, InterruptedException {
        for (Member m : members) {
            try {
                m.node.awaitReady(timeout);
            } catch (IOException e) {
                throw fabricOfNodes() ? new IOException(m.spec.name() + ": " + e.getMessage(), e) : e;
            }
        }
    }

    /** The run starts now: each node's CPU is counted from here. */
    void markStart(long nanos) {
        startNanos = nanos;
        nextReadingNanos = nanos + READING_EVERY.toNanos();
        for (Member m : members) {
            m.cpu0 = m.node.cpu();
            m.cpuLast = m.cpu0;
        }
    }

    /**
     * Waits until the nodes' edges, together, show every device with status OK.
     *
     * @throws IOException naming the devices missing and, first, what each node's log says kept it out of its fabric
     *                     (a node outside its fabric leases none of its devices)
     */
    void awaitDevices(List<String> devices, Duration timeout) throws IOException, InterruptedException {
        try {
            EdgeProbe.awaitDevices(members.stream().map(m -> m.probe).toList(), devices, timeout);
        } catch (IOException e) {
            List<String> troubles = new ArrayList<>();
            for (Member m : members) {
                FabricTrouble.in(m.node.log()).ifPresent(t -> troubles.add(m.spec.name() + ": " + t));
            }
            if (troubles.isEmpty()) {
                throw e;
            }
            throw new IOException(String.join("; ", troubles) + " (and so " + e.getMessage() + ")", e);
        }
    }

    /** Every node's JVM has ended (killed or by itself): the run cannot go on. */
    boolean allEnded() {
        return members.stream().noneMatch(m -> m.node.alive());
    }

    /**
     * A look during the run: notes the nodes of a fabric that ended by themselves (one line each, once), and reads
     * every live node's CPU and {@code fabric:stats} when {@link #READING_EVERY} has passed.
     *
     * @return lines for the terminal
     */
    List<String> look(long nowNanos) throws InterruptedException {
        List<String> said = new ArrayList<>();
        if (!fabricOfNodes()) {
            return said;
        }
        for (Member m : members) {
            if (!m.node.alive() && !m.killed() && !m.endTold) {
                m.endTold = true;
                m.endNanos = nowNanos;
                said.add("scenario: " + m.spec.name() + " ended during the run (exit code " + m.node.exitCode()
                        + "; its log: " + m.node.log() + ")");
            }
        }
        if (nowNanos >= nextReadingNanos) {
            nextReadingNanos = nowNanos + READING_EVERY.toNanos();
            for (Member m : members) {
                if (m.node.alive() && m.node.up()) { // a node started again answers once it is up
                    readCpu(m);
                    readStats(m, READING_SHELL_TIMEOUT);
                }
            }
        }
        return said;
    }

    /**
     * Kills a node's JVM outright ({@link FabricNode#kill}: SIGKILL), after a last reading of its figures.
     *
     * @return what was done, for the fault log
     */
    String kill(String name, long warehouseMs) throws InterruptedException {
        Member m = members.stream().filter(x -> name.equals(x.spec.name())).findFirst().orElse(null);
        if (m == null) {
            return "no node " + name + ": nothing to kill";
        }
        if (!m.node.alive()) {
            return name + " had already ended (exit code " + m.node.exitCode() + "): not killed";
        }
        finalReading(m, READING_SHELL_TIMEOUT);
        m.node.kill();
        m.killedAtMs = warehouseMs;
        m.endNanos = System.nanoTime();
        return name + " killed (kill -9)";
    }

    /**
     * Starts a node the run killed again, with its configuration and state folder (its output in
     * {@code node-restarted.log} beside the first): it rejoins its fabric, listens for a lease period and gets its
     * share back. Its CPU and fabric figures add up over both lives.
     *
     * @return what was done, for the fault log
     */
    String restart(String name, long warehouseMs) throws IOException {
        Member m = members.stream().filter(x -> name.equals(x.spec.name())).findFirst().orElse(null);
        if (m == null || m.killedAtMs == null || m.node.alive()) {
            return name + " was not killed by the run: not started again";
        }
        m.cpuEarlier = m.cpuEarlier.plus(m.cpuThisLife());
        m.statsEarlier = m.statsEarlier == null ? m.stats : m.statsEarlier.plus(m.stats);
        m.stats = null;
        m.logsEarlier.add(m.node.log());
        java.nio.file.Path log = m.spec.folder().resolve("node-restarted.log");
        m.node = FabricNode.start(root, m.configDir, m.spec.httpPort(), log, m.spec.name());
        m.cpu0 = Duration.ZERO;
        m.cpuLast = null;
        m.endNanos = -1;
        m.endTold = false;
        m.restartedAtMs = warehouseMs;
        return name + " started again (pid " + m.node.pid() + ", log " + log + ")";
    }

    /** The run ended now: every live node's CPU until then. */
    void endRun(long nowNanos) {
        for (Member m : members) {
            if (m.node.alive()) {
                readCpu(m);
                m.endNanos = nowNanos;
            } else if (m.endNanos < 0) {
                m.endNanos = nowNanos;
            }
        }
    }

    /** Every live node's CPU time during the run, summed (a node that ended: until its last reading). */
    long cpuMs() {
        return members.stream().mapToLong(m -> m.cpuEarlier.plus(m.cpuThisLife()).toMillis()).sum();
    }

    /**
     * Waits, up to {@code timeout}, until every node started again and alive has taken devices, as its lease
     * manager logs it ({@code Device leases of node NODE: took [...]}): a node started late in the run takes its
     * share back after the warehouse is done (its start, then a lease period of listening), and its figures are read
     * then. Its edge's device list alone does not say it: right after the start it shows the fleet before the
     * other nodes' reports name their devices' owners.
     */
    void awaitRestartedOwning(Duration timeout) throws InterruptedException {
        long until = System.nanoTime() + timeout.toNanos();
        for (Member m : members) {
            String took = "Device leases of node " + m.spec.name() + ": took [";
            while (m.restarted() && m.node.alive() && System.nanoTime() < until) {
                try {
                    if (Files.readString(m.node.log()).contains(took)) {
                        break;
                    }
                } catch (IOException e) {
                    // not written yet
                }
                Thread.sleep(RESTART_LOOK_MS);
            }
        }
    }

    /** With several nodes: every live node's last figures (its shell and its REST API), at the end of the run. */
    void finalReadings() throws InterruptedException {
        if (!fabricOfNodes()) {
            return;
        }
        for (Member m : members) {
            if (m.node.alive()) {
                finalReading(m, SHELL_TIMEOUT);
            }
        }
    }

    /** The report's per-node section: each node as last read. */
    List<NodeReport> reports() {
        List<NodeReport> reports = new ArrayList<>();
        for (Member m : members) {
            Long cpu = m.cpuLast == null && m.cpuEarlier.isZero() ? null
                    : m.cpuEarlier.plus(m.cpuThisLife()).toMillis();
            long wallMs = m.endNanos < 0 ? 0 : Math.max(0, (m.endNanos - startNanos) / 1_000_000);
            FabricStats stats = m.statsEarlier == null ? m.stats : m.statsEarlier.plus(m.stats);
            reports.add(new NodeReport(m.spec.name(), m.killedAtMs, m.restartedAtMs, m.owned, m.behaviours,
                    stats == null ? null : stats.sentTo(), stats == null ? null : stats.receivedFrom(), cpu, wallMs));
        }
        return reports;
    }

    /** A bundle on the first live node that has it, active there if one is. */
    record Found(Member member, Bundles.Bundle bundle) {
    }

    /** The bundle with that symbolic name on the live nodes (an active one first), or null. */
    Found find(String symbolicName) throws IOException, InterruptedException {
        Found any = null;
        for (Member m : members) {
            if (!m.node.alive()) {
                continue;
            }
            for (Bundles.Bundle b : Bundles.parse(m.node.shell("lb -s", SHELL_TIMEOUT))) {
                if (b.symbolicName().equals(symbolicName)) {
                    if (b.state().equals(Bundles.ACTIVE)) {
                        return new Found(m, b);
                    }
                    any = any == null ? new Found(m, b) : any;
                }
            }
        }
        return any;
    }

    private void finalReading(Member m, Duration timeout) throws InterruptedException {
        readCpu(m);
        readStats(m, timeout);
        try {
            m.behaviours = Bundles.activeBehaviours(Bundles.parse(m.node.shell("lb -s", timeout)));
        } catch (IOException e) {
            // kept from before, or unknown
        }
        try {
            m.owned = m.probe.owned(m.spec.name());
        } catch (IOException e) {
            // kept from before, or unknown
        }
    }

    private static void readCpu(Member m) {
        Duration cpu = m.node.cpu();
        if (cpu.compareTo(Duration.ZERO) > 0) { // zero: the process is gone and the system no longer says
            m.cpuLast = cpu;
        }
    }

    private static void readStats(Member m, Duration timeout) throws InterruptedException {
        try {
            FabricStats stats = FabricStats.parse(m.node.shell("fabric:stats", timeout));
            if (stats != null) {
                m.stats = stats;
            }
        } catch (IOException e) {
            // the shell did not answer in time: the last reading stands
        }
    }

    /**
     * Stops every node still running (SIGTERM to all, then each waited for, SIGKILL after 15 s; a node killed by a
     * fault is not stopped again), then the broker. Idempotent.
     */
    synchronized void stop() {
        members.forEach(m -> m.node.requestStop());
        members.forEach(m -> m.node.stop());
        if (broker != null) {
            broker.stop();
        }
    }
}
