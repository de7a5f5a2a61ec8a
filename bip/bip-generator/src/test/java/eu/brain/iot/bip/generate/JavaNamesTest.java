package eu.brain.iot.bip.generate;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class JavaNamesTest {

    @Test
    void aSmartBehaviourClassDoesNotSayBehaviourTwice() {
        assertThat(JavaNames.behaviourClass(JavaNames.type("Robot_behavior"))).isEqualTo("RobotSmartBehaviour");
        assertThat(JavaNames.behaviourClass("DoorBehaviour")).isEqualTo("DoorSmartBehaviour");
        assertThat(JavaNames.behaviourClass("Sensor")).isEqualTo("SensorBehaviour");
        assertThat(JavaNames.behaviourClass("Behavior")).as("nothing left to keep").isEqualTo("BehaviorBehaviour");
    }
}
