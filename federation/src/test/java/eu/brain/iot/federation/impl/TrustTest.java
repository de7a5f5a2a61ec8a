package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import eu.brain.iot.federation.impl.Events.Moved;
import eu.brain.iot.federation.impl.Events.Recorder;

/**
 * A node refuses, and counts, events that are unsigned, signed with another key, or replayed (signed too long ago, or
 * a sequence number it took already), sent by a client of the same broker that is not a member of the fabric; and a
 * node without the fabric's key does not join.
 */
class TrustTest extends FabricTestBase {

    static final Duration DEADLINE = Duration.ofSeconds(60);
    static final String MOVED = Moved.class.getName();

    TestNode a;
    TestNode b;
    Intruder attacker;

    @Override
    String logPrefix() {
        return "trust-test";
    }

    @AfterEach
    void closeAttacker() throws Exception {
        if (attacker != null) {
            attacker.close();
        }
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void unsignedWronglySignedAndReplayedEventsAreRefused(Broker.Kind kind) throws Exception {
        startBroker(kind);
        a = new TestNode("a", settings("a"));
        nodes.add(a);
        a.start();
        Recorder r = new Recorder();
        b = new TestNode("b", settings("b"));
        nodes.add(b);
        b.addBehaviour(r, null, MOVED);
        b.start();
        FabricTest.awaitInterest(a, b, 1);
        a.bus.deliver(new Moved("r1", 1));
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(r.got.size() + " received, backlog "
                + a.statsOf("b").backlog()).isEqualTo("1 received, backlog 0"));

        String epoch = Files.readAllLines(tmp.resolve("state-a/outbox/b.journal"), StandardCharsets.US_ASCII).get(0)
                .substring("EPOCH ".length());
        String topic = new Topics("test").events("b", "a");
        Wire wire = new Wire();
        FabricKey right = FabricKey.read(key);
        FabricKey wrong = FabricKey.of(new byte[32]);
        long now = System.currentTimeMillis();
        byte[] forged = wire.batch("a", "b", epoch, now,
                List.of(wire.event(2, MOVED, List.of(MOVED), Map.of("robotId", "forged", "seq", 2))));
        byte[] old = wire.batch("a", "b", epoch, now - TimeUnit.HOURS.toMillis(1),
                List.of(wire.event(2, MOVED, List.of(MOVED), Map.of("robotId", "old", "seq", 2))));
        byte[] replayed = wire.batch("a", "b", epoch, now,
                List.of(wire.event(1, MOVED, List.of(MOVED), Map.of("robotId", "again", "seq", 1))));

        attacker = new Intruder(broker.uri());
        publish(topic, forged, null);
        publish(topic, forged, wrong.sign(topic, forged));
        publish(topic, old, right.sign(topic, old));
        publish(topic, replayed, right.sign(topic, replayed));

        await().atMost(DEADLINE).until(() -> {
            NodeStats.Snapshot s = b.statsOf("a");
            return s.unsigned() == 1 && s.badSignature() == 1 && s.replayed() == 1 && s.duplicates() >= 1;
        });
        assertThat(b.statsOf("a").refused()).isEqualTo(3);

        // the genuine second event still comes, as number 2: nothing forged took its place
        a.bus.deliver(new Moved("r1", 2));
        await().atMost(DEADLINE).until(() -> r.got.size() >= 2);
        assertThat(r.got).extracting(m -> m.robotId).containsExactly("r1", "r1");
        assertThat(r.seqs()).containsExactly(1L, 2L);
    }

    @Test
    void aNodeWithoutTheKeyDoesNotJoinAndSaysWhy() {
        Path missing = tmp.resolve("no-such.key");
        Settings s = Settings.of("tcp://127.0.0.1:1", "test", "lonely", missing, tmp.resolve("state"));
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> new FabricNode(s, null))
                .hasMessageContaining("fabric key file").hasMessageContaining("fabric:keygen");
    }

    @Test
    void aKeyFileThatHoldsNoKeySaysWhatItShouldHoldAndWhatToDo() throws Exception {
        Path text = Files.writeString(tmp.resolve("hello.key"), "hello\n");
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> FabricKey.read(text))
                .hasMessageStartingWith("the fabric key file " + text + " is not a key: a key file holds one line of "
                        + "Base64, as fabric:keygen writes it (here: ")
                .hasMessageEndingWith("copy the fabric's key file here, or make a new one with fabric:keygen for "
                        + "every node");
        Path binary = Files.write(tmp.resolve("binary.key"), new byte[] { (byte) 0xff, (byte) 0xfe, 1 });
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> FabricKey.read(binary))
                .hasMessageContaining("is not a key: a key file holds one line of Base64");
        Path shortKey = Files.writeString(tmp.resolve("short.key"), "AAECAwQ=\n");
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> FabricKey.read(shortKey)).hasMessage("the fabric key "
                + "in " + shortKey + " is too short (5 bytes, at least 32); make a new one with fabric:keygen for "
                + "every node");
    }

    @Test
    void keygenRefusesToOverwriteAKey() throws Exception {
        Path k = tmp.resolve("k");
        FabricKey.generate(k);
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> FabricKey.generate(k))
                .hasMessageContaining("exists already");
        assertThat(FabricKey.read(k).verify("t", new byte[] { 1 }, FabricKey.read(k).sign("t", new byte[] { 1 })))
                .isTrue();
    }

    private void publish(String topic, byte[] payload, String signature) throws Exception {
        attacker.publish(topic, payload, signature, false);
    }
}
