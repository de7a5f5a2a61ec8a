package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/**
 * Batches on the wire: a large one travels deflated and reads back the same, a small one stays JSON text, and a
 * deflated payload that is cut short, corrupt or inflates beyond the limit is refused as malformed.
 */
class CompressionTest {

    final Wire wire = new Wire();
    final Compression compression = new Compression();

    @Test
    void aLargeBatchTravelsDeflatedAndReadsBackTheSame() throws Exception {
        List<byte[]> events = new ArrayList<>();
        for (int i = 1; i <= 200; i++) {
            events.add(wire.event(i, "x.Moved", List.of("x.Moved", "x.Event"), Map.<String, Object>of("robot", "robot" + i, "n", i)));
        }
        byte[] payload = wire.batch("a", "b", "e1", 42L, events);

        assertThat(Compression.isDeflated(payload)).isTrue();
        int plain = events.stream().mapToInt(e -> e.length).sum();
        assertThat(payload.length).as("deflated size against %d bytes of events", plain).isLessThan(plain / 4);
        Wire.Batch batch = wire.readBatch(payload);
        assertThat(batch.from()).isEqualTo("a");
        assertThat(batch.sent()).isEqualTo(42L);
        assertThat(batch.events()).hasSize(200);
        assertThat(batch.events().get(199).seq()).isEqualTo(200);
        assertThat(batch.events().get(199).data()).containsEntry("robot", "robot200").containsEntry("n", 200);
        assertThat(batch.events().get(0).types()).containsExactly("x.Moved", "x.Event");
    }

    @Test
    void aSmallBatchStaysJsonText() throws Exception {
        byte[] payload = wire.batch("a", "b", "e1", 42L, List.of(wire.event(1, "x.Moved", List.of("x.Moved"),
                Map.<String, Object>of("n", 1))));
        assertThat(payload.length).isLessThan(Compression.MIN_BYTES);
        assertThat(new String(payload, StandardCharsets.UTF_8)).startsWith("{\"from\":\"a\"");
        assertThat(Compression.isDeflated(payload)).isFalse();
        assertThat(wire.readBatch(payload).events()).hasSize(1);
    }

    @Test
    void aDeflatedPayloadCutShortOrCorruptIsMalformed() {
        byte[] deflated = compression.deflate(text(4096).getBytes(StandardCharsets.UTF_8));
        byte[] cut = Arrays.copyOf(deflated, deflated.length / 2);
        assertThatThrownBy(() -> wire.readBatch(cut)).isInstanceOf(Wire.MalformedException.class)
                .hasMessageContaining("ends before its stream");
        byte[] corrupt = deflated.clone();
        for (int i = 2; i < corrupt.length; i++) {
            corrupt[i] = (byte) 0xff;
        }
        assertThatThrownBy(() -> wire.readBatch(corrupt)).isInstanceOf(Wire.MalformedException.class)
                .hasMessageContaining("not a zlib stream");
    }

    @Test
    void aPayloadThatInflatesBeyondTheLimitIsRefusedBeforeItIsRead() {
        byte[] bomb = compression.deflate(new byte[Compression.MAX_INFLATED_BYTES + 1]);
        assertThat(bomb.length).isLessThan(100_000);
        assertThatThrownBy(() -> wire.readBatch(bomb)).isInstanceOf(Wire.MalformedException.class)
                .hasMessageContaining("inflates to more than");
    }

    private static String text(int length) {
        StringBuilder b = new StringBuilder("{\"events\":[");
        while (b.length() < length) {
            b.append("{\"seq\":").append(b.length()).append("},");
        }
        return b.append("{}]}").toString();
    }
}
