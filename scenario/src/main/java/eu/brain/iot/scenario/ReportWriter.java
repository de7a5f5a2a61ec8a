package eu.brain.iot.scenario;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.TreeMap;

/** Writes the run's JSON report: what was run, the verdict, and the figures of BENCHMARKS.md. Stateless. */
final class ReportWriter {
    static final ObjectMapper MAPPER = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private ReportWriter() {
    }

    static ObjectNode report(Run run) {
        ObjectNode r = MAPPER.createObjectNode();
        WorldSnapshot start = run.start();
        WorldSnapshot end = run.end();
        ArrayNode args = r.putArray("arguments");
        run.arguments().forEach(args::add);
        ObjectNode warehouse = r.putObject("warehouse");
        warehouse.put("map", end.doc().path("name").asText());
        warehouse.put("width", end.doc().path("width").asInt());
        warehouse.put("height", end.doc().path("height").asInt());
        warehouse.put("robots", end.robotCount());
        warehouse.put("carts", end.cartCount());
        warehouse.put("doors", end.doc().path("doors").size());
        warehouse.put("seed", run.options().seed());
        warehouse.put("speed", run.options().speed());
        warehouse.put("stepMillis", end.stepMillis());
        warehouse.put("waitLimitMs", run.options().waitLimitMs());
        warehouse.put("deadlineMs", run.options().deadlineMs());
        r.put("passed", run.verdict().passed());
        ArrayNode checks = r.putArray("checks");
        for (Verdict.Check c : run.verdict().checks()) {
            checks.addObject().put("name", c.name()).put("passed", c.passed()).put("detail", c.detail());
        }
        ObjectNode f = r.putObject("figures");
        f.put("wallSeconds", run.wallMs() / 1000.0);
        f.put("nodeStartSeconds", run.nodeStartMs() / 1000.0);
        long elapsed = Figures.elapsedMs(start, end);
        f.put("warehouseSeconds", elapsed / 1000.0);
        if (run.deliveredAfterMs() >= 0) {
            f.put("warehouseSecondsUntilAllDelivered", run.deliveredAfterMs() / 1000.0);
            f.put("cartsPerWarehouseHour", Figures.cartsPerHour(end.cartCount(), run.deliveredAfterMs()));
        } else {
            f.putNull("warehouseSecondsUntilAllDelivered");
            f.putNull("cartsPerWarehouseHour");
        }
        int doors = end.doc().path("doors").size();
        f.put("doorBoundCartsPerWarehouseHour", Figures.doorBoundCartsPerHour(doors, 1, end.stepMillis()));
        f.put("doorBoundCartsPerWarehouseHourBatched",
                Figures.doorBoundCartsPerHour(doors, Math.max(1, end.robotCount()), end.stepMillis()));
        f.put("fleetBoundCartsPerWarehouseHour", FleetBound.cartsPerHour(start.doc(), end.stepMillis()));
        TrafficFigures.put(f, run.nodeLogs());
        f.put("waitShare", Figures.waitShare(start, end));
        f.put("robotInFrontDetections", end.nearMisses() - start.nearMisses());
        TreeMap<Long, Long> waits = Figures.waits(start, end);
        f.put("waitsEnded", waits.values().stream().mapToLong(Long::longValue).sum());
        f.put("waitMedianMs", Figures.quantile(waits, 0.5) * end.stepMillis());
        f.put("waitMaxMs", end.longestWaitMs());
        f.put("deadlocks", end.deadlocks());
        f.put("doorOpenings", end.doorOpenings());
        f.put("commandsAccepted", end.commandsAccepted());
        f.put("commandsRefused", end.commandsRefused());
        f.put("missionsFailed", end.missionsFailed());
        f.put("missionsCancelled", end.missionsCancelled());
        ObjectNode by = f.putObject("commandsRefusedByStatus");
        end.refusedByStatus().forEach(by::put);
        BusStats bus = run.bus();
        if (bus != null) {
            f.put("busEventsPublished", bus.totalPublished());
            f.put("busEventsPerSecond", run.wallMs() <= 0 ? 0 : bus.totalPublished() * 1000.0 / run.wallMs());
            f.put("busCommandEvents", bus.commandsPublished());
            f.put("busCommandOutcomes", bus.outcomesPublished());
        } else {
            f.putNull("busEventsPerSecond");
        }
        f.put("nodeCpuSeconds", run.nodeCpuMs() / 1000.0);
        f.put("nodeCpuPercentOfOneCore", run.wallMs() <= 0 ? 0 : 100.0 * run.nodeCpuMs() / run.wallMs());
        ArrayNode faults = r.putArray("faults");
        run.faultLog().forEach(faults::add);
        r.put("nodeLog", run.nodeLog().toString());
        if (!run.nodes().isEmpty()) {
            nodes(r.putArray("nodes"), run.nodes());
        }
        return r;
    }

    private static void seconds(ObjectNode o, String field, Long ms) {
        if (ms == null) {
            o.putNull(field);
        } else {
            o.put(field, ms / 1000.0);
        }
    }

    /** The per-node section of a run on several nodes: each node as last read (null where unknown). */
    static void nodes(ArrayNode array, List<NodeReport> nodes) {
        for (NodeReport n : nodes) {
            ObjectNode o = array.addObject();
            o.put("name", n.name());
            seconds(o, "killedAtWarehouseSeconds", n.killedAtWarehouseMs());
            seconds(o, "restartedAtWarehouseSeconds", n.restartedAtWarehouseMs());
            strings(o, "devicesOwned", n.devicesOwned());
            strings(o, "behavioursInstalled", n.behavioursInstalled());
            counts(o, "eventsSentTo", n.eventsSentTo());
            counts(o, "eventsReceivedFrom", n.eventsReceivedFrom());
            if (n.cpuMs() == null) {
                o.putNull("cpuSeconds");
                o.putNull("cpuPercentOfOneCore");
            } else {
                o.put("cpuSeconds", n.cpuMs() / 1000.0);
                o.put("cpuPercentOfOneCore", n.cpuPercentOfOneCore());
            }
        }
    }

    private static void strings(ObjectNode o, String name, List<String> values) {
        if (values == null) {
            o.putNull(name);
        } else {
            values.forEach(o.putArray(name)::add);
        }
    }

    private static void counts(ObjectNode o, String name, java.util.Map<String, Long> values) {
        if (values == null) {
            o.putNull(name);
        } else {
            ObjectNode counts = o.putObject(name);
            new TreeMap<>(values).forEach(counts::put);
        }
    }

    static void write(Path file, ObjectNode report) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        MAPPER.writeValue(file.toFile(), report);
    }

    /**
     * What the report is made from.
     *
     * @param deliveredAfterMs warehouse ms from the start until every cart was in storage, -1 if never
     * @param bus              the nodes' bus counters at the end (summed over the live nodes), or null when they
     *                         could not be read
     * @param nodeCpuMs        the nodes' CPU time during the run, summed
     * @param nodeLog          the node's log (node1's with several)
     * @param nodeLogs         every log of every node (each life of each node), where the traffic figures are read
     * @param nodes            with several nodes, each node's figures; empty for one node alone
     */
    record Run(List<String> arguments, Options options, WorldSnapshot start, WorldSnapshot end, Verdict verdict,
               long wallMs, long nodeStartMs, long deliveredAfterMs, BusStats bus, long nodeCpuMs,
               List<String> faultLog, Path nodeLog, List<Path> nodeLogs, List<NodeReport> nodes) {
    }
}
