package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.eventing.spi.EventForwarder;
import eu.brain.iot.eventing.spi.RemoteEvents;

/**
 * Refusals are logged without flooding the log: the first of each reason from a node at once, then at most one line
 * a minute per node with the number refused since; names never verified are counted in one total and followed one by
 * one only up to a bound.
 */
class RefusalsTest {

    @TempDir
    Path tmp;

    final List<String> log = new CopyOnWriteArrayList<>();
    final AtomicLong clock = new AtomicLong(1_000_000);

    final Host host = new Host() {
        @Override
        public RemoteEvents remoteEvents() {
            return null;
        }

        @Override
        public AutoCloseable addForwarder(String destination, InterestEntry entry, EventForwarder forwarder) {
            return null;
        }

        @Override
        public void warn(String message, Object... args) {
            log.add(TestNode.format(message, args));
        }

        @Override
        public void info(String message, Object... args) {
            // not refusals
        }
    };

    Refusals refusals() {
        return new Refusals(Settings.of("tcp://127.0.0.1:1", "test", "a", tmp.resolve("fabric.key"), tmp),
                host, clock::get);
    }

    @Test
    void theFirstRefusalOfEachReasonIsToldThenOneLineAMinuteWithTheCount() {
        Refusals refusals = refusals();
        RemoteNode b = new RemoteNode("b");
        String topic = "brainiot/test/nodes/b/status";
        refusals.refused(topic, "b", Refusals.Reason.BAD_SIGNATURE, null, b);
        refusals.refused(topic, "b", Refusals.Reason.BAD_SIGNATURE, null, b);
        refusals.refused(topic, "b", Refusals.Reason.UNSIGNED, null, b);
        assertThat(log).hasSize(2);
        assertThat(log.get(0)).isEqualTo("Fabric test: node a refused a message on " + topic + " claiming to come "
                + "from node b: its signature does not match this node's fabric key (" + tmp.resolve("fabric.key")
                + "); nothing of it was applied. The sending node may use another fabric key: every node of a fabric "
                + "needs the same key file; federation/README.md (\"Trust\") says how to share it (counted in "
                + "fabric:stats as BAD-SIG, row b)");
        assertThat(log.get(1)).contains("it carries no signature");

        for (int i = 0; i < 10; i++) {
            clock.addAndGet(1000);
            refusals.refused(topic, "b", Refusals.Reason.BAD_SIGNATURE, null, b);
        }
        assertThat(log).as("within a minute of the last line").hasSize(2);
        clock.addAndGet(Refusals.REPEAT_MILLIS);
        refusals.refused(topic, "b", Refusals.Reason.BAD_SIGNATURE, null, b);
        assertThat(log).hasSize(3);
        assertThat(log.get(2)).endsWith("; 12 refused from node b in the last 70 s without a line of their own "
                + "(this one included)");
        assertThat(b.stats.snapshot().badSignature()).isEqualTo(13);
        assertThat(b.stats.snapshot().unsigned()).isEqualTo(1);
        assertThat(refusals.unverified.snapshot().refused()).isZero();
    }

    @Test
    void namesNeverVerifiedAreCountedInOneTotalAndFollowedOnlyUpToABound() {
        Refusals refusals = refusals();
        int names = 1000;
        for (int i = 0; i < names; i++) {
            refusals.refused("brainiot/test/nodes/evil" + i + "/status", "evil" + i, Refusals.Reason.UNSIGNED, null,
                    null);
        }
        assertThat(refusals.unverified.snapshot().unsigned()).isEqualTo(names);
        assertThat(log).as("one line per followed name, one for the others").hasSize(
                Refusals.MAX_TRACKED_NAMES + 1);
        assertThat(log.get(0)).endsWith("(counted in fabric:stats as UNSIGNED, row (unverified))");
    }

    @Test
    void aNodeThatHeardOnlyBadSignaturesSaysItsKeyIsMostLikelyNotTheFabrics() {
        Refusals refusals = refusals();
        refusals.refused("brainiot/test/nodes/c/status", "c", Refusals.Reason.BAD_SIGNATURE, null, null);
        refusals.refused("brainiot/test/nodes/b/status", "b", Refusals.Reason.BAD_SIGNATURE, null, null);
        log.clear();
        refusals.checkAlone();
        assertThat(log).singleElement().asString().contains("has refused every message of the other nodes (b, c)")
                .contains("this node's key file " + tmp.resolve("fabric.key") + " is most likely not the fabric's");
        refusals.checkAlone();
        assertThat(log).as("once").hasSize(1);

        Refusals heard = refusals();
        heard.refused("brainiot/test/nodes/c/status", "c", Refusals.Reason.BAD_SIGNATURE, null, null);
        heard.verified();
        log.clear();
        heard.checkAlone();
        assertThat(log).as("a verified message came: another node's key is wrong, not this one's").isEmpty();
    }
}
