package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;

/** The model's steps as a report carries them: every kind read back as written; text that is no step refused. */
class ModelStepTest {

    @Test
    void everyStepReadsBackAsWritten() {
        for (ModelStep step : List.of(ModelStep.MOVE_ON, ModelStep.LIFT, ModelStep.PLACE,
                ModelStep.aside(new Cell(12, 7)))) {
            assertThat(ModelStep.parse(step.text())).contains(step);
        }
        assertThat(ModelStep.aside(new Cell(4, 2)).text()).isEqualTo("STEP_ASIDE 4 2");
    }

    @Test
    void textThatIsNoStepIsRefused() {
        for (String text : new String[] { null, "", "JUMP", "STEP_ASIDE", "STEP_ASIDE 4", "STEP_ASIDE a b",
            "LIFT 3", "lift" }) {
            assertThat(ModelStep.parse(text)).as(String.valueOf(text)).isEmpty();
        }
    }
}
