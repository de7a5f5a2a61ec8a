package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/**
 * A batch read from the wire: its events come as the maps untyped behaviours get (nested objects as maps, arrays as
 * lists, numbers as JSON gives them), and a batch that lacks a part names the part.
 */
class WireBatchTest {

    final Wire wire = new Wire();

    @Test
    void aBatchReadsBackWithItsEventsAsMapsOfFields() throws Exception {
        Map<String, Object> data = new LinkedHashMap<>();
        data.put("robotId", "robot7");
        data.put("x", 3);
        data.put("nanos", 12_345_678_901L);
        data.put("ratio", 0.5);
        data.put("stops", List.of(Map.of("x", 1, "y", 2)));
        data.put("nothing", null);
        byte[] payload = wire.batch("node1", "node2", "e9", 77L,
                List.of(wire.event(5, "a.Moved", List.of("a.Moved", "a.Base"), data),
                        wire.event(6, "a.Stopped", List.of(), Map.of())));

        Wire.Batch batch = wire.readBatch(payload);

        assertThat(batch.from()).isEqualTo("node1");
        assertThat(batch.to()).isEqualTo("node2");
        assertThat(batch.epoch()).isEqualTo("e9");
        assertThat(batch.sent()).isEqualTo(77L);
        assertThat(batch.events()).extracting(Wire.Event::seq).containsExactly(5L, 6L);
        Wire.Event first = batch.events().get(0);
        assertThat(first.type()).isEqualTo("a.Moved");
        assertThat(first.types()).containsExactly("a.Moved", "a.Base");
        assertThat(first.data()).isEqualTo(data);
        assertThat(first.data().get("x")).isInstanceOf(Integer.class);
        assertThat(first.data().get("nanos")).isInstanceOf(Long.class);
        assertThat(batch.events().get(1).data()).isEmpty();
    }

    @Test
    void aBatchWithoutAPartIsRefusedNamingThePart() {
        String event = "{\"seq\":1,\"type\":\"a.T\",\"types\":[],\"data\":{}}";
        String head = "\"from\":\"n1\",\"to\":\"n2\",\"epoch\":\"e\",\"sent\":1";
        assertMalformed("[1,2]", "not a batch");
        assertMalformed("{" + head + "}", "an 'events' array");
        assertMalformed("{" + head + ",\"events\":[{\"type\":\"a.T\",\"data\":{}}]}", "'seq'");
        assertMalformed("{" + head + ",\"events\":[{\"seq\":1,\"data\":{}}]}", "'type'");
        assertMalformed("{" + head + ",\"events\":[{\"seq\":1,\"type\":\"a.T\"}]}", "object 'data'");
        assertMalformed("{" + head + ",\"events\":[{\"seq\":1,\"type\":\"a.T\",\"data\":5}]}", "not a batch");
        assertMalformed("{" + head + ",\"events\":[{\"seq\":\"x\",\"type\":\"a.T\",\"data\":{}}]}", "not a batch");
        assertMalformed("{\"to\":\"n2\",\"epoch\":\"e\",\"sent\":1,\"events\":[" + event + "]}", "'from'");
        assertMalformed("{\"from\":\"n1\",\"to\":\"n2\",\"epoch\":\"e\",\"events\":[" + event + "]}", "'sent'");
        assertMalformed("{" + head + ",\"events\":[" + (event + ",").repeat(Wire.MAX_BATCH_EVENTS) + event + "]}",
                "at most " + Wire.MAX_BATCH_EVENTS);
    }

    private void assertMalformed(String json, String says) {
        assertThatThrownBy(() -> wire.readBatch(json.getBytes(StandardCharsets.UTF_8)))
                .isInstanceOf(Wire.MalformedException.class).hasMessageContaining(says);
    }
}
