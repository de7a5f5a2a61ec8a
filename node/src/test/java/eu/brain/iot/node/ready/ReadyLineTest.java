package eu.brain.iot.node.ready;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The end of the ready line: what to type and how to stop, which depends on whether a shell reads the console. */
class ReadyLineTest {

    @Test
    void withTheInteractiveShellItNamesCommandsAndStop0() {
        assertThat(ReadyReporter.howToUse(false, "", 42)).contains("bus:behaviours").endsWith("'stop 0' quits");
        assertThat(ReadyReporter.howToUse(false, null, 42)).endsWith("'stop 0' quits");
        assertThat(ReadyReporter.howToUse(false, "--login", 42)).endsWith("'stop 0' quits");
    }

    @Test
    void withoutAShellItSaysHowToStopTheProcess() {
        assertThat(ReadyReporter.howToUse(false, "--nointeractive", 4711))
                .isEqualTo("no shell (gosh.args=--nointeractive): stop it with Ctrl-C or kill 4711")
                .doesNotContain("stop 0");
        assertThat(ReadyReporter.howToUse(false, " --noshutdown  --nointeractive ", 4711)).endsWith("kill 4711");
    }

    @Test
    void aCheckRunStopsByItself() {
        assertThat(ReadyReporter.howToUse(true, "", 42)).doesNotContain("stop 0").contains("stops once");
    }
}
