package eu.brain.iot.robotsim.world;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

class SensorTest {

    @Test
    void robotInFrontStopsTheRobotWhichGoesOnByItselfWhenTheCellClears() {
        Sim sim = Sim.of("map:\n########\n#RddddR#\n######d#\n########\n");
        Robot r1 = sim.robot("robot1");
        Robot r2 = sim.robot("robot2");
        Mission m = sim.goTo("robot1", 6, 1);
        sim.step(4);
        assertThat(r1.x()).isEqualTo(5);
        assertThat(r1.detect()).isZero();
        sim.step(1);
        assertThat(r1.x()).isEqualTo(5);
        assertThat(r1.detect()).isEqualTo(1);
        assertThat(r1.running()).isFalse();
        assertThat(r1.heading()).isEqualTo(Heading.E);
        assertThat(r1.nearMisses()).isEqualTo(1);
        sim.step(3);
        assertThat(r1.nearMisses()).as("one stop, counted once").isEqualTo(1);
        assertThat(sim.world.nearMisses()).isEqualTo(1);
        assertThat(r2.nearMisses()).isZero();

        sim.goTo("robot2", 6, 2);
        sim.step(1);
        assertThat(r2.y()).isEqualTo(2);
        assertThat(r1.x()).as("sees the robot that is just leaving").isEqualTo(5);
        sim.step(1);
        assertThat(r1.x()).isEqualTo(6);
        assertThat(r1.detect()).isZero();
        assertThat(m.state()).isEqualTo(MissionState.FINISHED);
        assertThat(r1.deadlocks()).isZero();
    }

    @Test
    void waitsBehindAnotherRobotAreCountedInStepsWithTheLongestAndTheEndedOnes() {
        Sim sim = Sim.of("map:\n########\n#RddddR#\n######d#\n########\n");
        Robot r1 = sim.robot("robot1");
        Robot r2 = sim.robot("robot2");
        sim.goTo("robot1", 6, 1);
        sim.step(4);
        assertThat(r1.waitSteps()).as("moving is no wait").isZero();
        sim.step(3);
        assertThat(r1.detect()).isEqualTo(1);
        assertThat(r1.waitSteps()).isEqualTo(3);
        assertThat(r1.waitingSteps()).isEqualTo(3);
        assertThat(r1.longestWaitSteps()).isEqualTo(3);
        assertThat(r1.waitsEnded()).isZero();
        assertThat(sim.world.endedWaits()).isEmpty();

        sim.goTo("robot2", 6, 2);
        sim.step(1);
        assertThat(r1.waitingSteps()).as("still sees the robot that is just leaving").isEqualTo(4);
        sim.step(1);
        assertThat(r1.x()).isEqualTo(6);
        assertThat(r1.waitingSteps()).isZero();
        assertThat(r1.waitSteps()).isEqualTo(4);
        assertThat(r1.longestWaitSteps()).isEqualTo(4);
        assertThat(r1.waitsEnded()).isEqualTo(1);
        assertThat(sim.world.endedWaits()).containsExactly(java.util.Map.entry(4L, 1L));
        assertThat(r2.waitSteps()).isZero();

        sim.goTo("robot1", 5, 1);
        sim.step(1);
        sim.goTo("robot2", 4, 1);
        sim.step(2);
        assertThat(r2.waitingSteps()).as("robot1 stands at (5,1)").isEqualTo(1);
        sim.goTo("robot1", 1, 1);
        sim.step(1);
        assertThat(r2.waitingSteps()).as("robot1 left (5,1) in this step").isEqualTo(2);
        sim.step(1);
        assertThat(r2.x()).isEqualTo(5);
        assertThat(r2.waitsEnded()).isEqualTo(1);
        assertThat(r2.longestWaitSteps()).isEqualTo(2);
        assertThat(r1.longestWaitSteps()).as("robot1's own longest wait stays").isEqualTo(4);
        assertThat(sim.world.endedWaits()).containsExactly(java.util.Map.entry(2L, 1L), java.util.Map.entry(4L, 1L));
    }

    @Test
    void aDoorOrAnIdleRobotIsNoWaitAndGoingOfflineEndsOne() {
        Sim sim = Sim.of("map:\n######\n#RddR#\n######\n");
        Robot r1 = sim.robot("robot1");
        sim.goTo("robot1", 4, 1);
        sim.step(5);
        assertThat(r1.waitingSteps()).isEqualTo(3);
        sim.offline[0] = true;
        sim.step(1);
        assertThat(r1.waitingSteps()).isZero();
        assertThat(r1.waitsEnded()).isEqualTo(1);
        assertThat(sim.robot("robot2").waitSteps()).as("an idle robot waits for nothing").isZero();
    }

    @Test
    void twoRobotsWantingTheSameCellNeverShareItAndTheSeedPicksTheWinner() {
        Set<String> winners = new HashSet<>();
        for (long seed = 1; seed <= 20; seed++) {
            Sim sim = Sim.of("map:\n#####\n#RdR#\n#####\n", SimRules.DEFAULT.withSeed(seed));
            sim.goTo("robot1", 2, 1);
            sim.goTo("robot2", 2, 1);
            sim.step(1);
            int winner = sim.world.robotAt(2, 1);
            assertThat(winner).isNotNegative();
            Robot loser = sim.world.robot(1 - winner);
            assertThat(loser.x()).isNotEqualTo(2);
            assertThat(loser.detect()).isEqualTo(1);
            assertThat(loser.nearMisses()).isEqualTo(1);
            winners.add(sim.world.robot(winner).id());
        }
        assertThat(winners).containsExactlyInAnyOrder("robot1", "robot2");
    }

    @Test
    void headOnRobotsDeadlockAndItIsCountedOncePerCycle() throws Exception {
        SimRules rules = new SimRules(1, 2, 2, 3, -1);
        Sim sim = Sim.of("map:\n#######\n#RdddR#\n#######\n", rules);
        Robot r1 = sim.robot("robot1");
        Robot r2 = sim.robot("robot2");
        sim.goTo("robot1", 5, 1);
        sim.goTo("robot2", 1, 1);
        sim.step(3);
        assertThat(Math.abs(r1.x() - r2.x())).isEqualTo(1);
        assertThat(r1.detect()).isEqualTo(1);
        assertThat(r2.detect()).isEqualTo(1);
        sim.step(10);
        assertThat(sim.world.deadlocks()).isEqualTo(1);
        assertThat(r1.deadlocks()).isEqualTo(1);
        assertThat(r2.deadlocks()).isEqualTo(1);
        assertThat(r1.x()).isNotEqualTo(r2.x());

        sim.commands.cancel(r1.index(), MissionType.GOTO, null);
        sim.step(5);
        assertThat(sim.world.deadlocks()).as("waiting on an idle robot is no cycle").isEqualTo(1);
        assertThat(r2.detect()).isEqualTo(1);
        sim.goTo("robot1", 5, 1);
        sim.step(10);
        assertThat(sim.world.deadlocks()).as("a new cycle is a new deadlock").isEqualTo(2);
    }

    @Test
    void deadlockNeedsTheConfiguredNumberOfSteps() {
        SimRules rules = new SimRules(1, 2, 2, 5, -1);
        Sim sim = Sim.of("map:\n####\n#RR#\n####\n", rules);
        sim.goTo("robot1", 2, 1);
        sim.goTo("robot2", 1, 1);
        sim.step(4);
        assertThat(sim.world.deadlocks()).isZero();
        sim.step(1);
        assertThat(sim.world.deadlocks()).isEqualTo(1);
    }

    @Test
    void offlineRobotStandsStillAsAnObstacle() {
        Sim sim = Sim.of("map:\n######\n#RddR#\n######\n");
        sim.offline[0] = true;
        sim.goTo("robot1", 3, 1);
        sim.goTo("robot2", 1, 1);
        sim.step(5);
        assertThat(sim.robot("robot1").x()).isEqualTo(1);
        assertThat(sim.robot("robot2").x()).isEqualTo(2);
        assertThat(sim.robot("robot2").detect()).isEqualTo(1);
        sim.offline[0] = false;
        sim.step(1);
        assertThat(sim.robot("robot1").running()).isFalse();
        assertThat(sim.robot("robot1").detect()).isEqualTo(1);
    }
}
