package eu.brain.iot.bis.integration;

import static eu.brain.iot.bis.integration.TestRepository.DOOR;
import static eu.brain.iot.bis.integration.TestRepository.DOOR_CLOSED;
import static eu.brain.iot.bis.integration.TestRepository.EVENTS;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.sign.IndexSigning;

/**
 * What an operator meets around the journal and the configuration: several repositories in one comma-separated value
 * (as a .cfg file gives them), a name nothing is installed under, a journal that cannot be written (a full disk:
 * Linux's {@code /dev/full} answers every write with ENOSPC), a journal entry whose index is refused.
 */
class JournalAndNamesIntegrationTest extends BisTestBase {

    @Test
    void aCommaSeparatedRepositoriesValueIsSeveralRepositories() throws Exception {
        TestRepository second = TestRepository.copy(context.getProperty("bis.test.repository"), temp.resolve("repo2"));
        second.sign(keys);
        var settings = settings();
        String first = repo.index.toUri().toString();
        String other = second.index.toUri().toString();
        settings.put("repositories", first + ", " + other); // one string, as Config Admin makes of a .cfg line

        configure(settings);

        await().atMost(DEADLINE).until(() -> command("repos").split("signature: valid", -1).length == 3);
        assertThat(command("repos")).containsPattern("(?m)^" + first + "$").containsPattern("(?m)^" + other + "$");
    }

    @Test
    void uninstallingANameNothingIsInstalledUnderSaysSoAndChangesNothing() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        value(installer.install(byType(DOOR_CLOSED)));

        String answer = command("uninstall", "no.such.Behaviour");

        assertThat(answer).contains("nothing is installed under the name no.such.Behaviour (installed: " + DOOR + ")")
                .contains("nothing done").doesNotContain("uninstalled");
        assertThat(command("list")).doesNotContain("removed or stopped by an operator");
        assertThat(installer.installed()).extracting(b -> b.symbolicName).containsExactly(DOOR);
    }

    @Test
    void aJournalThatCannotBeWrittenFailsTheUninstallAndLeavesEverythingAsItWas() throws Exception {
        Assumptions.assumeTrue(Files.exists(Path.of("/dev/full")), "no /dev/full here to play a full disk");
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        value(installer.install(byType(DOOR_CLOSED)));
        Path temporary = journal.resolve("journal.tsv.tmp");
        Files.createSymbolicLink(temporary, Path.of("/dev/full")); // the journal's next write hits a full disk

        String answer = command("uninstall", DOOR);

        assertThat(answer).contains("failed (JOURNAL_FAILED)").contains("No space left on device")
                .contains(DOOR + " was NOT uninstalled");
        assertThat(Files.exists(temporary, LinkOption.NOFOLLOW_LINKS)).as("no temporary file left").isFalse();
        assertThat(installer.installed()).extracting(b -> b.symbolicName).containsExactly(DOOR);
        assertThat(command("list")).doesNotContain("removed or stopped by an operator");
        assertThat(bundle(DOOR).getState()).isEqualTo(Bundle.ACTIVE);
        assertThat(Files.readString(journal.resolve("journal.tsv"))).contains(DOOR);

        // with room again, the same command works
        assertThat(command("uninstall", DOOR)).contains("uninstalled " + DOOR);
        assertThat(bundle(DOOR)).isNull();
    }

    @Test
    void aJournalEntryWhoseIndexIsRefusedDoesNotHoldTheInstallerBack() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        value(installer.install(byType(DOOR_CLOSED)));
        unconfigure();
        bundle(DOOR).uninstall();
        bundle(EVENTS).uninstall();
        bundle(TestRepository.WAREHOUSE).uninstall();
        var settings = settings(); // the index is signed with a key that is no longer trusted: it is refused
        settings.put("trusted.keys", new String[] { repo.publicKey(IndexSigning.generateKeyPair(), "other")
                .toString() });
        settings.put("restore.timeout.ms", 30_000L);

        long started = System.nanoTime();
        configure(settings);

        assertThat(Duration.ofNanos(System.nanoTime() - started)).isLessThan(Duration.ofSeconds(10));
        assertThat(command("list")).contains("journal, not back yet: " + DOOR).contains("no index in use offers");
        assertThat(logMessages()).anyMatch(m -> m.contains("without 1 of the journal's behaviours"));
        assertThat(command("repos")).contains("REFUSED");
    }
}
