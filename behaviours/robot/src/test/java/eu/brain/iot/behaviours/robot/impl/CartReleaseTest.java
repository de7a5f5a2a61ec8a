package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** How robots are released towards the door: in waves, or continuously under the traffic planner. */
class CartReleaseTest {

    @Test
    void aWaveClosesWhenFullAndStaysClosedWhileOneOfItsRobotsCarriesACart() {
        CartRelease waves = CartRelease.waves(4);
        assertThat(waves.open(0, false)).isTrue();
        assertThat(waves.open(3, false)).isTrue();
        assertThat(waves.open(4, false)).as("the wave is full").isFalse();
        assertThat(waves.open(0, true)).as("a robot of the wave carries its cart back").isFalse();
    }

    @Test
    void releasedContinuouslyARobotSetsOffWhileOthersCarryTheirCarts() {
        CartRelease continuous = CartRelease.continuous();
        assertThat(continuous.open(0, true)).isTrue();
        assertThat(continuous.open(1_000, true)).isTrue();
    }

    @Test
    void aWaveHasAtLeastOneRobot() {
        assertThat(CartRelease.waves(0).open(0, false)).isTrue();
        assertThat(CartRelease.waves(0).open(1, false)).isFalse();
    }
}
