package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * When a node was last connected, kept in its state folder: away for half of the give-up time or more, it joins
 * with a clean broker session; and when an event given up was first published.
 */
class LastConnectedTest {

    static final long GIVE_UP = 30_000;

    @Test
    void aNodeNeverConnectedOrBackSoonKeepsItsSessionOneAwayLongStartsClean(@TempDir Path state) {
        Host host = new Host() {
            @Override
            public eu.brain.iot.eventing.spi.RemoteEvents remoteEvents() {
                throw new UnsupportedOperationException();
            }

            @Override
            public AutoCloseable addForwarder(String destination, InterestEntry entry,
                    eu.brain.iot.eventing.spi.EventForwarder forwarder) {
                throw new UnsupportedOperationException();
            }

            @Override
            public void warn(String message, Object... args) {
                throw new AssertionError(TestNode.format(message, args));
            }

            @Override
            public void info(String message, Object... args) {
                // nothing to see
            }
        };
        LastConnected first = new LastConnected(state, GIVE_UP);
        assertThat(first.cleanStart(1_000_000)).as("never connected: no session to fear").isFalse();
        first.connected(1_000_000, host, "f");

        LastConnected soon = new LastConnected(state, GIVE_UP);
        assertThat(soon.awayMillis(1_010_000)).isEqualTo(10_000);
        assertThat(soon.cleanStart(1_010_000)).as("10 s away, read back from the file").isFalse();
        assertThat(soon.cleanStart(1_015_000)).as("half of the give-up time").isTrue();
        assertThat(soon.periodMillis()).isEqualTo(5_000);
    }

    @Test
    void anUnreadableFileCountsAsNeverConnected(@TempDir Path state) throws Exception {
        Files.writeString(state.resolve(LastConnected.FILE), "not a time");
        assertThat(new LastConnected(state, GIVE_UP).cleanStart(Long.MAX_VALUE / 2)).isFalse();
    }

    @Test
    void anEventGivenUpWasPublishedAtItsTimestampAtTheLatestWhenItsNodeWasSeenOffline() {
        long seen = Instant.parse("2026-11-30T01:00:00Z").toEpochMilli();
        assertThat(GivingUp.publishedMillis(Map.of("timestamp", "2026-11-30T00:59:58Z"), seen))
                .isEqualTo(seen - 2_000);
        assertThat(GivingUp.publishedMillis(Map.of(), seen)).isEqualTo(seen);
        assertThat(GivingUp.publishedMillis(Map.of("timestamp", "soon"), seen)).isEqualTo(seen);
        assertThat(GivingUp.publishedMillis(Map.of("timestamp", "2026-11-30T01:00:05Z"), seen)).isEqualTo(seen);
    }
}
