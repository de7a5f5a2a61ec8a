package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Nodes whose host has not reported are sent model inputs one at a time; this node and nodes with a host always. */
class HostInstallsTest {

    @Test
    void nodesWithoutAHostAreSentInputsOneAtATime() {
        HostInstalls installs = new HostInstalls("node1");
        assertThat(installs.mayFire("node1", 0)).as("this node's host: in the same bundle").isTrue();
        assertThat(installs.mayFire("node2", 0)).as("the first node without a host").isTrue();
        assertThat(installs.mayFire("node3", 1)).as("while node2's is installed").isFalse();
        assertThat(installs.mayFire("node2", 2)).isTrue();
        installs.reported("node2"); // node2's host is there
        assertThat(installs.mayFire("node3", 3)).isTrue();
        assertThat(installs.mayFire("node4", 4)).isFalse();
        assertThat(installs.mayFire("node4", 3 + HostInstalls.INSTALL_NANOS))
                .as("node3's install took too long: the next node's turn").isTrue();
        assertThat(installs.mayFire("node2", 5)).as("a node with a host, always").isTrue();
    }
}
