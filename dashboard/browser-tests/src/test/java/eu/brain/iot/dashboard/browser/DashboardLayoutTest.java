package eu.brain.iot.dashboard.browser;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.chrome.ChromeDriver;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/**
 * The page's layout in a 1,400 px wide headless Chromium, with a behaviour installed on demand (whose "why" is a
 * long sentence) and the bus's event types listed: nothing makes the page wider than the window, every column's
 * header is aligned as its cells are, the page declares its icon, and (the node has no fabric) shows no Nodes panel.
 * A screenshot is saved under target/screenshots/layout-1400.png.
 */
class DashboardLayoutTest {

    private static final String ROBOT_TRIGGER = "eu.brain.iot.behaviours.events.RobotBehaviorUnloadLocation";
    private static final Duration SHOWN = Duration.ofSeconds(60);

    @TempDir
    Path home;

    @Test
    void theFabricTablesFitTheWindowAndTheirHeadersAlignWithTheirColumns() throws Exception {
        Chromium.assumeInstalled();
        try (RobotSim sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
                Node node = new Node(home.resolve("node"), sim.baseUri(), 500, true).withShell().start()) {
            node.type("bus:publish " + ROBOT_TRIGGER);
            ChromeDriver driver = Chromium.start(home.resolve("chromium-profile"));
            try {
                DashboardPage page = new DashboardPage(driver);
                page.open(node.dashboard());
                await("the installed behaviour and the event types shown").atMost(SHOWN)
                        .pollInterval(Duration.ofMillis(250)).until(() -> (Boolean) page.script(
                                "return document.querySelectorAll('#behaviours tbody tr:not(.empty)').length > 0"
                                        + " && document.querySelectorAll('#event-types tbody tr:not(.empty)').length > 0"
                                        + " && document.querySelector('#behaviours tbody td:last-child')"
                                        + ".textContent.length > 60;"));
                page.screenshot("layout-1400");

                assertThat(((Number) page.script("return window.innerWidth;")).intValue()).isEqualTo(1400);
                assertThat(((Number) page.script("return document.documentElement.scrollWidth;")).intValue())
                        .as("the page is no wider than the window").isLessThanOrEqualTo(1400);
                assertThat((Boolean) page.script("const t = document.querySelector('#behaviours');"
                        + " return t.getBoundingClientRect().right <= t.closest('section').getBoundingClientRect().right;"))
                        .as("the behaviours table stays inside its card").isTrue();

                @SuppressWarnings("unchecked")
                List<String> misaligned = (List<String>) page.script("const out = [];"
                        + " for (const id of ['event-types', 'bms-history', 'behaviours', 'devices']) {"
                        + "   const t = document.getElementById(id); const row = t.querySelector('tbody tr:not(.empty)');"
                        + "   if (!row) continue;"
                        + "   t.querySelectorAll('thead th').forEach((th, i) => { const td = row.cells[i];"
                        + "     if (td && getComputedStyle(th).textAlign !== getComputedStyle(td).textAlign)"
                        + "       out.push(id + ' ' + th.textContent); }); }"
                        + " return out;");
                assertThat(misaligned).as("headers aligned as their cells").isEmpty();

                assertThat((Boolean) page.script("return document.getElementById('nodes-panel').hidden;"))
                        .as("a node without a fabric shows no Nodes panel").isTrue();

                assertThat((String) page.script("const l = document.querySelector('link[rel=icon]');"
                        + " return l ? l.href : null;")).endsWith("/dashboard/favicon.svg");
            } finally {
                driver.quit();
            }
        }
    }
}
