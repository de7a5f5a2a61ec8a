package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.federation.impl.Journal.Pending;

/**
 * An outbox and its journal: an event goes on the wire only once the journal holds it, the sender thread writes the
 * journal whether or not the events are sent, and a publishing node started again finds every event its destination
 * has not acknowledged, in order, under the same epoch.
 */
class OutboxTest {

    @TempDir
    Path dir;

    @Test
    void anEventIsTakenOnlyOnceTheJournalHoldsIt() throws Exception {
        try (Outbox outbox = new Outbox("b", dir.resolve("b.journal"), 100, new NodeStats())) {
            append(outbox, 3);
            assertThat(outbox.hasUnsent()).isTrue();
            assertThat(outbox.take(10)).as("nothing before the journal has it").isEmpty();
            assertThat(journalLines()).noneMatch(l -> l.startsWith("E "));

            outbox.writeJournal();
            assertThat(journalLines()).filteredOn(l -> l.startsWith("E ")).hasSize(3);
            assertThat(outbox.take(10)).extracting(Pending::seq).containsExactly(1L, 2L, 3L);
        }
    }

    @Test
    void aPublisherAppendsWithoutWaitingOnlyWhileThereIsRoom() throws Exception {
        Outbox outbox = new Outbox("b", dir.resolve("b.journal"), 2, new NodeStats());
        try (outbox) {
            assertThat(outbox.tryAppend(OutboxTest::json)).isTrue();
            assertThat(outbox.tryAppend(OutboxTest::json)).isTrue();
            assertThat(outbox.tryAppend(OutboxTest::json)).as("full: refused, nothing kept").isFalse();

            outbox.writeJournal();
            List<Pending> sent = outbox.take(10);
            assertThat(sent).extracting(Pending::seq).containsExactly(1L, 2L);
            assertThat(outbox.tryAppend(OutboxTest::json)).as("sent, not acknowledged: still full").isFalse();
            outbox.acked(outbox.epoch(), 1);
            assertThat(outbox.tryAppend(OutboxTest::json)).as("room again once one is acknowledged").isTrue();
            outbox.writeJournal();
            assertThat(outbox.take(10)).extracting(Pending::seq).containsExactly(3L);
        }
        assertThat(outbox.tryAppend(OutboxTest::json)).as("closed").isFalse();
    }

    @Test
    void givingUpTakesOutEverythingKeptInOrderAndStartsANewSequence() throws Exception {
        String oldEpoch;
        try (Outbox outbox = new Outbox("b", dir.resolve("b.journal"), 100, new NodeStats())) {
            oldEpoch = outbox.epoch();
            append(outbox, 4);
            outbox.writeJournal();
            outbox.take(2); // 1 and 2 sent, not acknowledged; 3 and 4 not sent
            append(outbox, 1); // 5: not in the journal yet

            Outbox.Abandoned abandoned = outbox.abandon();

            assertThat(abandoned.events()).extracting(Pending::seq).containsExactly(1L, 2L, 3L, 4L, 5L);
            assertThat(abandoned.restoredThrough()).as("nothing read from the journal at start").isZero();
            assertThat(outbox.epoch()).isNotEqualTo(oldEpoch);
            assertThat(outbox.backlog()).isZero();
            outbox.acked(oldEpoch, 5); // the old sequence's acknowledgement, late: nothing to free, no error
            append(outbox, 1);
            outbox.writeJournal();
            Outbox.Taken next = outbox.takeBatch(10);
            assertThat(next.epoch()).isEqualTo(outbox.epoch());
            assertThat(next.events()).extracting(Pending::seq).as("numbered from 1 again").containsExactly(1L);
        }
        try (Outbox again = new Outbox("b", dir.resolve("b.journal"), 100, new NodeStats())) {
            assertThat(again.epoch()).as("the journal has the new sequence").isNotEqualTo(oldEpoch);
            append(again, 1);
            again.writeJournal();
            Outbox.Abandoned restored = again.abandon();
            assertThat(restored.events()).extracting(Pending::seq).as("only what came after").containsExactly(1L, 2L);
            assertThat(restored.restoredThrough()).as("1 was read from the journal at start, 2 was not").isEqualTo(1);
        }
    }

    @Test
    void aRestartedPublisherFindsWhatWasNotAcknowledgedSentOrNot() throws Exception {
        String epoch;
        try (Outbox outbox = new Outbox("b", dir.resolve("b.journal"), 100, new NodeStats())) {
            epoch = outbox.epoch();
            append(outbox, 4);
            outbox.writeJournal();
            outbox.take(2); // 1 and 2 on the wire
            outbox.acked(epoch, 1);
            append(outbox, 1); // 5: its node went away, never taken
            outbox.writeJournal();
        }
        try (Outbox again = new Outbox("b", dir.resolve("b.journal"), 100, new NodeStats())) {
            assertThat(again.epoch()).isEqualTo(epoch);
            assertThat(again.take(10)).extracting(Pending::seq).containsExactly(2L, 3L, 4L, 5L);
            append(again, 1);
            again.writeJournal();
            assertThat(again.take(10)).extracting(Pending::seq).as("numbering goes on").containsExactly(6L);
        }
    }

    /**
     * What was sent, less what was sent again, is what the destination acknowledges in the end: an event whose
     * publication failed (the broker went) is first sent after the reconnection, and an event rewound whose
     * acknowledgement came before it went again was sent once.
     */
    @Test
    void sentLessResentIsWhatWasAcknowledgedAcrossAFailedPublicationAndALateAcknowledgement() throws Exception {
        NodeStats stats = new NodeStats();
        try (Outbox outbox = new Outbox("b", dir.resolve("b.journal"), 100, stats)) {
            String epoch = outbox.epoch();
            append(outbox, 3);
            outbox.writeJournal();
            outbox.sent(outbox.takeBatch(1)); // 1 on the wire
            outbox.takeBatch(1); // 2 taken, its publication failed: the broker went
            outbox.rewind(true, 0); // the reconnection: 1 and 2 to send again
            outbox.sent(outbox.takeBatch(10)); // 1 again, 2 and 3 for the first time
            outbox.acked(epoch, 3);
            NodeStats.Snapshot s = stats.snapshot();
            assertThat(s.sent() + " sent, " + s.resent() + " resent, " + s.acked() + " acknowledged")
                    .isEqualTo("4 sent, 1 resent, 3 acknowledged");

            append(outbox, 1);
            outbox.writeJournal();
            outbox.sent(outbox.takeBatch(1)); // 4 on the wire
            outbox.rewind(true, 0); // a reconnection; 4's acknowledgement comes before it goes again
            outbox.acked(epoch, 4);
            assertThat(outbox.hasUnsent()).isFalse();
            s = stats.snapshot();
            assertThat(s.sent() - s.resent()).as("sent less resent").isEqualTo(s.acked()).isEqualTo(4);
        }
    }

    @Test
    void aCompactedJournalKeepsThePendingEventsAndTheNumbering() throws Exception {
        String epoch;
        byte[] big = new byte[64 * 1024];
        java.util.Arrays.fill(big, (byte) ' ');
        int bigEvents = (int) (Journal.COMPACT_BYTES / big.length) + 10;
        try (Outbox outbox = new Outbox("b", dir.resolve("b.journal"), 100, new NodeStats())) {
            epoch = outbox.epoch();
            for (int i = 0; i < bigEvents; i++) {
                outbox.append(seq -> big);
                outbox.writeJournal();
                outbox.acked(epoch, outbox.take(10).get(0).seq());
            }
            append(outbox, 1);
            outbox.writeJournal();
        }
        assertThat(Files.size(dir.resolve("b.journal"))).as("compacted").isLessThan(1 << 20);
        try (Outbox again = new Outbox("b", dir.resolve("b.journal"), 100, new NodeStats())) {
            assertThat(again.epoch()).isEqualTo(epoch);
            List<Pending> pending = again.take(10);
            assertThat(pending).extracting(Pending::seq).containsExactly(bigEvents + 1L);
            append(again, 1);
            again.writeJournal();
            assertThat(again.take(10)).extracting(Pending::seq).containsExactly(bigEvents + 2L);
        }
    }

    private static void append(Outbox outbox, int events) throws InterruptedException {
        for (int i = 0; i < events; i++) {
            outbox.append(OutboxTest::json);
        }
    }

    private static byte[] json(long seq) {
        return ("{\"n\":" + seq + "}").getBytes(StandardCharsets.UTF_8);
    }

    private List<String> journalLines() throws Exception {
        return Files.readAllLines(dir.resolve("b.journal"), StandardCharsets.UTF_8);
    }
}
