package eu.brain.iot.dashboard.browser;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.Base64;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.chrome.ChromeDriver;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/**
 * The "Nodes" panel with a real fabric: two real nodes (node/target/fabric-node.jar, each its own JVM, state folder
 * and port) joined through a real Mosquitto, the page of node-a in headless Chromium. The page shows node-a (this
 * node) online and node-b online with its behaviours; an event node-a publishes that node-b's behaviours take shows
 * up live in node-b's counters (sent, acknowledged); once node-b is killed (kill -9: its Last Will) the page shows it
 * offline. The panel fits the window and its headers align as their cells. Screenshots: target/screenshots/nodes-online.png, nodes-offline.png.
 */
class DashboardNodesTest {

    private static final String FABRIC = "dashboard-test";
    private static final String A = "node-a";
    private static final String B = "node-b";
    /**
     * Taken by every node's edge (it consumes {@code EdgeCommand}): published on a, it goes to b too. For a device no
     * fleet has, so that both edges only answer it with a refused {@code CommandOutcome}; the dashboard's own
     * consumer stays local and pulls nothing across.
     */
    private static final String TAKEN_BY_B = "eu.brain.iot.edge.api.CancelMissionCommand deviceId=no-such-robot";
    /** Small, so that the Last Will of a killed node comes within 1.5 of it. */
    private static final int KEEP_ALIVE_S = 2;
    private static final int KEY_BYTES = 32;
    private static final Duration SHOWN = Duration.ofSeconds(60);
    private static final Duration POLL = Duration.ofMillis(250);
    /** The browser window's width (see {@link Chromium}). */
    private static final int WIDTH = 1400;

    @TempDir
    Path home;

    @Test
    void thePageShowsTheOtherNodeOnlineWithItsCountersThenOfflineOnceKilled() throws Exception {
        Chromium.assumeInstalled();
        Path key = key(home.resolve("fabric.key"));
        try (Mosquitto broker = Mosquitto.start(home.resolve("broker"));
                RobotSim sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
                Node a = new Node(home.resolve(A), sim.baseUri(), 500, false)
                        .withFabric(broker.uri(), FABRIC, A, key, KEEP_ALIVE_S).withShell().start();
                Node b = new Node(home.resolve(B), sim.baseUri(), 500, false)
                        .withFabric(broker.uri(), FABRIC, B, key, KEEP_ALIVE_S).start()) {
            ChromeDriver driver = Chromium.start(home.resolve("chromium-profile"));
            try {
                DashboardPage page = new DashboardPage(driver);
                page.open(a.dashboard());
                await("node-a online (this node) and node-b online with its behaviours, in the page")
                        .atMost(SHOWN).pollInterval(POLL).until(() -> {
                            Map<String, Map<String, String>> rows = rows(page);
                            return "online".equals(cell(rows, A, "status")) && "true".equals(cell(rows, A, "self"))
                                    && "online".equals(cell(rows, B, "status"))
                                    && number(cell(rows, B, "behaviours")) > 0;
                        });
                assertThat((String) page.script("return document.getElementById('nodes-summary').textContent;"))
                        .contains("fabric " + FABRIC).contains(broker.uri().toString())
                        .contains("1 of 1 other node online");

                assertThat(((Number) page.script("return document.documentElement.scrollWidth;")).intValue())
                        .as("the page is no wider than the window").isLessThanOrEqualTo(WIDTH);
                assertThat((Object) page.script("const t = document.getElementById('nodes'); const out = [];"
                        + " const row = t.tBodies[0].rows[1];"
                        + " t.tHead.querySelectorAll('th').forEach((th, i) => { const td = row.cells[i];"
                        + "   if (getComputedStyle(th).textAlign !== getComputedStyle(td).textAlign)"
                        + "     out.push(th.textContent); });"
                        + " return out;")).as("headers aligned as their cells").isEqualTo(List.of());

                a.type("bus:publish " + TAKEN_BY_B);
                await("node-b's counters on node-a's page: the event sent and acknowledged").atMost(SHOWN)
                        .pollInterval(POLL).until(() -> {
                            Map<String, Map<String, String>> rows = rows(page);
                            return number(cell(rows, B, "sent")) >= 1 && number(cell(rows, B, "acked")) >= 1
                                    && number(cell(rows, B, "backlog")) == 0;
                        });
                page.screenshot("nodes-online");

                b.kill();
                await("node-b offline in the page once killed (its Last Will)").atMost(SHOWN).pollInterval(POLL)
                        .until(() -> "offline".equals(cell(rows(page), B, "status")));
                assertThat(cell(rows(page), A, "status")).as("this node stays online").isEqualTo("online");
                assertThat((String) page.script("return document.getElementById('nodes-summary').textContent;"))
                        .contains("0 of 1 other node online");
                page.screenshot("nodes-offline");
            } finally {
                driver.quit();
            }
        }
    }

    /** A fabric key file as fabric:keygen writes it: 32 random bytes in Base64, owner-only. */
    private static Path key(Path file) throws Exception {
        byte[] secret = new byte[KEY_BYTES];
        new SecureRandom().nextBytes(secret);
        Files.createFile(file, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        Files.writeString(file, Base64.getEncoder().encodeToString(secret));
        return file;
    }

    /** The Nodes table as shown: per node, each column's text by its header, and the row's status and self flags. */
    @SuppressWarnings("unchecked")
    private static Map<String, Map<String, String>> rows(DashboardPage page) {
        return (Map<String, Map<String, String>>) page.script("const out = {};"
                + " const t = document.getElementById('nodes');"
                + " if (!t || document.getElementById('nodes-panel').hidden || !t.tHead.rows.length) return out;"
                + " const names = [...t.tHead.rows[0].cells].map(c => c.textContent);"
                + " for (const tr of t.tBodies[0].rows) { const r = {};"
                + "   names.forEach((n, i) => r[n] = tr.cells[i] ? tr.cells[i].textContent : '');"
                + "   r.status = tr.dataset.status; r.self = tr.dataset.self; out[tr.dataset.node] = r; }"
                + " return out;");
    }

    private static String cell(Map<String, Map<String, String>> rows, String node, String column) {
        Map<String, String> row = rows.get(node);
        return row == null ? null : row.get(column);
    }

    private static long number(String text) {
        return text == null || text.isBlank() ? -1 : Long.parseLong(text.trim());
    }
}
