package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** Events as maps of their fields and back, and from one class of an event to another with the same fields. */
class EventMapsTest {

    public static class Point {
        public int x;
        public int y;
    }

    public static class Route extends BrainIoTEvent {
        public String robotId;
        public Point start;
        public Point[] stops;
        public List<Point> detours;
        public Map<String, Integer> counts;
        public int[] codes;
    }

    /** Another bundle's copy of {@link Route}: same field names, other classes. */
    public static class OtherRoute extends BrainIoTEvent {
        public String robotId;
        public OtherPoint start;
        public List<OtherPoint> stops;
        public long[] codes;
    }

    public static class OtherPoint {
        public long x;
        public long y;
    }

    static Point point(int x, int y) {
        Point p = new Point();
        p.x = x;
        p.y = y;
        return p;
    }

    static Route route() {
        Route r = new Route();
        r.robotId = "robot1";
        r.timestamp = Instant.parse("2026-11-23T00:00:00Z");
        r.start = point(1, 2);
        r.stops = new Point[] { point(3, 4), point(5, 6) };
        r.detours = new ArrayList<>(List.of(point(7, 8)));
        r.counts = new LinkedHashMap<>(Map.of("moves", 3));
        r.codes = new int[] { 9, 10 };
        return r;
    }

    @Test
    void anEventBecomesAMapOfItsFieldsWithNestedObjectsAsMapsAndArraysAsLists() {
        Map<String, Object> map = EventMaps.toMap(route());
        assertThat(map).containsEntry("robotId", "robot1").containsEntry("timestamp",
                Instant.parse("2026-11-23T00:00:00Z")).containsEntry("sourceNode", null);
        assertThat(map.get("start")).isEqualTo(Map.of("x", 1, "y", 2));
        assertThat(map.get("stops")).isEqualTo(List.of(Map.of("x", 3, "y", 4), Map.of("x", 5, "y", 6)));
        assertThat(map.get("detours")).isEqualTo(List.of(Map.of("x", 7, "y", 8)));
        assertThat(map.get("counts")).isEqualTo(Map.of("moves", 3));
        assertThat(map.get("codes")).isEqualTo(List.of(9, 10));
    }

    @Test
    void aMapBecomesAnEventWithEveryFieldConvertedToItsDeclaredType() {
        Map<String, Object> fields = new LinkedHashMap<>();
        fields.put("robotId", "robot2");
        fields.put("start", Map.of("x", 1L, "y", "2"));
        fields.put("stops", List.of(Map.of("x", 3, "y", 4)));
        fields.put("codes", List.of(5L, 6L));
        Route r = EventMaps.fromMap(fields, Route.class);
        assertThat(r.robotId).isEqualTo("robot2");
        assertThat(r.start.x).isEqualTo(1);
        assertThat(r.start.y).isEqualTo(2);
        assertThat(r.stops).hasSize(1);
        assertThat(r.stops[0].y).isEqualTo(4);
        assertThat(r.codes).containsExactly(5, 6);
        assertThat(r.detours).isNull();
    }

    public static class Scalars extends BrainIoTEvent {
        public int count;
        public long big;
        public double ratio;
        public float small;
        public boolean flag;
        public Integer boxed;
        public String text;
        public Thread.State state;
        public Object anything;
        public Point where;
        public List<Point> path;
        public java.time.LocalDate day;
        public java.time.Duration lasted;
    }

    @Test
    void aMapBecomesAnEventAsTheOsgiConverterBuildsIt() {
        List<Map<String, Object>> inputs = new ArrayList<>();
        Map<String, Object> exact = new LinkedHashMap<>();
        exact.put("count", 3);
        exact.put("big", 4L);
        exact.put("ratio", 0.5);
        exact.put("small", 1.5f);
        exact.put("flag", true);
        exact.put("boxed", 7);
        exact.put("text", "t");
        exact.put("state", Thread.State.RUNNABLE);
        exact.put("anything", "x");
        exact.put("timestamp", Instant.parse("2026-11-23T00:00:00Z"));
        exact.put("sourceNode", "nodeA");
        exact.put("where", Map.of("x", 1, "y", 2));
        exact.put("path", List.of(Map.of("x", 3, "y", 4)));
        inputs.add(exact);
        // as JSON from another node gives them: other number types, enums and instants as text
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("count", 3L);
        json.put("big", 4);
        json.put("ratio", 1);
        json.put("small", 2.25);
        json.put("flag", "true");
        json.put("boxed", 8L);
        json.put("text", 12);
        json.put("state", "BLOCKED");
        json.put("anything", List.of(1, 2));
        json.put("timestamp", "2026-11-23T00:00:00Z");
        json.put("day", "2026-11-23");
        json.put("lasted", "PT1.5S");
        json.put("where", Map.of("x", 5L, "y", "6"));
        json.put("unknown", "ignored");
        inputs.add(json);
        // numbers of narrower types, which take the widening path instead of the Converter
        Map<String, Object> narrower = new LinkedHashMap<>();
        narrower.put("count", (short) 3);
        narrower.put("big", Integer.MAX_VALUE);
        narrower.put("ratio", 0.75f);
        narrower.put("small", 5L);
        narrower.put("boxed", (byte) 9);
        inputs.add(narrower);
        Map<String, Object> nulls = new LinkedHashMap<>();
        nulls.put("text", null);
        nulls.put("count", null);
        nulls.put("flag", null);
        nulls.put("boxed", null);
        nulls.put("where", null);
        inputs.add(nulls);
        for (Map<String, Object> input : inputs) {
            Scalars ours = EventMaps.fromMap(input, Scalars.class);
            Scalars theirs = org.osgi.util.converter.Converters.standardConverter().convert(input).targetAsDTO()
                    .to(Scalars.class);
            assertThat(EventMaps.toMap(ours)).as("from %s", input).isEqualTo(EventMaps.toMap(theirs));
        }
    }

    @Test
    void onlyANumberOfANarrowerTypeIsWidenedTheRestGoesToTheConverter() {
        assertThat(EventMaps.Writer.widened(3, Long.class)).isEqualTo(3L);
        assertThat(EventMaps.Writer.widened(3L, Double.class)).isEqualTo(3.0);
        assertThat(EventMaps.Writer.widened(0.5f, Double.class)).isEqualTo(0.5);
        assertThat(EventMaps.Writer.widened((short) 2, Integer.class)).isEqualTo(2);
        assertThat(EventMaps.Writer.widened(3L, Integer.class)).as("narrowing").isNull();
        assertThat(EventMaps.Writer.widened(2.5, Long.class)).as("a fraction").isNull();
        assertThat(EventMaps.Writer.widened(0.5f, Long.class)).as("a fraction").isNull();
        assertThat(EventMaps.Writer.widened(3, String.class)).as("not a number field").isNull();
        assertThat(EventMaps.Writer.widened("3", Long.class)).as("text").isNull();
    }

    public static class Holder<T> extends BrainIoTEvent {
        public T value;
        public List<T> values;
    }

    public static class PointHolder extends Holder<Point> {
    }

    public static class Loose extends BrainIoTEvent {
        public Object anything;
    }

    @Test
    void fieldsOfATypeParameterAreBuiltAsTheClassBindsIt() {
        Map<String, Object> fields = new LinkedHashMap<>();
        fields.put("value", Map.of("x", 1, "y", 2));
        fields.put("values", List.of(Map.of("x", 3, "y", 4)));
        PointHolder h = EventMaps.fromMap(fields, PointHolder.class);
        assertThat(h.value.y).isEqualTo(2);
        assertThat(h.values).hasSize(1);
        assertThat(h.values.get(0).x).isEqualTo(3);
    }

    @Test
    void aValueForAnObjectFieldIsCopiedNotSharedWithTheMap() {
        List<Object> shared = new ArrayList<>(List.of(new ArrayList<>(List.of(1))));
        Map<String, Object> fields = new LinkedHashMap<>();
        fields.put("anything", shared);
        Loose h = EventMaps.fromMap(fields, Loose.class);
        assertThat(h.anything).isEqualTo(shared).isNotSameAs(shared);
        assertThat(((List<?>) h.anything).get(0)).isNotSameAs(shared.get(0));
    }

    @Test
    void anEventIsConvertedToAnotherClassWithTheSameFieldNames() {
        OtherRoute other = EventMaps.convert(route(), OtherRoute.class);
        assertThat(other.robotId).isEqualTo("robot1");
        assertThat(other.timestamp).isEqualTo(Instant.parse("2026-11-23T00:00:00Z"));
        assertThat(other.start.x).isEqualTo(1L);
        assertThat(other.stops).extracting(p -> p.y).containsExactly(4L, 6L);
        assertThat(other.codes).containsExactly(9L, 10L);
    }

    @Test
    void aCopiedMapSharesNothingMutableWithTheOriginal() {
        List<Object> stops = new ArrayList<>(List.of(new LinkedHashMap<>(Map.of("x", 1))));
        Map<String, Object> original = new LinkedHashMap<>();
        original.put("stops", stops);
        original.put("start", point(2, 3));
        original.put("codes", new int[] { 4 });
        Map<String, Object> copy = EventMaps.copyMap(original);

        stops.add("added later");
        @SuppressWarnings("unchecked")
        Map<String, Object> firstStop = (Map<String, Object>) stops.get(0);
        firstStop.put("x", 99);
        assertThat(copy.get("stops")).isEqualTo(List.of(Map.of("x", 1)));
        assertThat(copy.get("start")).as("a data object becomes a map, as toMap makes it")
                .isEqualTo(Map.of("x", 2, "y", 3));
        assertThat(copy.get("codes")).isEqualTo(List.of(4));
    }
}
