package eu.brain.iot.robotsim;

import com.fasterxml.jackson.databind.JsonNode;
import eu.brain.iot.robotsim.fault.FaultTable;
import eu.brain.iot.robotsim.http.CommandCounter;
import eu.brain.iot.robotsim.http.CommandOriginLog;
import eu.brain.iot.robotsim.http.HttpServer;
import eu.brain.iot.robotsim.view.CommandOrigins;
import eu.brain.iot.robotsim.view.DoorView;
import eu.brain.iot.robotsim.view.Json;
import eu.brain.iot.robotsim.view.RobotView;
import eu.brain.iot.robotsim.view.ViewPublisher;
import eu.brain.iot.robotsim.view.WorldDocument;
import eu.brain.iot.robotsim.world.Placement;
import eu.brain.iot.robotsim.world.World;
import eu.brain.iot.robotsim.world.WarehouseMap;
import java.io.IOException;
import java.net.URI;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Function;

/**
 * A running simulator: the warehouse world, its step clock and its HTTP server. The public entry point for
 * embedding in tests:
 * <pre>{@code
 * try (RobotSim sim = RobotSim.start(SimConfig.builder().manualStep(true).build())) {
 *     URI state = sim.robotStateUri("robot1");   // GET it over HTTP
 *     sim.step(4);                                // advance the world 4 steps (2 s of warehouse time)
 * }
 * }</pre>
 */
public final class RobotSim implements AutoCloseable {
    private static final long CALL_TIMEOUT_SECONDS = 60;

    private final SimConfig config;
    private final FaultTable faults;
    private final WorldThread world;
    private final HttpServer server;
    private final Map<String, Integer> robots;
    private final Map<String, Integer> doors;
    private final CommandCounter commands;
    private final CommandOriginLog origins;

    private RobotSim(SimConfig config, FaultTable faults, WorldThread world, HttpServer server,
                     Map<String, Integer> robots, Map<String, Integer> doors, CommandCounter commands,
                     CommandOriginLog origins) {
        this.commands = commands;
        this.origins = origins;
        this.config = config;
        this.faults = faults;
        this.world = world;
        this.server = server;
        this.robots = robots;
        this.doors = doors;
    }

    /**
     * Builds the world from the configuration, binds the HTTP server and (unless manual) starts the clock.
     *
     * @throws IOException when the address cannot be bound
     * @throws IllegalArgumentException when a fault names an unknown robot
     */
    public static RobotSim start(SimConfig config) throws IOException {
        WarehouseMap map = config.map();
        Map<String, Integer> robots = indexOf(map.robots());
        Map<String, Integer> doors = indexOf(map.doors());
        FaultTable faults = new FaultTable(robots.size());
        faults.setFleet(config.fleetFaults());
        config.robotFaults().forEach((id, f) -> {
            Integer i = robots.get(id);
            if (i == null) {
                throw new IllegalArgumentException("fault for unknown robot '" + id + "' (the map has "
                        + robots.size() + " robots: robot1.." + "robot" + robots.size() + ")");
            }
            faults.setOwn(i, f);
        });
        WorldThread worldThread = new WorldThread(new World(map, config.rules()), faults,
                config.maxQueuedMissions());
        Map<String, Object> index = new LinkedHashMap<>();
        index.put("name", map.name());
        index.put("width", map.width());
        index.put("height", map.height());
        index.put("stepMillis", config.stepMillis());
        index.put("speed", config.speed());
        index.put("manualStep", config.manualStep());
        index.put("robots", List.copyOf(robots.keySet()));
        index.put("doors", List.copyOf(doors.keySet()));
        CommandCounter commands = new CommandCounter();
        long stepMillis = config.stepMillis();
        ViewPublisher views = worldThread.views();
        CommandOriginLog origins = new CommandOriginLog(() -> views.step() * stepMillis, System::currentTimeMillis,
                CommandOriginLog.DEFAULT_CAPACITY);
        HttpServer server;
        try {
            server = HttpServer.start(config.bindAddress(), config.port(), config.ioThreads(),
                    new HttpServer.Limits(config.allowedHosts(), config.requestTimeoutMillis()),
                    new HttpServer.Wiring(worldThread, worldThread.views(), faults, robots, doors,
                            List.copyOf(robots.keySet()), index, config.stepMillis(), commands, origins));
        } catch (IOException | RuntimeException e) {
            worldThread.close();
            throw e;
        }
        if (!config.manualStep()) {
            worldThread.startClock(config.stepPeriodNanos());
        }
        return new RobotSim(config, faults, worldThread, server, robots, doors, commands, origins);
    }

    private static Map<String, Integer> indexOf(List<Placement> placements) {
        Map<String, Integer> ids = new LinkedHashMap<>();
        for (int i = 0; i < placements.size(); i++) {
            ids.put(placements.get(i).id(), i);
        }
        return java.util.Collections.unmodifiableMap(ids);
    }

    public SimConfig config() {
        return config;
    }

    /** The bound port. */
    public int port() {
        return server.port();
    }

    /** For example {@code http://127.0.0.1:8090/}. */
    public URI baseUri() {
        String host = config.bindAddress().contains(":") ? "[" + config.bindAddress() + "]" : config.bindAddress();
        return URI.create("http://" + host + ":" + port() + "/");
    }

    /** {@code GET} this for a robot's position answer. */
    public URI robotStateUri(String robotId) {
        return baseUri().resolve(robotId + "/robot_local_control/state");
    }

    /** {@code POST {"data":1.0}} here opens the door. */
    public URI doorCommandUri(String doorId) {
        return baseUri().resolve(doorId + "/door_controller/command");
    }

    public URI doorStateUri(String doorId) {
        return baseUri().resolve(doorId + "/door_controller/state");
    }

    public List<String> robotIds() {
        return List.copyOf(robots.keySet());
    }

    public List<String> doorIds() {
        return List.copyOf(doors.keySet());
    }

    /** The latest published state of a robot (what its state endpoint answers). */
    public RobotView robot(String robotId) {
        return world.views().robot(index(robots, robotId, "robot")).view();
    }

    public DoorView door(String doorId) {
        return world.views().door(index(doors, doorId, "door"));
    }

    /** Fault settings, changeable at run time (also through {@code /admin/faults}). */
    public FaultTable faults() {
        return faults;
    }

    /** Advances n steps now (usually in manual mode) and returns the step count after them. */
    public long step(int n) {
        if (n < 0) {
            throw new IllegalArgumentException("n must be >= 0");
        }
        return await(world.step(n));
    }

    /**
     * Runs a read-only look at the world on the world thread and returns its result; the function must not keep
     * references to the world or mutate it.
     */
    public <T> T inspect(Function<World, T> look) {
        return await(world.call(a -> look.apply(a.world())));
    }

    /** What {@code GET /world/counters} answers now (waits, deadlocks, door openings, carts in storage). */
    public JsonNode counters() {
        return inspect(w -> Json.MAPPER.valueToTree(
                WorldDocument.counters(w, config.stepMillis(), commands.snapshot())));
    }

    /** What {@code GET /world} answers now: map, robots, carts, doors and counters. */
    public JsonNode worldDocument() {
        return inspect(w -> Json.MAPPER.valueToTree(
                WorldDocument.world(w, config.stepMillis(), commands.snapshot(), origins.snapshot())));
    }

    /** Which node commanded each robot last, and the hand-overs between nodes ({@code commandOrigins} of /world). */
    public CommandOrigins commandOrigins() {
        return origins.snapshot();
    }

    private static <T> T await(java.util.concurrent.CompletableFuture<T> f) {
        try {
            return f.get(CALL_TIMEOUT_SECONDS, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the world thread", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("world thread task failed: " + e.getCause(), e.getCause());
        } catch (TimeoutException e) {
            throw new IllegalStateException("world thread did not answer in " + CALL_TIMEOUT_SECONDS + " s", e);
        }
    }

    private static int index(Map<String, Integer> ids, String id, String kind) {
        Integer i = ids.get(id);
        if (i == null) {
            throw new IllegalArgumentException("unknown " + kind + " '" + id + "'");
        }
        return i;
    }

    @Override
    public void close() {
        server.close();
        world.close();
    }
}
