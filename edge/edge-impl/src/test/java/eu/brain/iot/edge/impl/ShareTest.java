package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.stream.IntStream;

import org.junit.jupiter.api.Test;

/** A node's share of the fleet: all, K/N by robot number (doors on one node), or a list; bad values named. */
class ShareTest {

    private static List<String> robotsOf(Share s, int robots) {
        return IntStream.rangeClosed(1, robots).mapToObj(i -> "robot" + i).filter(id -> s.holds(id, DeviceKind.ROBOT))
                .toList();
    }

    @Test
    void allHoldsEveryDeviceAndIsTheDefault() {
        assertThat(Share.parse("", 1)).isEqualTo(Share.EVERY_DEVICE);
        assertThat(Share.parse(" ALL ", 1)).isEqualTo(Share.EVERY_DEVICE);
        assertThat(robotsOf(Share.EVERY_DEVICE, 3)).containsExactly("robot1", "robot2", "robot3");
        assertThat(Share.EVERY_DEVICE.holds("door1", DeviceKind.DOOR)).isTrue();
    }

    @Test
    void kOfNHoldsTheRobotsWhoseNumberModuloNIsKMinusOne() {
        assertThat(robotsOf(Share.parse("1/3", 1), 7)).containsExactly("robot3", "robot6");
        assertThat(robotsOf(Share.parse("2/3", 1), 7)).containsExactly("robot1", "robot4", "robot7");
        assertThat(robotsOf(Share.parse("3/3", 1), 7)).containsExactly("robot2", "robot5");
        assertThat(Share.parse("2/2", 1).holds("robot010", DeviceKind.ROBOT)).as("leading zeros").isFalse();
        assertThat(Share.parse("1/2", 1).holds("robot010", DeviceKind.ROBOT)).isTrue();
        assertThat(Share.parse("1/1", 1).holds("robot7", DeviceKind.ROBOT)).isTrue();
    }

    @Test
    void everyRobotIsHeldByExactlyOneOfTheNNodesWhateverItsName() {
        for (String id : List.of("robot1", "robot29", "agv-east", "forklift.7", "robot")) {
            assertThat(IntStream.rangeClosed(1, 3).filter(k -> Share.parse(k + "/3", 1).holds(id, DeviceKind.ROBOT))
                    .count()).as(id).isEqualTo(1);
        }
    }

    @Test
    void theDoorsAreOnTheDoorsOwnerNode() {
        assertThat(Share.parse("1/3", 1).holds("door1", DeviceKind.DOOR)).isTrue();
        assertThat(Share.parse("2/3", 1).holds("door1", DeviceKind.DOOR)).isFalse();
        assertThat(Share.parse("2/3", 2).holds("door2", DeviceKind.DOOR)).isTrue();
        assertThat(Share.parse("1/3", 2).holds("door2", DeviceKind.DOOR)).isFalse();
    }

    @Test
    void aListHoldsTheDevicesListed() {
        Share s = Share.parse("robot1, robot4,door1", 1);
        assertThat(robotsOf(s, 5)).containsExactly("robot1", "robot4");
        assertThat(s.holds("door1", DeviceKind.DOOR)).isTrue();
        assertThat(s.holds("door2", DeviceKind.DOOR)).isFalse();
        assertThat(s).hasToString("robot1,robot4,door1");
    }

    @Test
    void badSharesAreRefusedSayingWhatToWrite() {
        assertThatThrownBy(() -> Share.parse("0/3", 1)).hasMessageContaining("share '0/3' must be K/N with 1 <= K <= N");
        assertThatThrownBy(() -> Share.parse("4/3", 1)).hasMessageContaining("1 <= K <= N");
        assertThatThrownBy(() -> Share.parse("1/3", 4)).hasMessage("doors.owner must be a node number from 1 to 3 "
                + "(share 1/3), found 4");
        assertThatThrownBy(() -> Share.parse("robot1,,robot2", 1)).hasMessageContaining("share holds ''")
                .hasMessageContaining("'all', K/N");
        assertThatThrownBy(() -> Share.parse("1/x", 1)).hasMessageContaining("share holds '1/x'");
    }

    @Test
    void theNodeNameIsCheckedAndDefaultsToNode() {
        assertThat(EdgeNode.name(null)).isEqualTo("node");
        assertThat(EdgeNode.name(" ")).isEqualTo("node");
        assertThat(EdgeNode.name("node2")).isEqualTo("node2");
        assertThatThrownBy(() -> EdgeNode.name("node 2")).hasMessageContaining("fabric.node.name must be 1 to 64")
                .hasMessageContaining("'node 2'");
    }
}
