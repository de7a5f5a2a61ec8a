package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** How robots are released towards the doors: in waves, or continuously under the traffic planner. */
class CartReleaseTest {

    @Test
    void aWaveClosesWhenFullAndStaysClosedWhileOneOfItsRobotsCarriesACart() {
        CartRelease waves = CartRelease.waves(4);
        assertThat(waves.open(0, false, 1)).isTrue();
        assertThat(waves.open(3, false, 1)).isTrue();
        assertThat(waves.open(4, false, 1)).as("the wave is full").isFalse();
        assertThat(waves.open(0, true, 1)).as("a robot of the wave carries its cart back").isFalse();
        assertThat(waves.open(4, false, 3)).as("a wave does not grow with the doors").isFalse();
        assertThat(waves.farthestFirst(1)).isFalse();
    }

    @Test
    void releasedContinuouslyARobotSetsOffWhileOthersCarryTheirCartsUpToItsShareOfTheDoors() {
        CartRelease continuous = CartRelease.continuous(10);
        assertThat(continuous.open(0, true, 1)).isTrue();
        assertThat(continuous.open(9, true, 1)).isTrue();
        assertThat(continuous.open(10, true, 1)).as("ten robots per door").isFalse();
        assertThat(continuous.open(29, true, 3)).isTrue();
        assertThat(continuous.open(30, false, 3)).isFalse();
        assertThat(continuous.open(9, false, 0)).as("a map without a door counts as one").isTrue();
        assertThat(continuous.farthestFirst(1)).as("through one door").isTrue();
        assertThat(continuous.farthestFirst(3)).as("the farthest is through another door").isFalse();
    }

    @Test
    void aReleaseLetsAtLeastOneRobotGo() {
        assertThat(CartRelease.waves(0).open(0, false, 1)).isTrue();
        assertThat(CartRelease.waves(0).open(1, false, 1)).isFalse();
        assertThat(CartRelease.continuous(0).open(0, true, 1)).isTrue();
    }
}
