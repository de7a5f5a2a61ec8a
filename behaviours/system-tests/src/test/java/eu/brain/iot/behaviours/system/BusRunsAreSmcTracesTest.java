package eu.brain.iot.behaviours.system;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.Supplier;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.door.DoorSmartBehaviour;
import eu.brain.iot.behaviours.door.impl.DoorExterns;
import eu.brain.iot.behaviours.events.ConnectorResolveCollision;
import eu.brain.iot.behaviours.events.ConnectorTypeDoor;
import eu.brain.iot.behaviours.events.DoorBehaviorClosed;
import eu.brain.iot.behaviours.events.RobotBehaviorFromUnloadObstacle;
import eu.brain.iot.behaviours.events.RobotBehaviorStorageToDocking;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadLocation;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadToStorage;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadToUnload;
import eu.brain.iot.behaviours.events.TransitionFired;
import eu.brain.iot.behaviours.orchestrator.OrchestratorSmartBehaviour;
import eu.brain.iot.behaviours.orchestrator.impl.OrchestratorExterns;
import eu.brain.iot.behaviours.robot.RobotSmartBehaviour;
import eu.brain.iot.behaviours.robot.impl.RobotExterns;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.smc.SmcSession;
import eu.brain.iot.bip.system.SystemModel;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * What is verified covers what runs: every run of the deployed behaviours (the Java generated from the models at
 * this build, with their hand-written externs) on a bus, driven by a random environment, is a possible run of the
 * SMC semantics of the deployed system (Listing 4, WarehouseSystem.bip), checked step by step by the interpreter
 * ({@link BusRunChecker}), and ends in the same places and data. The environment sends the robots' poll answers
 * (all five ports, random positions and detections) and the door's "closed", to any robot at any time, so it covers
 * every environment, not only the gate's model of it. Two bus schedules: in order (the environment waits until the
 * behaviours are idle) and interleaved (each behaviour its own queue, deliveries interleaved at random, the
 * environment publishing at any moment), which the fabric's bus can also produce. See bip/README, "Differences
 * between the SMC semantics and the behaviours on the bus", for why each difference listed there is covered or
 * excluded.
 */
class BusRunsAreSmcTracesTest {

    /** Runs per schedule; {@code -Dbus.runs=1000} searches further. */
    private static final int RUNS = Integer.getInteger("bus.runs", 40);
    private static final int EVENTS = 250;

    private static SystemModel system;

    @BeforeAll
    static void load() {
        Path bip = Path.of("..");
        List<Path> modelPath = new ArrayList<>();
        for (String m : List.of("events", "robot", "door", "orchestrator")) {
            modelPath.add(bip.resolve(m).resolve("src/main/bip"));
        }
        Diagnostics d = new Diagnostics();
        system = SmcSession.load(List.of(bip.resolve("events/src/main/bip/WarehouseSystem.bip")), modelPath,
                "WarehouseSystem.Compound", d).orElseThrow(() -> new AssertionError(d.toString())).system();
    }

    /** A run: the behaviours on a recording bus, driven by a seeded random environment. */
    private static final class Run {
        final RecordingBus bus;
        final RobotSmartBehaviour robots;
        final DoorSmartBehaviour door;
        final OrchestratorSmartBehaviour orchestrator;
        final Random env;

        Run(long seed, boolean interleaved) {
            env = new Random(seed);
            bus = new RecordingBus(interleaved ? new Random(seed * 31 + 7) : null);
            Map<String, Object> trace = Map.of("trace", true);
            robots = new RobotSmartBehaviour(bus, RobotExterns.withoutFleet(), trace);
            door = new DoorSmartBehaviour(bus, new DoorExterns(), trace);
            orchestrator = new OrchestratorSmartBehaviour(bus, new OrchestratorExterns(), trace);
            bus.register(robots);
            bus.register(door);
            bus.register(orchestrator);
            for (int i = 0; i < EVENTS; i++) {
                if (interleaved) {
                    // the environment publishes at any moment, the behaviours' queues need not be empty
                    while (env.nextInt(3) != 0 && bus.deliverOne()) {
                        // deliver a few queued events first
                    }
                    bus.deliver(event());
                } else {
                    bus.deliver(event());
                    bus.drain();
                }
            }
            bus.drain();
        }

        /** One of the 16 kinds of environment event, for any robot, with plausible data. */
        private BrainIoTEvent event() {
            String robot = "Robot" + (1 + env.nextInt(3));
            double position = 1 + env.nextInt(3);
            int kind = env.nextInt(16);
            if (kind == 15) {
                DoorBehaviorClosed e = new DoorBehaviorClosed();
                e.component = "DoorInstance";
                return e;
            }
            Supplier<int[]> detect = () -> new int[] {0, 4, 5, 6};
            switch (kind % 5) {
                case 0 -> {
                    RobotBehaviorUnloadLocation e = new RobotBehaviorUnloadLocation();
                    e.component = robot;
                    e.position = position;
                    return e;
                }
                case 1 -> {
                    RobotBehaviorUnloadToUnload e = new RobotBehaviorUnloadToUnload();
                    e.component = robot;
                    e.position = position;
                    e.detect = env.nextInt(8) == 0 ? detect.get()[env.nextInt(4)] : 0;
                    return e;
                }
                case 2 -> {
                    RobotBehaviorFromUnloadObstacle e = new RobotBehaviorFromUnloadObstacle();
                    e.component = robot;
                    e.position = position;
                    e.detect = 4 + env.nextInt(3); // isObstacle, isDoor, inFrontOfCart
                    return e;
                }
                case 3 -> {
                    RobotBehaviorUnloadToStorage e = new RobotBehaviorUnloadToStorage();
                    e.component = robot;
                    e.position = position;
                    return e;
                }
                default -> {
                    RobotBehaviorStorageToDocking e = new RobotBehaviorStorageToDocking();
                    e.component = robot;
                    e.position = position;
                    return e;
                }
            }
        }

        BusRunChecker check() {
            BusRunChecker checker = new BusRunChecker(system, List.of(RobotExterns.withoutFleet(), new DoorExterns(),
                    new OrchestratorExterns()));
            checker.check(bus.log());
            return checker;
        }

        /** The bus's final places and data equal the replay's. */
        void sameEndState(BusRunChecker checker, long seed) {
            for (String c : List.of("Robot1", "Robot2", "Robot3")) {
                same(seed, c, robots.placesOf(c), robots.dataOf(c), checker);
            }
            same(seed, "DoorInstance", door.placesOf("DoorInstance"), door.dataOf("DoorInstance"), checker);
            same(seed, "Orchestrator1", orchestrator.placesOf("Orchestrator1"), orchestrator.dataOf("Orchestrator1"),
                    checker);
        }

        private static void same(long seed, String c, List<String> places, Map<String, Object> data,
                BusRunChecker checker) {
            var atom = checker.run().atom(c);
            assertThat(atom.marking()).as("seed %d: %s's places", seed, c).containsExactlyInAnyOrderElementsOf(places);
            data.forEach((name, value) -> assertThat(atom.get(name)).as("seed %d: %s.%s", seed, c, name)
                    .isEqualTo(value));
        }
    }

    private static void everyRunIsAnSmcRun(boolean interleaved) {
        long steps = 0;
        long reordered = 0;
        long interactions = 0;
        long doorJoined = 0;
        for (long seed = 1; seed <= RUNS; seed++) {
            Run r = new Run(seed, interleaved);
            BusRunChecker checker;
            try {
                checker = r.check();
            } catch (AssertionError e) {
                throw new AssertionError((interleaved ? "interleaved" : "in-order") + " bus, seed " + seed + ": "
                        + e.getMessage(), e);
            }
            r.sameEndState(checker, seed);
            steps += checker.steps();
            reordered += checker.reordered();
            interactions += r.bus.log().stream().filter(p -> p.event() instanceof ConnectorResolveCollision).count();
            doorJoined += r.bus.log().stream().filter(p -> p.event() instanceof TransitionFired t
                    && t.component.equals("DoorInstance") && t.port.equals("openDoor")).count();
        }
        System.out.printf("%s bus: %d runs, %d SMC steps checked (%d taken out of the bus's order), %d collisions "
                + "resolved, %d broadcasts joined by the door%n", interleaved ? "interleaved" : "in-order", RUNS, steps,
                reordered, interactions, doorJoined);
        // the runs are not trivial: every kind of step happens
        assertThat(steps).as("SMC steps checked").isGreaterThan(RUNS * 40L);
        assertThat(interactions).as("collisions resolved (rendezvous of 4)").isGreaterThan(RUNS / 4);
        assertThat(doorJoined).as("broadcasts the door joined").isGreaterThan(RUNS);
        if (!interleaved) {
            assertThat(reordered).as("in order, every step is a candidate where the bus took it").isZero();
        }
    }

    @Test
    void everyRunOnAnInOrderBusIsAnSmcRun() {
        everyRunIsAnSmcRun(false);
    }

    /**
     * On an interleaved bus a broadcast may reach the door after the door changed state (its "closed" event was
     * queued first): the door was open when the robot fired, closes, then joins. That run is still an SMC run, with
     * the door's closing before the interaction (the robot took no step in between); the checker finds that order.
     */
    @Test
    void everyRunOnAnInterleavedBusIsAnSmcRun() {
        everyRunIsAnSmcRun(true);
    }

    /** The checker is not vacuous: a broadcast that a ready door misses is no SMC run (maximal progress). */
    @Test
    void aReadyReceiverMissingABroadcastIsRejected() {
        for (long seed = 1; seed <= RUNS; seed++) {
            Run r = new Run(seed, false);
            List<RecordingBus.Published> log = new ArrayList<>(r.bus.log());
            int join = -1;
            for (int i = 0; i < log.size() && join < 0; i++) {
                if (log.get(i).event() instanceof TransitionFired t && t.component.equals("DoorInstance")
                        && t.port.equals("openDoor") && log.get(i).cause() instanceof ConnectorTypeDoor) {
                    join = i;
                }
            }
            if (join < 0) {
                continue;
            }
            log.remove(join);
            BusRunChecker checker = new BusRunChecker(system, List.of(RobotExterns.withoutFleet(), new DoorExterns(),
                    new OrchestratorExterns()));
            assertThatThrownBy(() -> checker.check(log)).isInstanceOf(AssertionError.class)
                    .hasMessageContaining("interaction Connector1")
                    .hasMessageContaining("which the SMC semantics cannot: this interaction is not enabled and maximal")
                    .hasMessageContaining("Connector1: [DoorInstance.openDoor, Robot");
            return;
        }
        throw new AssertionError("no run had the door join a broadcast");
    }

    /** The checker is not vacuous: a transition the bus did not take, or took out of turn, is found. */
    @Test
    void aStepOutOfTurnIsRejected() {
        Run r = new Run(3, false);
        List<RecordingBus.Published> log = new ArrayList<>(r.bus.log());
        int unload = -1;
        for (int i = 0; i < log.size() && unload < 0; i++) {
            if (log.get(i).event() instanceof TransitionFired t && t.port.equals("unloadLocation")) {
                unload = i;
            }
        }
        assertThat(unload).isNotNegative();
        log.remove(unload); // the robot never left START, yet its next transitions are in the log
        BusRunChecker checker = new BusRunChecker(system, List.of(RobotExterns.withoutFleet(), new DoorExterns(),
                new OrchestratorExterns()));
        assertThatThrownBy(() -> checker.check(log)).isInstanceOf(AssertionError.class)
                .hasMessageContaining("which the SMC semantics cannot");
    }
}
