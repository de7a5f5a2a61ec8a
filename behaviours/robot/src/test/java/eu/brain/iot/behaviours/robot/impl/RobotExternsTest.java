package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.reflect.Proxy;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A move the externs cannot make for want of a fleet: a warning once per robot on a node, none for the model alone.
 * A lift counts against the robot's budget unless the robot carries its cart already.
 */
class RobotExternsTest {

    private final List<LogRecord> warnings = new CopyOnWriteArrayList<>();
    private final Logger jul = Logger.getLogger(RobotExterns.class.getName());
    private final Handler handler = new Handler() {
        @Override
        public void publish(LogRecord r) {
            if (r.getLevel().intValue() >= Level.WARNING.intValue()) {
                warnings.add(r);
            }
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };

    @BeforeEach
    void listen() {
        jul.addHandler(handler);
    }

    @AfterEach
    void stopListening() {
        jul.removeHandler(handler);
    }

    /** Robot k of group g1 sent on twice (to the unload area, then to storage). */
    private static void moveTwice(RobotExterns externs, int k) {
        externs.bipInstance("g1", "Robot" + k);
        externs.moveTo(k, 2);
        externs.moveTo(k, 3);
    }

    @Test
    void onANodeWithoutAFleetEachRobotIsWarnedAboutOnceUntilTheFleetIsBack() {
        RobotExterns externs = new RobotExterns();
        for (int i = 0; i < 100; i++) {
            moveTwice(externs, 1);
            moveTwice(externs, 2);
        }
        assertThat(warnings).hasSize(2).allSatisfy(r -> assertThat(r.getMessage()).contains("no fleet service"));
    }

    @Test
    void theModelAloneHasNoFleetByDesignAndWarnsAboutNone() {
        RobotExterns externs = RobotExterns.withoutFleet();
        for (int i = 0; i < 100; i++) {
            moveTwice(externs, 1);
        }
        assertThat(warnings).isEmpty();
    }

    @Test
    void aLiftCountsAgainstTheBudgetUnlessTheRobotCarriesItsCartAlready() throws Exception {
        TrafficControlTest.Model model = new TrafficControlTest.Model();
        model.robot(1, 1, "stopped", 0, null, null);
        FleetLeadership leadership = new FleetLeadership(new FleetLeadershipTest.Recorded(),
                new FleetLeadershipTest.Ownership("node1", Set.of("robot1"), Set.of("robot1")), null);
        RobotFleet fleet = new RobotFleet(model, new FleetLeadershipTest.Recorded(), leadership, defaults(), null);
        try {
            RobotExterns externs = new RobotExterns();
            externs.fleet = fleet;
            externs.bipInstance("g1", "Robot1");
            assertThat(externs.liftCart(1, 3)).as("a cart lifted from the floor").isEqualTo(2);

            model.carrying("cart1"); // taken over carrying it, or carrying it back to storage: lifted again
            model.robot(1, 1, "stopped", 0, null, null);
            assertThat(externs.liftCart(1, 2)).as("the cart it carries, counted when first lifted").isEqualTo(2);
        } finally {
            fleet.deactivate();
            leadership.deactivate();
        }
    }

    /** The robot behaviour's configuration with every default. */
    private static RobotConfig defaults() {
        return (RobotConfig) Proxy.newProxyInstance(RobotConfig.class.getClassLoader(),
                new Class<?>[] { RobotConfig.class }, (proxy, method, args) -> method.getDefaultValue());
    }
}
