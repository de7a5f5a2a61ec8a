package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.events.RobotBehaviorFromUnloadObstacle;
import eu.brain.iot.behaviours.events.RobotBehaviorStorageToDocking;

/** Every port's event names the robot's group and component and carries the port's data. */
class ModelPortTest {

    @Test
    void everyPortsEventCarriesTheRobotsInstanceAndTheData() {
        for (ModelPort port : ModelPort.values()) {
            assertThat(port.event("robot4", 2, 5)).as(port.name()).hasFieldOrPropertyWithValue("group", "g2")
                    .hasFieldOrPropertyWithValue("component", "Robot1").hasFieldOrPropertyWithValue("position", 2.0)
                    .hasFieldOrPropertyWithValue("detect", 5);
        }
        assertThat(ModelPort.FROM_UNLOAD_OBSTACLE.event("robot9", 3, 6)).isInstanceOf(
                RobotBehaviorFromUnloadObstacle.class).hasFieldOrPropertyWithValue("group", "g3")
                .hasFieldOrPropertyWithValue("component", "Robot3");
        assertThat(ModelPort.STORAGE_TO_DOCKING.event("robot1", 1, 0)).isInstanceOf(
                RobotBehaviorStorageToDocking.class);
    }
}
