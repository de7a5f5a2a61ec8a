package eu.brain.iot.federation.impl;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.TestInfo;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the multi-node tests share: a real broker started per test on a free port (Mosquitto, skipped where its
 * binary is missing, or embedded HiveMQ CE), the fabric's key, and the nodes a test starts; after each test, every
 * node's log goes to {@code target/<prefix>-<test>[-<run>].log}, then the nodes and the broker are stopped.
 */
abstract class FabricTestBase {

    @TempDir
    Path tmp;
    Broker broker;
    Path key;
    final List<TestNode> nodes = new ArrayList<>();

    /** @return the prefix of the log files this class's tests leave in {@code target/} */
    abstract String logPrefix();

    @AfterEach
    void tearDown(TestInfo info) throws Exception {
        StringBuilder report = new StringBuilder(info.getDisplayName()).append('\n');
        for (TestNode n : nodes) {
            n.log.forEach(l -> report.append(n.name).append(": ").append(l).append('\n'));
        }
        Files.createDirectories(Path.of("target"));
        // a parameterised test's runs each get their own file: "[1] kind=MOSQUITTO" gives "-1-kind-MOSQUITTO"
        String run = info.getDisplayName().startsWith("[")
                ? "-" + info.getDisplayName().replaceAll("[^A-Za-z0-9]+", "-").replaceAll("^-|-$", "") : "";
        Files.writeString(Path.of("target", logPrefix() + "-" + info.getTestMethod().get().getName() + run + ".log"),
                report);
        for (TestNode n : nodes) {
            try {
                n.close();
            } catch (RuntimeException e) {
                // crashed already
            }
        }
        if (broker != null) {
            broker.close();
        }
    }

    void startBroker(Broker.Kind kind) throws Exception {
        if (kind == Broker.Kind.MOSQUITTO) {
            Assumptions.assumeTrue(Files.isExecutable(Broker.MOSQUITTO), "Mosquitto is not installed ("
                    + Broker.MOSQUITTO + " missing: apt-get install mosquitto); the Mosquitto variant is skipped");
        }
        broker = Broker.of(kind, tmp.resolve("broker"));
        key = tmp.resolve("fabric.key");
        FabricKey.generate(key);
    }

    /** A node of this test's fabric, started. */
    TestNode node(String name) throws Exception {
        TestNode n = new TestNode(name, settings(name));
        nodes.add(n);
        n.start();
        return n;
    }

    /** The settings of a node of this test's fabric. */
    Settings settings(String name) {
        return Settings.of(broker.uri(), "test", name, key, tmp.resolve("state-" + name)).withResendTimeout(1000)
                .withKeepAlive(2);
    }
}
