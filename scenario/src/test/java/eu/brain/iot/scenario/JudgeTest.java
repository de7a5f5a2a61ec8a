package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/**
 * The judge on ground truth captured from robot-sim runs driven here by REST commands, in manual-step mode: a
 * complete run passes; a robot left carrying a cart, a long wait behind a robot, a head-on deadlock, robots away
 * from docking and refused commands each fail the check they break, saying what was wrong.
 */
class JudgeTest {
    private static final long LIMIT_MS = 10_000;

    /** robot3 carries the three carts of the paper's warehouse through the open door to storage, then docks. */
    private static void deliverEverything(Fleet f) throws Exception {
        assertThat(f.openDoor()).isEqualTo(200);
        int[][] carts = {{3, 7}, {10, 7}, {16, 7}};
        int[][] storage = {{12, 2}, {14, 2}, {16, 2}};
        for (int i = 0; i < carts.length; i++) {
            assertThat(f.goTo("robot3", carts[i][0], carts[i][1])).isEqualTo(200);
            assertThat(f.pick("robot3")).isEqualTo(200);
            assertThat(f.goTo("robot3", storage[i][0], storage[i][1])).isEqualTo(200);
            assertThat(f.place("robot3")).isEqualTo(200);
        }
        assertThat(f.goTo("robot3", 6, 1)).isEqualTo(200);
        f.step(300);
    }

    @Test
    void aCompleteRunPassesEveryCheck() throws Exception {
        try (Fleet f = Fleet.paper()) {
            deliverEverything(f);
            WorldSnapshot end = f.world();
            Verdict v = Judge.judge(end, LIMIT_MS, -1);
            assertThat(v.failed()).isEmpty();
            assertThat(v.passed()).isTrue();
            assertThat(v.checks()).extracting(Verdict.Check::detail).contains("3/3 carts in storage",
                    "3/3 robots docked and idle", "14 accepted, 0 refused");
            assertThat(end.finished()).isTrue();
        }
    }

    @Test
    void aNodeThatEndedDuringTheRunFailsTheRunAndSaysSo() throws Exception {
        try (Fleet f = Fleet.paper()) {
            f.openDoor();
            f.step(10);
            Verdict v = Judge.judge(f.world(), LIMIT_MS, Judge.RunEnd.NODE_ENDED, 12_000);
            assertThat(v.passed()).isFalse();
            assertThat(check(v, "finished before the deadline").passed()).isFalse();
            assertThat(detail(v, "deadline")).isEqualTo("the node ended during the run, at 12.0 s of warehouse time: "
                    + "the run could not finish");
        }
    }

    @Test
    void aCartStillCarriedFailsReq1AndSaysWhereItIs() throws Exception {
        try (Fleet f = Fleet.paper()) {
            f.openDoor();
            f.goTo("robot3", 3, 7);
            f.pick("robot3");
            f.goTo("robot3", 9, 3);
            f.step(60);
            Verdict v = Judge.judge(f.world(), LIMIT_MS, 30_000);
            assertThat(v.passed()).isFalse();
            assertThat(detail(v, "REQ-1")).isEqualTo("0/3 carts in storage; not delivered: cart1 carried by robot3 "
                    + "at (9,3), cart2 at (10,7), cart3 at (16,7)");
            assertThat(detail(v, "every robot back in docking")).isEqualTo("not back: robot3 at (9,3), area 0, "
                    + "carrying cart1");
            assertThat(detail(v, "deadline")).isEqualTo("the deadline ended the run at 30.0 s of warehouse time");
        }
    }

    @Test
    void aWaitBehindAnotherRobotLongerThanTheLimitFailsReq2AndNamesTheRobot() throws Exception {
        try (Fleet f = Fleet.paper()) {
            f.goTo("robot1", 9, 1); // robot2 stands at (4,1) on its way
            f.step(22);
            WorldSnapshot end = f.world();
            assertThat(end.longestWaitMs()).isEqualTo(10_500);
            Verdict v = Judge.judge(end, LIMIT_MS, 11_000);
            assertThat(check(v, "REQ-2 no wait").passed()).isFalse();
            assertThat(detail(v, "REQ-2 no wait")).isEqualTo("robot1 waited 10.5 s (still waiting)");
            assertThat(check(v, "cycle").passed()).as("waiting on an idle robot is no cycle").isTrue();
            assertThat(Judge.judge(end, 10_500, -1).failed()).extracting(Verdict.Check::name)
                    .as("at a 10.5 s limit the wait is within it; robot1 is still away")
                    .doesNotContain("REQ-2 no wait behind another robot longer than 10.5 s")
                    .contains("REQ-2 every errand's destination reached, every robot back in docking");
        }
    }

    @Test
    void robotsHeadOnInACorridorAreADeadlock() throws Exception {
        try (Fleet f = Fleet.of("map:\n#########\n#dRsssRd#\n#########\n", 20)) {
            f.goTo("robot1", 7, 1);
            f.goTo("robot2", 1, 1);
            f.step(30);
            Verdict v = Judge.judge(f.world(), LIMIT_MS, 15_000);
            assertThat(check(v, "cycle").passed()).isFalse();
            assertThat(detail(v, "cycle")).startsWith("1 deadlocks");
            assertThat(detail(v, "REQ-2 no wait")).contains("robot1 waited", "robot2 waited", "(still waiting)");
        }
    }

    @Test
    void refusedCommandsAreReportedAndPassOnlyWhenTheRunCompleted() throws Exception {
        try (Fleet f = Fleet.paper()) {
            assertThat(f.goTo("robot2", 0, 0)).as("a wall").isEqualTo(422);
            f.sim.faults().setOwn(0, new eu.brain.iot.robotsim.fault.FaultSettings(0, 0, 0, 0, true));
            assertThat(f.goTo("robot1", 9, 3)).as("offline").isEqualTo(503);
            f.sim.faults().setOwn(0, null);
            WorldSnapshot before = f.world();
            assertThat(check(Judge.judge(before, LIMIT_MS, 5_000), "command").passed()).isFalse();
            assertThat(detail(Judge.judge(before, LIMIT_MS, 5_000), "command")).isEqualTo("0 accepted, 2 refused "
                    + "(by HTTP status: 422 x1, 503 x1); the run did not complete: refusals may not have been handled");

            deliverEverything(f);
            Verdict v = Judge.judge(f.world(), LIMIT_MS, -1);
            assertThat(v.passed()).isTrue();
            assertThat(detail(v, "command")).isEqualTo("14 accepted, 2 refused (by HTTP status: 422 x1, 503 x1); the "
                    + "run completed in spite of them");
        }
    }

    @Test
    void aMissionThatFailedWhenItStartedCountsAsARefusal() throws Exception {
        try (Fleet f = Fleet.paper()) {
            assertThat(f.pick("robot1")).as("queued: checked when it starts").isEqualTo(200);
            f.step(2);
            Verdict v = Judge.judge(f.world(), LIMIT_MS, 1_000);
            assertThat(detail(v, "command")).isEqualTo("1 accepted, 0 refused, 1 missions failed when they started; "
                    + "the run did not complete: refusals may not have been handled");
            assertThat(check(v, "command").passed()).isFalse();
        }
    }

    @Test
    void nothingDoneIsSaidPlainly() throws Exception {
        try (Fleet f = Fleet.paper()) {
            f.step(10);
            Verdict v = Judge.judge(f.world(), LIMIT_MS, 5_000);
            assertThat(detail(v, "command")).isEqualTo("no command reached the fleet: nothing drove the robots");
            assertThat(check(v, "every robot back in docking").passed()).as("they never left").isTrue();
        }
    }

    private static Verdict.Check check(Verdict v, String nameContains) {
        return v.checks().stream().filter(c -> c.name().contains(nameContains)).findFirst().orElseThrow();
    }

    private static String detail(Verdict v, String nameContains) {
        return check(v, nameContains).detail();
    }
}
