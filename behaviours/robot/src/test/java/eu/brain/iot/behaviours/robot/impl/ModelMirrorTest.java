package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;

/**
 * The binding's view of the robots' model instances: an input awaits its report, which brings the instance's places,
 * data and steps; a report of another coordinator's input, or an old one, answers nothing; an input no host answers is
 * given up; a robot hosted on another node now is not waited for.
 */
class ModelMirrorTest {

    private static final long LOST = 1_000;

    private final ModelMirror mirror = new ModelMirror("me", LOST, -ModelMirror.FIRST_REPORTS_NANOS);

    private static RobotModelReport report(String node, String coordinator, long seq, List<String> places,
            String data, String... steps) {
        RobotModelReport r = new RobotModelReport();
        r.node = node;
        r.robot = "robot4";
        r.coordinator = coordinator;
        r.seq = seq;
        r.places.addAll(places);
        r.data = data;
        r.steps.addAll(List.of(steps));
        return r;
    }

    @Test
    void anInputAwaitsTheReportThatAnswersIt() {
        assertThat(mirror.of("robot4")).isEmpty();
        RobotModelInput in = mirror.input("robot4", "node2", ModelPort.UNLOAD_LOCATION, 2, 0, 0);
        assertThat(in.coordinator).isEqualTo("me");
        assertThat(in.node).isEqualTo("node2");
        assertThat(in.robotId).isEqualTo("robot4");
        assertThat(in.port).isEqualTo("UNLOAD_LOCATION");
        assertThat(mirror.awaiting("robot4", 10)).isTrue();

        assertThat(mirror.reported(report("node2", "me", in.seq - 1, List.of("START"), ""))).isEmpty();
        assertThat(mirror.awaiting("robot4", 20)).as("an earlier input's report").isTrue();
        mirror.reported(report("node2", "someone-else", in.seq, List.of("START"), ""));
        assertThat(mirror.awaiting("robot4", 30)).as("another coordinator's input").isTrue();

        List<ModelStep> steps = mirror.reported(report("node2", "me", in.seq, List.of("UNLOAD"),
                "cart=3 carrying=false position=2.0", "MOVE_ON", "nonsense", "STEP_ASIDE 4 2"));
        assertThat(steps).as("the steps that read, in order").containsExactly(ModelStep.MOVE_ON,
                ModelStep.aside(new Cell(4, 2)));
        assertThat(mirror.awaiting("robot4", 40)).isFalse();
        assertThat(mirror.of("robot4")).hasValueSatisfying(i -> {
            assertThat(i.node()).isEqualTo("node2");
            assertThat(i.places()).containsExactly("UNLOAD");
            assertThat(i.data()).isEqualTo(Map.of("cart", 3L, "carrying", false, "position", 2.0));
        });
    }

    @Test
    void aRobotNotReportedIsLeftAloneForItsHostsFirstReportOnly() {
        ModelMirror young = new ModelMirror("me", LOST, 0);
        assertThat(young.reportDue("robot4", 0)).isTrue();
        young.reported(report("node2", null, -1, List.of(), ""));
        assertThat(young.reportDue("robot4", 1)).as("reported").isFalse();
        assertThat(young.reportDue("robot5", ModelMirror.FIRST_REPORTS_NANOS - 1)).isTrue();
        assertThat(young.reportDue("robot5", ModelMirror.FIRST_REPORTS_NANOS)).as("its node may have no host yet")
                .isFalse();
    }

    @Test
    void anInputNoHostAnswersIsGivenUp() {
        mirror.input("robot4", "node2", ModelPort.UNLOAD_TO_UNLOAD, 2, 0, 0);
        assertThat(mirror.awaiting("robot4", LOST - 1)).isTrue();
        assertThat(mirror.awaiting("robot4", LOST)).isFalse();
        assertThat(mirror.awaiting("robot4", LOST + 1)).isFalse();
    }

    @Test
    void aRobotHostedOnAnotherNodeNowIsNotWaitedFor() {
        mirror.reported(report("node2", null, -1, List.of("UNLOAD"), ""));
        mirror.input("robot4", "node2", ModelPort.UNLOAD_TO_UNLOAD, 2, 0, 0);
        mirror.reported(report("node3", null, -1, List.of(), ""));
        assertThat(mirror.awaiting("robot4", 1)).as("its new host never got the input").isFalse();
        assertThat(mirror.of("robot4")).hasValueSatisfying(i -> assertThat(i.places()).isEmpty());

        mirror.input("robot4", "node2", ModelPort.UNLOAD_LOCATION, 2, 0, 2);
        mirror.handedOver("robot4"); // it appeared on the node that polls it now
        assertThat(mirror.awaiting("robot4", 3)).isFalse();
    }
}
