package eu.brain.iot.node.ready;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/**
 * The wording of the two lines: what to type and how to stop, which depends on whether a shell reads the console;
 * counts that a reader cannot take for a failed bundle; the levels reached and why the shell comes after them.
 */
class ReadyLineTest {

    @Test
    void withTheInteractiveShellItNamesCommandsAndStop0() {
        assertThat(ReadyLines.howToUse(false, "", 42)).contains("bus:behaviours").endsWith("'stop 0' quits");
        assertThat(ReadyLines.howToUse(false, null, 42)).endsWith("'stop 0' quits");
        assertThat(ReadyLines.howToUse(false, "--login", 42)).endsWith("'stop 0' quits");
    }

    @Test
    void withoutAShellItSaysHowToStopTheProcess() {
        assertThat(ReadyLines.howToUse(false, "--nointeractive", 4711))
                .isEqualTo("no shell (gosh.args=--nointeractive): stop it with Ctrl-C or kill 4711")
                .doesNotContain("stop 0");
        assertThat(ReadyLines.howToUse(false, " --noshutdown  --nointeractive ", 4711)).endsWith("kill 4711");
    }

    @Test
    void aCheckRunStopsByItself() {
        assertThat(ReadyLines.howToUse(true, "", 42)).doesNotContain("stop 0").contains("stops once");
    }

    @Test
    void theReadyLineSaysThatTheBundlesNotYetActiveStartNext() {
        assertThat(ReadyLines.readyLine(812, "", 1, new Census(37, 0, 0, 41), "try lb"))
                .isEqualTo("fabric node ready in 812 ms (JVM start to event bus up; start level 1: 37 of 41 bundles "
                        + "active, the other 4 start next); try lb");
        assertThat(ReadyLines.readyLine(5, " and X", 1, new Census(14, 0, 0, 14), "try lb"))
                .contains("start level 1: 14 of 14 bundles active); try lb");
    }

    @Test
    void fragmentsAndLazyBundlesAreCountedApartFromTheActiveOnes() {
        assertThat(new Census(35, 2, 1, 41).describe())
                .isEqualTo("35 of 41 bundles active, 2 fragments attached, 1 lazy bundle waiting for first use");
        assertThat(ReadyLines.readyLine(1, "", 1, new Census(35, 2, 0, 41), "x"))
                .contains("35 of 41 bundles active, 2 fragments attached, the other 4 start next");
    }

    @Test
    void theSecondLineNamesTheLevelsReachedAndWhyTheShellComesLast() {
        assertThat(ReadyLines.upLine(1724, 2, new Census(40, 0, 0, 41),
                ReadyLines.whatIsNext(false, "", 3, 1)))
                .isEqualTo("fabric node: start levels 1 and 2 up in 1724 ms (the core, then the edge and its REST "
                        + "API): 40 of 41 bundles active; the other one starts at level 3: the Gogo shell, last so "
                        + "that its prompt follows this line");
        assertThat(ReadyLines.whatIsNext(false, "--nointeractive", 3, 2)).isEqualTo("; the other 2 start at "
                + "level 3: the Gogo shell (without a console: gosh.args=--nointeractive) and the config folder's "
                + "bundles");
        assertThat(ReadyLines.whatIsNext(true, "", 3, 1))
                .isEqualTo("; a check run stops here, before level 3 (the Gogo shell)");
        assertThat(ReadyLines.upLine(9, 3, new Census(5, 0, 0, 5), ""))
                .startsWith("fabric node: start levels 1 to 3 ");
    }

    @Test
    void theSecondLineLinksTheDashboardWhereFelixHttpListens() {
        assertThat(ReadyLines.upLine(1724, 2, new Census(40, 0, 0, 41), ReadyLines.dashboard("127.0.0.1", "8181")
                + ReadyLines.whatIsNext(false, "", 3, 1)))
                .isEqualTo("fabric node: start levels 1 and 2 up in 1724 ms (the core, then the edge and its REST "
                        + "API): 40 of 41 bundles active; dashboard: http://127.0.0.1:8181/dashboard/; the other one "
                        + "starts at level 3: the Gogo shell, last so that its prompt follows this line");
        assertThat(ReadyLines.dashboard("192.168.1.20", "9000"))
                .isEqualTo("; dashboard: http://192.168.1.20:9000/dashboard/");
        assertThat(ReadyLines.dashboard("::1", "8181")).isEqualTo("; dashboard: http://[::1]:8181/dashboard/");
        // a wildcard bind: an address that works on this machine, and a word for the others
        for (String wildcard : new String[] { null, "", "0.0.0.0", "::" }) {
            assertThat(ReadyLines.dashboard(wildcard, "8181")).as(wildcard)
                    .startsWith("; dashboard: http://127.0.0.1:8181/dashboard/ (listening on every interface");
        }
        assertThat(ReadyLines.dashboard("127.0.0.1", null)).isEqualTo("; dashboard: http://127.0.0.1:8080/dashboard/");
    }

    @Test
    void theCheckDeadlineIsConfigurableInSeconds() {
        assertThat(ReadyReporter.checkTimeoutSeconds(null)).isEqualTo(ReadyReporter.DEFAULT_CHECK_TIMEOUT_SECONDS);
        assertThat(ReadyReporter.checkTimeoutSeconds(" 7 ")).isEqualTo(7);
        assertThat(ReadyReporter.checkTimeoutSeconds("soon")).isEqualTo(ReadyReporter.DEFAULT_CHECK_TIMEOUT_SECONDS);
        assertThat(ReadyReporter.checkTimeoutSeconds("0")).isEqualTo(ReadyReporter.DEFAULT_CHECK_TIMEOUT_SECONDS);
    }
}
