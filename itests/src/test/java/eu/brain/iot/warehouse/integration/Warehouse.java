package eu.brain.iot.warehouse.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/**
 * One warehouse run for a test: robot-sim embedded (its Java API) at a speed factor, the edge configured to poll
 * it over real HTTP at the matching period, the behaviours' timing configured for the same speed (Config Admin:
 * PIDs eu.brain.iot.behaviours.robot and eu.brain.iot.behaviours.door), every command outcome on the bus recorded,
 * and the ground truth read from robot-sim's {@code GET /world}. Constructed, it has the behaviours stopped, the
 * edge moved to this simulator and its device model filled from it, then the behaviours started afresh; closed after
 * the test: configurations deleted, the edge gone from the simulator, the simulator stopped.
 */
final class Warehouse implements AutoCloseable {

    static final String EDGE_PID = "eu.brain.iot.edge";
    static final String ROBOT_PID = "eu.brain.iot.behaviours.robot";
    static final String DOOR_PID = "eu.brain.iot.behaviours.door";

    /**
     * The speed factor of the tests' warehouses: 10 steps per 0.5 s of wall time. A head-on meeting is reported after
     * 10 steps (the behaviours' patience) and must be resolved before robot-sim counts a deadlock (20 steps, REQ-2's
     * 10 s): that leaves 500 ms of wall time for the rendezvous, the commands and the first moves on a loaded
     * 2-core machine (at speed 20, 250 ms was not always enough).
     */
    static final double SPEED = 10;

    /**
     * A warehouse of this map at {@link #SPEED}, seed 1, where robots waiting on each other for 20 steps (10 s of
     * warehouse time, REQ-2's limit) count as a deadlock.
     */
    static SimConfig config(eu.brain.iot.robotsim.world.WarehouseMap map) {
        return config(map, SPEED);
    }

    /** The same at another speed factor. */
    static SimConfig config(eu.brain.iot.robotsim.world.WarehouseMap map, double speed) {
        return SimConfig.builder().map(map).speed(speed).rules(new eu.brain.iot.robotsim.world.SimRules(1L, 2, 2, 20,
                -1)).build();
    }

    /** The behaviour bundles, in the order they are started. */
    static final List<String> BEHAVIOURS = List.of("eu.brain.iot.behaviours.orchestrator",
            "eu.brain.iot.behaviours.door", "eu.brain.iot.behaviours.robot");

    /** How long the edge may take to move to a new fleet, or away from one (Config Admin applies a change later). */
    private static final Duration EDGE_DEADLINE = Duration.ofSeconds(20);

    final RobotSim sim;
    final double speed;
    final List<CommandOutcome> outcomes = new CopyOnWriteArrayList<>();
    private final List<Configuration> configurations = new ArrayList<>();
    private final HttpClient http = HttpClient.newHttpClient();
    private final ObjectMapper json = new ObjectMapper();
    private final BundleContext context;
    private final DeviceModel model;
    private final String fleetUrl;
    private ServiceRegistration<?> recorder;

    /**
     * Starts the simulator and returns once the behaviours run on it. In this order: the behaviours stop (those of
     * the previous warehouse must not act on this one's robots, nor see its first polls with their old state); the
     * edge is pointed at this simulator; it polls it and its device model holds this fleet's robots, doors, carts
     * and map (not the previous simulator's: see {@link #awaitEdge}); the behaviours start, and their first look at
     * the device model is this warehouse as it stands.
     */
    Warehouse(BundleContext context, ConfigurationAdmin cm, DeviceModel model, SimConfig config) throws Exception {
        this.context = context;
        this.model = model;
        this.sim = RobotSim.start(config);
        this.speed = config.speed();
        this.fleetUrl = sim.baseUri().toString();
        try {
            List<Bundle> behaviours = behaviourBundles(context);
            for (Bundle b : behaviours) {
                b.stop();
            }
            long poll = Math.max(5, Math.round(500 / speed));
            configure(cm, ROBOT_PID, Map.of("speed", speed));
            configure(cm, DOOR_PID, Map.of("speed", speed));
            Instant configuredAt = Instant.now();
            configure(cm, EDGE_PID, Map.of("fleet.url", fleetUrl, "poll.period.ms", poll,
                    "world.period.ms", 4 * poll, "backoff.max.ms", 40 * poll));
            awaitEdge(configuredAt);
            // the outcomes of this warehouse's commands only, from the behaviours started next
            Hashtable<String, Object> props = new Hashtable<>();
            props.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { CommandOutcome.class.getName() });
            recorder = context.registerService(SmartBehaviour.class.getName(),
                    (SmartBehaviour<BrainIoTEvent>) e -> outcomes.add((CommandOutcome) e), props);
            // started in the order of BEHAVIOURS, each afresh (its models' places and data), as on a new node
            for (Bundle b : behaviours) {
                b.start();
            }
        } catch (Exception | Error e) {
            try {
                close();
            } catch (Exception | Error c) {
                e.addSuppressed(c);
            }
            throw e;
        }
    }

    /** The behaviour bundles installed, in the order of {@link #BEHAVIOURS}. */
    private static List<Bundle> behaviourBundles(BundleContext context) {
        List<Bundle> behaviours = new ArrayList<>();
        for (String name : BEHAVIOURS) {
            for (Bundle b : context.getBundles()) {
                if (name.equals(b.getSymbolicName())) {
                    behaviours.add(b);
                }
            }
        }
        return behaviours;
    }

    private void configure(ConfigurationAdmin cm, String pid, Map<String, Object> values) throws IOException {
        Configuration c = cm.getConfiguration(pid, "?");
        c.update(new Hashtable<>(values));
        configurations.add(c);
    }

    /**
     * Waits until the edge polls this simulator and its device model holds this fleet as it stands (the behaviours
     * are stopped: nothing moves): the edge's {@code fleetUrl} is this simulator's; its robots and doors are exactly
     * this fleet's, each {@code OK} from a poll answered since it was configured, each robot where robot-sim has it;
     * its carts are exactly this world's, where robot-sim has them; its map is this world's. Counting providers is
     * not enough: the edge keeps devices under their ids across a change of fleet, and the carts and map of the
     * previous simulator stay until it reads this one's world, so a model of the previous warehouse, its carts in
     * storage, has the same counts.
     */
    private void awaitEdge(Instant configuredAt) throws IOException, InterruptedException {
        JsonNode world = world();
        List<String> devices = new ArrayList<>(sim.robotIds());
        devices.addAll(sim.doorIds());
        await("the edge polls the fleet at " + fleetUrl + " and its model holds that fleet").atMost(EDGE_DEADLINE)
                .pollInterval(Duration.ofMillis(50)).untilAsserted(() -> {
                    assertThat(edgeFleetUrl()).as("the edge's fleet").isEqualTo(fleetUrl);
                    List<ProviderSnapshot> providers = model.providers();
                    assertThat(providers).filteredOn(p -> p.kind().equals("robot") || p.kind().equals("door"))
                            .allSatisfy(p -> {
                                assertThat(p.status()).as(p.id() + ": " + p.reason()).isEqualTo(ResourceStatus.OK);
                                assertThat(p.lastPoll()).as(p.id() + "'s last poll").isAfter(configuredAt);
                            }).extracting(ProviderSnapshot::id).containsExactlyInAnyOrderElementsOf(devices);
                    for (JsonNode r : world.get("robots")) {
                        assertThat(cell(r.get("id").asText())).as(r.get("id").asText())
                                .isEqualTo(r.get("x").asInt() + "," + r.get("y").asInt());
                    }
                    List<String> carts = new ArrayList<>();
                    world.get("carts").forEach(c -> carts.add(c.get("id").asText() + "@" + c.get("x").asInt() + ","
                            + c.get("y").asInt()));
                    assertThat(providers).filteredOn(p -> p.kind().equals("cart"))
                            .extracting(p -> p.id() + "@" + cell(p.id())).containsExactlyInAnyOrderElementsOf(carts);
                    List<String> rows = new ArrayList<>();
                    world.get("map").forEach(row -> rows.add(row.asText()));
                    assertThat(model.resource("warehouse", "map", "rows").map(ResourceValue::value))
                            .as("the map").contains(String.join("\n", rows));
                });
    }

    /** @return {@code x,y} of a provider's position in the device model, or {@code null} */
    private String cell(String provider) {
        Object x = model.resource(provider, "position", "x").map(ResourceValue::value).orElse(null);
        Object y = model.resource(provider, "position", "y").map(ResourceValue::value).orElse(null);
        return x == null || y == null ? null : ((Number) x).intValue() + "," + ((Number) y).intValue();
    }

    /** @return the fleet URL the edge polls now (its {@link PollMonitor}), {@code null} without an edge */
    private String edgeFleetUrl() {
        ServiceReference<PollMonitor> ref = context.getServiceReference(PollMonitor.class);
        if (ref == null) {
            return null;
        }
        try {
            PollMonitor monitor = context.getService(ref);
            return monitor == null ? null : monitor.statistics().fleetUrl;
        } finally {
            context.ungetService(ref);
        }
    }

    /**
     * Reads the world until {@code done} holds, at most {@code seconds}.
     *
     * @return the world that satisfied it
     * @throws AssertionError saying what the world looked like at the end
     */
    JsonNode until(String what, int seconds, java.util.function.Predicate<JsonNode> done) throws Exception {
        JsonNode[] last = { world() };
        try {
            await(what).atMost(Duration.ofSeconds(seconds)).pollInterval(Duration.ofMillis(100)).until(() -> {
                last[0] = world();
                return done.test(last[0]);
            });
        } catch (org.awaitility.core.ConditionTimeoutException e) {
            throw new AssertionError(what + ": not within " + seconds + " s; " + describe(last[0]) + "; behaviours "
                    + behaviours(), e);
        }
        return last[0];
    }

    /** @return the smart behaviours registered now, by component name and bundle state, for failure messages */
    private String behaviours() {
        StringBuilder b = new StringBuilder();
        try {
            org.osgi.framework.ServiceReference<?>[] refs = context.getServiceReferences(
                    SmartBehaviour.class.getName(), null);
            for (org.osgi.framework.ServiceReference<?> r : refs == null ? new org.osgi.framework.ServiceReference<?>[0]
                    : refs) {
                b.append(r.getProperty("component.name")).append('/').append(r.getBundle().getState()).append(' ');
            }
        } catch (org.osgi.framework.InvalidSyntaxException e) {
            b.append(e.getMessage());
        }
        return b.toString();
    }

    /** robot-sim's {@code GET /world}: its ground truth. */
    JsonNode world() throws IOException, InterruptedException {
        HttpResponse<String> r = http.send(HttpRequest.newBuilder(sim.baseUri().resolve("world")).build(),
                HttpResponse.BodyHandlers.ofString());
        return json.readTree(r.body());
    }

    /** @return the area code robot-sim's map gives a cell (0 corridor, 1 docking, 2 unload, 3 storage, 5 door) */
    static int area(JsonNode world, int x, int y) {
        char c = world.get("map").get(y).asText().charAt(x);
        return switch (c) {
            case 'd' -> 1;
            case 'u' -> 2;
            case 's' -> 3;
            case 'D' -> 5;
            default -> 0;
        };
    }

    /** Every cart stands on the floor of the storage area. */
    static boolean cartsInStorage(JsonNode world) {
        for (JsonNode c : world.get("carts")) {
            if (!c.get("carriedBy").isNull() || area(world, c.get("x").asInt(), c.get("y").asInt()) != 3) {
                return false;
            }
        }
        return true;
    }

    /** Every robot stands in the docking area with no mission left. */
    static boolean robotsDocked(JsonNode world) {
        for (JsonNode r : world.get("robots")) {
            JsonNode m = r.get("mission");
            boolean idle = m == null || m.isNull() || m.get("state").asText().matches("finished|failed");
            if (r.get("area").asInt() != 1 || !idle) {
                return false;
            }
        }
        return true;
    }

    /** @return what the world shows, short: carts and robots with their cells, for assertion messages */
    static String describe(JsonNode world) {
        StringBuilder s = new StringBuilder("step ").append(world.get("step")).append(": ");
        for (JsonNode c : world.get("carts")) {
            s.append(c.get("id").asText()).append('@').append(c.get("x")).append(',').append(c.get("y"))
                    .append(c.get("carriedBy").isNull() ? "" : "^" + c.get("carriedBy").asText()).append(' ');
        }
        for (JsonNode r : world.get("robots")) {
            s.append(r.get("id").asText()).append('@').append(r.get("x")).append(',').append(r.get("y"))
                    .append(" detect ").append(r.get("detect")).append(' ');
        }
        return s.append("counters ").append(world.get("counters")).toString();
    }

    /**
     * Deletes the configurations, waits until the edge has left this simulator, then stops it. Config Admin applies
     * the deletion later: a simulator stopped at once would be polled closed meanwhile, its devices made
     * {@code STALE} or {@code UNREACHABLE} in a model the next warehouse starts from.
     */
    @Override
    public void close() throws Exception {
        try {
            if (recorder != null) {
                recorder.unregister();
                recorder = null;
            }
            for (Configuration c : configurations) {
                c.delete();
            }
            configurations.clear();
            await("the edge leaves the fleet at " + fleetUrl).atMost(EDGE_DEADLINE)
                    .until(() -> !fleetUrl.equals(edgeFleetUrl()));
        } finally {
            sim.close();
        }
    }
}
