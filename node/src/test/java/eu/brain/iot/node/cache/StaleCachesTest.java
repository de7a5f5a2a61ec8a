package eu.brain.iot.node.cache;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Whose a cache's marker says it is: a live process (this test's JVM) or one that has ended. */
class StaleCachesTest {

    @Test
    void aMarkerOfThisProcessIsAlive() {
        assertThat(StaleCaches.alive(StaleCaches.marker(ProcessHandle.current()))).isTrue();
    }

    @Test
    void aMarkerOfAnEndedProcessIsNot() throws Exception {
        Process ended = new ProcessBuilder("true").start();
        String marker = StaleCaches.marker(ended.toHandle());
        ended.waitFor();
        assertThat(StaleCaches.alive(marker)).isFalse();
    }

    @Test
    void aPidNowUsedByAProcessStartedAtAnotherTimeIsNotTheOwner() {
        long pid = ProcessHandle.current().pid();
        assertThat(StaleCaches.alive(pid + " 12345")).isFalse();
        assertThat(StaleCaches.alive(pid + " 0")).as("start unknown: the pid decides").isTrue();
    }

    @Test
    void anUnreadableMarkerCountsAsAlive() {
        assertThat(StaleCaches.alive("not a pid")).isTrue();
    }
}
