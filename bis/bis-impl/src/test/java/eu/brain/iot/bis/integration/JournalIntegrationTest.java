package eu.brain.iot.bis.integration;

import static eu.brain.iot.bis.integration.TestRepository.DOOR;
import static eu.brain.iot.bis.integration.TestRepository.DOOR_CLOSED;
import static eu.brain.iot.bis.integration.TestRepository.EVENTS;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Files;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileTime;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstalledBehaviour;

/**
 * The journal brings installed behaviours back after a restart. A node's restart wipes the framework's cache, so
 * its bundles are gone: the test stops the installer, uninstalls the behaviour's bundles as the wipe would, and
 * starts a new installer on the same journal directory.
 */
class JournalIntegrationTest extends BisTestBase {

    @Test
    void afterARestartTheJournalsBehavioursAreBackBeforeTheInstallerIsOffered() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        InstalledBehaviour door = value(installer.install(byType(DOOR_CLOSED)));
        assertThat(Files.readString(journal.resolve("journal.tsv"))).contains(DOOR, door.version);
        assertThat(Files.readString(journal.resolve("history.log"))).contains("installed\t" + DOOR);

        unconfigure();
        bundle(DOOR).uninstall();
        bundle(EVENTS).uninstall();
        bundle(TestRepository.WAREHOUSE).uninstall();
        assertThat(bundle(DOOR)).isNull();

        // the service appears only once the journal is restored: no waiting for the behaviour after it
        BundleInstaller restarted = configure(settings());
        assertThat(bundle(DOOR)).as(command("list")).isNotNull();
        assertThat(bundle(DOOR).getState()).isEqualTo(Bundle.ACTIVE);
        assertThat(busKnows(DOOR)).isTrue();
        assertThat(restarted.installed()).extracting(b -> b.symbolicName).containsExactly(DOOR);
        assertThat(restarted.installed().get(0).reason).isEqualTo("journal: test: event had no consumer");
        assertThat(restarted.installed().get(0).installedAt).isEqualTo(door.installedAt);

        // and again: the reason says "journal" once, however often the node restarts
        unconfigure();
        bundle(DOOR).uninstall();
        bundle(EVENTS).uninstall();
        bundle(TestRepository.WAREHOUSE).uninstall();
        BundleInstaller again = configure(settings());
        assertThat(again.installed()).singleElement().extracting(b -> b.reason)
                .isEqualTo("journal: test: event had no consumer");
        assertThat(Files.readString(journal.resolve("journal.tsv"))).doesNotContain("journal:%20journal:");
    }

    @Test
    void theJournalsBehaviourIsReVerifiedWhenInstalledAgain() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        value(installer.install(byType(DOOR_CLOSED)));
        unconfigure();
        bundle(DOOR).uninstall();
        bundle(EVENTS).uninstall();
        bundle(TestRepository.WAREHOUSE).uninstall();
        byte[] original = Files.readAllBytes(repo.jar("behaviour-door"));
        Files.write(repo.jar("behaviour-door"), new byte[] { 0 }, StandardOpenOption.APPEND); // tampered meanwhile

        BundleInstaller restarted = configure(settings());

        assertThat(bundle(DOOR)).as("a tampered bundle is not installed from the journal either").isNull();
        assertThat(restarted.installed()).isEmpty();
        assertThat(command("list")).contains("journal, not back yet: " + DOOR, "problem:", "SHA-256");
        assertThat(Files.readString(journal.resolve("journal.tsv"))).as("kept for the next start").contains(DOOR);

        // the repository is repaired: when the index is read anew, the journal's entry comes back
        Files.write(repo.jar("behaviour-door"), original);
        Files.setLastModifiedTime(repo.index, FileTime.fromMillis(System.currentTimeMillis() + 5_000));
        await().atMost(DEADLINE).until(() -> bundle(DOOR) != null && busKnows(DOOR));
        assertThat(restarted.installed()).extracting(b -> b.symbolicName).containsExactly(DOOR);
        assertThat(command("list")).doesNotContain("not back yet");
    }

    @Test
    void anInstallerRestartedWithoutANodeRestartTakesItsBundlesBack() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        InstalledBehaviour door = value(installer.install(byType(DOOR_CLOSED)));
        unconfigure();
        bundle(DOOR).stop();

        BundleInstaller restarted = configure(settings());

        assertThat(restarted.installed()).extracting(b -> b.bundleId).containsExactly(door.bundleId);
        assertThat(bundle(DOOR).getState()).isEqualTo(Bundle.ACTIVE);
        assertThat(bundleCount(DOOR)).isEqualTo(1);
    }
}
