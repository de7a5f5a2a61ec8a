package eu.brain.iot.dashboard;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

class EventLogTest {

    private final EventLog log = new EventLog("e1", 3);

    @Test
    void replaysWhatAReconnectingPageMissed() {
        log.append("delta", "{\"a\":1}");
        log.append("delta", "{\"a\":2}");
        log.append("delta", "{\"a\":3}");

        assertThat(log.after("e1-1").orElseThrow()).extracting(EventLog.Frame::n).containsExactly(2L, 3L);
        assertThat(log.after("e1-3").orElseThrow()).isEmpty();
        assertThat(log.after("e1-2").orElseThrow().get(0).text())
                .isEqualTo("id: e1-3\nevent: delta\ndata: {\"a\":3}\n\n");
    }

    @Test
    void asksForASnapshotWhenTheMissedEventsAreGoneOrFromAnotherStart() {
        for (int i = 0; i < 5; i++) {
            log.append("delta", "{}");
        }
        assertThat(log.after("e1-1")).as("events 2 and 3 dropped from a log of 3").isEmpty();
        assertThat(log.after("e1-2").orElseThrow()).extracting(EventLog.Frame::n).containsExactly(3L, 4L, 5L);
        assertThat(log.after("e0-4")).as("another epoch: the node restarted").isEmpty();
        assertThat(log.after("e1-9")).as("an id from the future").isEmpty();
        assertThat(log.after("e1-x")).isEmpty();
        assertThat(log.after(null)).isEmpty();
    }

    @Test
    void aSnapshotCarriesTheIdOfTheLastEventItIncludes() {
        log.append("delta", "{}");
        assertThat(log.lastId()).isEqualTo("e1-1");
        assertThat(log.snapshot("{}")).startsWith("id: e1-1\nevent: snapshot\n");
        assertThat(log.after(log.lastId()).orElseThrow()).isEqualTo(List.of());
    }
}
