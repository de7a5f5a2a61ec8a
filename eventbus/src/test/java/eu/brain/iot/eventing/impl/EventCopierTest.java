package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.BrainIoTEvent;

class EventCopierTest {

    public static class Cell {
        public int x;
        public int y;
    }

    public enum Heading { NORTH, SOUTH }

    public static class Mission extends BrainIoTEvent {
        public String robotId;
        public Heading heading;
        public Cell goal;
        public List<Cell> path;
        public int[] weights;
        public Map<String, Object> extra;
    }

    private static Mission mission() {
        Mission m = new Mission();
        m.robotId = "robot1";
        m.heading = Heading.NORTH;
        m.timestamp = Instant.EPOCH;
        m.securityToken = new byte[] { 1, 2 };
        m.goal = new Cell();
        m.goal.x = 3;
        m.path = new ArrayList<>(List.of(new Cell()));
        m.weights = new int[] { 1, 2, 3 };
        m.extra = new java.util.HashMap<>(Map.of("k", new ArrayList<>(List.of(1))));
        return m;
    }

    @Test
    void copiesAreDeepForMutableValuesAndShareImmutableOnes() {
        Mission original = mission();
        Mission copy = EventCopier.copyEvent(original);

        assertThat(copy).isNotSameAs(original).isExactlyInstanceOf(Mission.class);
        assertThat(copy.robotId).isSameAs(original.robotId);
        assertThat(copy.timestamp).isSameAs(original.timestamp);
        assertThat(copy.heading).isSameAs(Heading.NORTH);
        assertThat(copy.goal).isNotSameAs(original.goal);
        assertThat(copy.goal.x).isEqualTo(3);
        assertThat(copy.path).isNotSameAs(original.path);
        assertThat(copy.path.get(0)).isNotSameAs(original.path.get(0));
        assertThat(copy.weights).isNotSameAs(original.weights).containsExactly(1, 2, 3);
        assertThat(copy.securityToken).isNotSameAs(original.securityToken).containsExactly(1, 2);
        assertThat(copy.extra.get("k")).isNotSameAs(original.extra.get("k")).isEqualTo(List.of(1));

        original.goal.x = 99;
        original.weights[0] = 99;
        assertThat(copy.goal.x).isEqualTo(3);
        assertThat(copy.weights[0]).isEqualTo(1);
    }

    @Test
    void eventsBecomeMapsOfTheirFieldsAndBack() {
        Map<String, Object> map = EventMaps.toMap(mission());

        assertThat(map).containsEntry("robotId", "robot1").containsEntry("heading", Heading.NORTH)
                .containsEntry("weights", List.of(1, 2, 3)).containsEntry("timestamp", Instant.EPOCH);
        assertThat(map.get("goal")).isEqualTo(Map.of("x", 3, "y", 0));

        Mission back = EventMaps.fromMap(map, Mission.class);
        assertThat(back.robotId).isEqualTo("robot1");
        assertThat(back.goal.x).isEqualTo(3);
        assertThat(back.weights).containsExactly(1, 2, 3);
        assertThat(back.path).hasSize(1);
        assertThat(back.path.get(0)).isInstanceOf(Cell.class);
    }

    @Test
    void routesIncludeEverySupertypeName() {
        assertThat(RouteTable.typeNames(Mission.class)).contains(Mission.class.getName(),
                BrainIoTEvent.class.getName(), Cloneable.class.getName());
    }
}
