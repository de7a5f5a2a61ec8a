package eu.brain.iot.robotsim.world;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class MovementTest {

    @Test
    void robotMovesOneCellPerStepInFourDirectionsAlongAShortestPath() {
        Sim sim = new Sim(WarehouseMap.paper(), SimRules.DEFAULT);
        Robot r = sim.robot("robot3");
        assertThat(r.x()).isEqualTo(6);
        assertThat(r.y()).isEqualTo(1);
        Mission m = sim.goTo("robot3", 11, 4);
        assertThat(m.state()).isEqualTo(MissionState.QUEUED);
        int distance = Math.abs(11 - 6) + Math.abs(4 - 1);
        for (int i = 0; i < distance; i++) {
            int x = r.x();
            int y = r.y();
            sim.step(1);
            assertThat(Math.abs(r.x() - x) + Math.abs(r.y() - y)).as("step %d", i + 1).isEqualTo(1);
            Heading h = r.heading();
            assertThat(r.x() - x).isEqualTo(h.dx());
            assertThat(r.y() - y).isEqualTo(h.dy());
        }
        assertThat(r.x()).isEqualTo(11);
        assertThat(r.y()).isEqualTo(4);
        assertThat(m.state()).isEqualTo(MissionState.FINISHED);
        assertThat(r.running()).isFalse();
        assertThat(r.detect()).isZero();
        assertThat(sim.world.robotAt(11, 4)).isEqualTo(r.index());
        assertThat(sim.world.robotAt(6, 1)).isEqualTo(-1);
    }

    @Test
    void runningWhileTravellingStoppedWhenIdle() {
        Sim sim = new Sim(WarehouseMap.paper(), SimRules.DEFAULT);
        Robot r = sim.robot("robot3");
        assertThat(r.running()).isFalse();
        sim.goTo("robot3", 6, 4);
        sim.step(1);
        assertThat(r.running()).isTrue();
        assertThat(r.current().state()).isEqualTo(MissionState.RUNNING);
        sim.step(2);
        assertThat(r.running()).isFalse();
        assertThat(r.shownMission().state()).isEqualTo(MissionState.FINISHED);
    }

    @Test
    void missionsRunInTheOrderTheyWereQueued() {
        Sim sim = new Sim(WarehouseMap.paper(), SimRules.DEFAULT);
        Robot r = sim.robot("robot3");
        Mission first = sim.goTo("robot3", 6, 3);
        Mission second = sim.goTo("robot3", 8, 3);
        sim.step(2);
        assertThat(first.state()).isEqualTo(MissionState.FINISHED);
        assertThat(second.state()).isEqualTo(MissionState.QUEUED);
        sim.step(2);
        assertThat(second.state()).isEqualTo(MissionState.FINISHED);
        assertThat(r.x()).isEqualTo(8);
        assertThat(r.y()).isEqualTo(3);
    }

    @Test
    void goalWhereTheRobotStandsFinishesAtOnceAndUnreachableGoalFails() throws Exception {
        Sim sim = Sim.of("map:\n#####\n#Rd#d\n#####\n");
        Mission here = sim.goTo("robot1", 1, 1);
        Mission enclosed = sim.goTo("robot1", 4, 1);
        sim.step(1);
        assertThat(here.state()).isEqualTo(MissionState.FINISHED);
        assertThat(enclosed.state()).isEqualTo(MissionState.FAILED);
        assertThat(enclosed.reason()).isEqualTo("no path from (1,1) to (4,1)");
    }

    @Test
    void goalOutsideTheMapOrInAWallIsRefusedWithoutChangingAnything() {
        Sim sim = new Sim(WarehouseMap.paper(), SimRules.DEFAULT);
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> sim.commands.goTo(0, 20, 3))
                .isInstanceOf(CommandRejectedException.class)
                .hasMessage("goal (20,3) is outside the 20x10 map (x 0..19, y 0..9)")
                .extracting(e -> ((CommandRejectedException) e).field()).isEqualTo("x");
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> sim.commands.goTo(0, 3, -1))
                .extracting(e -> ((CommandRejectedException) e).field()).isEqualTo("y");
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> sim.commands.goTo(0, 0, 0))
                .hasMessage("goal (0,0) is a wall");
        assertThat(sim.robot("robot1").shownMission()).isNull();
        assertThat(sim.world.nextMissionId).isEqualTo(1);
    }

    @Test
    void cancelStopsTheRobotWhereItIs() throws Exception {
        Sim sim = new Sim(WarehouseMap.paper(), SimRules.DEFAULT);
        Robot r = sim.robot("robot3");
        Mission m = sim.goTo("robot3", 6, 4);
        sim.step(1);
        assertThat(sim.commands.cancel(r.index(), MissionType.GOTO, null)).containsExactly(m);
        sim.step(3);
        assertThat(m.state()).isEqualTo(MissionState.FAILED);
        assertThat(m.reason()).isEqualTo("cancelled");
        assertThat(r.y()).isEqualTo(2);
        assertThat(r.running()).isFalse();
    }

    @Test
    void cancelByIdReachesQueuedMissionsAndUnknownIdsAreRefused() throws Exception {
        Sim sim = new Sim(WarehouseMap.paper(), SimRules.DEFAULT);
        int r = sim.index("robot3");
        Mission first = sim.goTo("robot3", 6, 3);
        Mission second = sim.goTo("robot3", 8, 3);
        assertThat(sim.commands.cancel(r, MissionType.GOTO, second.id())).containsExactly(second);
        assertThat(sim.commands.cancel(r, MissionType.PICK, null)).isEmpty();
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> sim.commands.cancel(r, MissionType.GOTO, 99L))
                .isInstanceOf(CommandRejectedException.class)
                .hasMessage("mission 99 is not queued or running on robot3's GoToComponent");
        sim.step(4);
        assertThat(first.state()).isEqualTo(MissionState.FINISHED);
        assertThat(sim.robot("robot3").x()).isEqualTo(6);
    }
}
