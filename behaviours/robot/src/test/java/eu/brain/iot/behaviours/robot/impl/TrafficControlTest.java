package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.CommandLedger;
import eu.brain.iot.behaviours.warehouse.FleetView;
import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceListener;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;

/**
 * The robots' legs along their reserved paths ({@link TrafficControl}): straight runs, the next sent once the robot
 * stands at the end of the one before, a leg blocked for three looks cancelled. One robot on an open floor, its
 * device model written by the test.
 */
class TrafficControlTest {

    private static final String MAP = String.join("\n",
            "############",
            "#..........#",
            "#..........#",
            "############");

    private final Model model = new Model();
    private final RobotCommandsTest.Bus bus = new RobotCommandsTest.Bus();
    private final CommandLedger ledger = new CommandLedger(bus, "t-");
    private final RobotCommands commands = new RobotCommands(ledger);
    private final List<String> walledIn = new ArrayList<>();
    private final TrafficControl traffic = new TrafficControl(new FleetView(model), commands, 16,
            TimeUnit.SECONDS.toNanos(5), TimeUnit.MINUTES.toNanos(1),
            (robot, goal) -> walledIn.add(robot + " " + goal));

    /** The robot at (1,1) with its goal at (10,2) is sent on its first leg, which the edge accepts: its end. */
    private Cell firstLeg() {
        model.robot(1, 1, "stopped", 0, null, null);
        traffic.goal("robot1", new Cell(10, 2));
        traffic.step();
        GoToCommand first = lastGoTo();
        Cell end = new Cell(first.x, first.y);
        assertThat(inLine(new Cell(1, 1), end)).as("the first leg runs straight from the robot").isTrue();
        answer(first);
        return end;
    }

    @Test
    void aRobotWhoseNodeStoppedReportingItGetsNoLegUntilReportedAgain() {
        model.status = ResourceStatus.STALE; // the node that polls it died: its last values linger in the model
        model.robot(1, 1, "stopped", 0, null, null);
        traffic.goal("robot1", new Cell(10, 2));
        traffic.step();
        assertThat(bus.sent).as("nothing sent from values no poll confirms").isEmpty();

        model.status = ResourceStatus.OK; // polled again, by the node that took it over
        model.robot(1, 1, "stopped", 0, null, null);
        traffic.step();
        assertThat(bus.sent).hasSize(1);
    }

    @Test
    void aRobotGetsItsNextLegOnlyOnceSeenStandingAtTheEndOfTheOneBefore() {
        Cell end = firstLeg();
        Cell before = end.distance(new Cell(1, 1)) == 1 ? new Cell(1, 1) : step(end, new Cell(1, 1));
        model.robot(before.x(), before.y(), "running", 0, "running", end);
        traffic.step();
        assertThat(bus.sent).as("nothing while it drives its leg").hasSize(1);

        model.robot(end.x(), end.y(), "stopped", 0, "finished", end);
        traffic.step();
        GoToCommand next = lastGoTo();
        Cell nextEnd = new Cell(next.x, next.y);
        assertThat(inLine(end, nextEnd)).as("straight on from where it stands").isTrue();
        assertThat(nextEnd.distance(new Cell(10, 2))).isLessThan(end.distance(new Cell(10, 2)));
    }

    @Test
    void aCarrierWhoseGoalCartsPutDownSinceWalledInIsReportedAfterRoundsWithoutProgress() {
        model.carrying("cart1");
        model.robot(1, 1, "stopped", 0, null, null);
        model.cartOnTheFloor("cart8", 9, 2);
        model.cartOnTheFloor("cart9", 10, 1); // (10,2) walled in: a robot carrying a cart cannot drive under them
        traffic.goal("robot1", new Cell(10, 2));
        traffic.step(); // its first round with this goal
        for (int round = 1; round < TrafficControl.WALLED_IN_ROUNDS; round++) {
            traffic.step();
        }
        assertThat(walledIn).as("not before it went %d rounds without progress", TrafficControl.WALLED_IN_ROUNDS)
                .isEmpty();
        traffic.step();
        assertThat(walledIn).containsExactly("robot1 (10,2)");
    }

    /**
     * A row of carts between a carrier and its goal two cells away, open only at both ends 15 cells off: the way round
     * is longer than the planner's window, and every cell of it looks farther from the goal than where the robot
     * stands (the planner's distances see the map without the carts), so the planner holds it there; after
     * {@link TrafficControl#WALLED_IN_ROUNDS} rounds without progress it is reported like a walled-in goal.
     */
    @Test
    void aCarrierWhoseGoalOnlyTheLongWayRoundReachesIsReportedAfterRoundsWithoutProgress() {
        Model wide = new Model(String.join("\n",
                "##################################",
                "#................................#",
                "#................................#",
                "#................................#",
                "##################################"));
        List<String> told = new ArrayList<>();
        TrafficControl control = new TrafficControl(new FleetView(wide), commands, 16, TimeUnit.SECONDS.toNanos(5),
                TimeUnit.MINUTES.toNanos(1),
                (robot, goal) -> told.add(robot + " " + goal));
        wide.carrying("cart1");
        wide.robot(16, 3, "stopped", 0, null, null);
        for (int x = 2; x <= 31; x++) {
            wide.cartOnTheFloor("cart" + (100 + x), x, 2);
        }
        control.goal("robot1", new Cell(16, 1));
        control.step(); // its first round with this goal
        for (int round = 1; round <= TrafficControl.WALLED_IN_ROUNDS; round++) {
            assertThat(told).as("round %d", round).isEmpty();
            control.step();
        }
        assertThat(bus.sent).as("held where it stands: no leg sent").isEmpty();
        assertThat(told).containsExactly("robot1 (16,1)");
    }

    @Test
    void aRobotBlockedOnItsLegForThreeLooksHasItCancelled() {
        Cell end = firstLeg();
        Cell before = end.distance(new Cell(1, 1)) == 1 ? new Cell(1, 1) : step(end, new Cell(1, 1));
        model.robot(before.x(), before.y(), "stopped", 1, "running", end); // a robot in front
        traffic.step();
        traffic.step();
        assertThat(bus.sent).as("two looks: it may still go on").hasSize(1);
        traffic.step();
        assertThat(bus.sent).hasSize(2).last().isInstanceOf(CancelMissionCommand.class);
    }

    /**
     * The edge shows a go-to only a while after it was sent (its answer, then the next poll): until then the robot
     * looks idle where it stood, and a leg planned from there would queue behind the one it drives.
     */
    @Test
    void aLegIsNotSentAgainBeforeTheDeviceModelShowsItsMission() {
        TrafficControl control = new TrafficControl(new FleetView(model), commands, 16, 0,
                TimeUnit.MINUTES.toNanos(1), (robot, goal) -> { });
        model.robot(1, 1, "stopped", 0, null, null);
        control.goal("robot1", new Cell(10, 2));
        control.step();
        GoToCommand first = lastGoTo();
        Cell end = new Cell(first.x, first.y);
        control.step();
        assertThat(bus.sent).as("not answered yet").hasSize(1);

        answer(first, 7L);
        control.step();
        assertThat(bus.sent).as("accepted as mission 7, the model still shows mission 1").hasSize(1);

        model.missionId = 7;
        model.robot(end.x(), end.y(), "stopped", 0, "finished", end);
        control.step();
        assertThat(bus.sent).as("mission 7 shown done at the leg's end: the next leg").hasSize(2);
        GoToCommand next = lastGoTo();
        assertThat(inLine(end, new Cell(next.x, next.y))).isTrue();
    }

    @Test
    void aLegAcceptedButNeverShownIsTakenAsLostAndSentAgain() {
        TrafficControl control = new TrafficControl(new FleetView(model), commands, 16, 0, 0, (robot, goal) -> { });
        model.robot(1, 1, "stopped", 0, null, null);
        control.goal("robot1", new Cell(10, 2));
        control.step();
        answer(lastGoTo(), 7L);
        control.step();
        assertThat(bus.sent).as("mission 7 not shown within the bound (none here): the leg again").hasSize(2)
                .allMatch(c -> c instanceof GoToCommand);
    }

    @Test
    void aBlockedLegIsCancelledOnceWhileTheCancelIsNotAnswered() {
        Cell end = firstLeg();
        Cell before = end.distance(new Cell(1, 1)) == 1 ? new Cell(1, 1) : step(end, new Cell(1, 1));
        model.robot(before.x(), before.y(), "stopped", 1, "running", end);
        for (int look = 0; look < 3 * 3; look++) {
            traffic.step();
        }
        assertThat(bus.sent).as("the go-to, then one cancel").hasSize(2).last()
                .isInstanceOf(CancelMissionCommand.class);
        answer(bus.sent.get(1));
        assertThat(bus.sent).as("no second cancel queued behind the first").hasSize(2);
    }

    private GoToCommand lastGoTo() {
        assertThat(bus.sent).isNotEmpty().last().isInstanceOf(GoToCommand.class);
        return (GoToCommand) bus.sent.get(bus.sent.size() - 1);
    }

    /** The edge answers the command: the robot's next command may go out. */
    private void answer(EdgeCommand c) {
        answer(c, null);
    }

    /** The edge answers the command, a mission the robot queued as {@code missionId}. */
    private void answer(EdgeCommand c, Long missionId) {
        CommandOutcome o = new CommandOutcome();
        o.missionId = missionId;
        o.commandId = c.commandId;
        o.deviceId = c.deviceId;
        o.accepted = true;
        commands.answered(o, sent -> null);
    }

    private static boolean inLine(Cell a, Cell b) {
        return !a.equals(b) && (a.x() == b.x() || a.y() == b.y());
    }

    /** @return the cell one step from {@code end} towards {@code from} */
    private static Cell step(Cell end, Cell from) {
        return new Cell(end.x() + Integer.signum(from.x() - end.x()), end.y() + Integer.signum(from.y() - end.y()));
    }

    /** The edge's device model of one robot on {@link #MAP}. */
    static final class Model implements DeviceModel {
        private final String map;
        private ProviderSnapshot robot;
        private final List<ProviderSnapshot> carts = new ArrayList<>();
        private String cart;

        Model() {
            this(MAP);
        }

        Model(String map) {
            this.map = map;
        }

        /** The robot carries this cart from now on (set before {@link #robot}). */
        void carrying(String id) {
            cart = id;
        }

        void cartOnTheFloor(String id, int x, int y) {
            carts.add(new ProviderSnapshot(id, "cart", ResourceStatus.OK, Instant.now(), null, Map.of("position",
                    Map.of("x", value("position", "x", x), "y", value("position", "y", y))), Map.of()));
        }

        /** The id of the mission the robot shows. */
        long missionId = 1;
        /** The robot's status in the model: {@code STALE} when another node polls it and stopped reporting it. */
        ResourceStatus status = ResourceStatus.OK;

        void robot(int x, int y, String state, int detect, String missionState, Cell goal) {
            Map<String, Map<String, ResourceValue>> services = new LinkedHashMap<>();
            services.put("position", Map.of("x", value("position", "x", x), "y", value("position", "y", y),
                    "area", value("position", "area", 0), "heading", value("position", "heading", "E")));
            services.put("state", Map.of("state", value("state", "state", state),
                    "detect", value("state", "detect", detect)));
            if (missionState != null) {
                services.put("mission", Map.of("type", value("mission", "type", "goto"),
                        "state", value("mission", "state", missionState), "id", value("mission", "id", missionId),
                        "goalX", value("mission", "goalX", goal.x()), "goalY", value("mission", "goalY", goal.y())));
            }
            if (cart != null) {
                services.put("cart", Map.of("cart", value("cart", "cart", cart)));
            }
            robot = new ProviderSnapshot("robot1", "robot", status, Instant.now(), null, services, Map.of());
        }

        private static ResourceValue value(String service, String resource, Object v) {
            return new ResourceValue("robot1", service, resource, v, Instant.now(), ResourceStatus.OK);
        }

        @Override
        public List<ProviderSnapshot> providers() {
            List<ProviderSnapshot> all = new ArrayList<>(carts);
            all.add(robot);
            return all;
        }

        @Override
        public Optional<ProviderSnapshot> provider(String providerId) {
            return "robot1".equals(providerId) ? Optional.of(robot) : Optional.empty();
        }

        @Override
        public Optional<ResourceValue> resource(String providerId, String service, String resource) {
            if ("warehouse".equals(providerId) && "map".equals(service) && "rows".equals(resource)) {
                return Optional.of(new ResourceValue("warehouse", "map", "rows", map, Instant.now(),
                        ResourceStatus.OK));
            }
            return Optional.empty();
        }

        @Override
        public Subscription subscribe(String providerId, String service, ResourceListener listener) {
            throw new UnsupportedOperationException();
        }

        @Override
        public CompletionStage<CommandOutcome> act(String providerId, String service, String action,
                Map<String, Object> parameters) {
            throw new UnsupportedOperationException();
        }
    }
}
