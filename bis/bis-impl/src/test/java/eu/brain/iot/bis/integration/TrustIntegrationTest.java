package eu.brain.iot.bis.integration;

import static eu.brain.iot.bis.integration.TestRepository.DOOR;
import static eu.brain.iot.bis.integration.TestRepository.DOOR_CLOSED;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT_UNLOAD;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Files;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileTime;
import java.security.KeyPair;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.sign.IndexSigning;

/** A tampered bundle is never installed; an index that no trusted key signed is refused. */
class TrustIntegrationTest extends BisTestBase {

    @Test
    void aBundleWhoseBytesDoNotMatchTheIndexIsNeverInstalled() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        // the door's jar changes after the index was made (one byte more at its end: still a valid zip)
        Files.write(repo.jar("behaviour-door"), new byte[] { 0 }, StandardOpenOption.APPEND);
        Set<String> before = frameworkBundles();

        InstallException e = failure(installer.install(byType(DOOR_CLOSED)));

        assertThat(e.problem()).isEqualTo(Problem.HASH_MISMATCH);
        assertThat(e.getMessage()).contains(DOOR, "behaviour-door", "SHA-256", "the index says", "Nothing was installed");
        assertThat(frameworkBundles()).isEqualTo(before);
        assertThat(bundle(DOOR)).isNull();
        assertThat(installer.installed()).isEmpty();
    }

    @Test
    void anUnsignedIndexIsRefusedWhenAKeyIsConfigured() throws Exception {
        Files.delete(repo.dir.resolve("index.xml.sig"));
        BundleInstaller installer = configure(settings());

        await().atMost(DEADLINE).until(() -> command("repos").contains("REFUSED"));
        assertThat(command("repos")).contains("has no signature file", "index.xml.sig", "trusted keys",
                "sign-index");
        assertThat(value(installer.find(List.of(DOOR_CLOSED)))).isEmpty();
        assertThat(failure(installer.install(byType(DOOR_CLOSED))).problem()).isEqualTo(Problem.NOT_FOUND);
    }

    @Test
    void aWronglySignedIndexIsRefusedAndThePreviousOneStaysInUse() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        assertThat(command("repos")).contains("signature: valid");

        // a new index without the door, signed by a key nobody trusts
        repo.drop(DOOR::equals);
        KeyPair stranger = IndexSigning.generateKeyPair();
        repo.sign(stranger);
        Files.setLastModifiedTime(repo.index, FileTime.fromMillis(System.currentTimeMillis() + 5_000));

        await().atMost(DEADLINE).until(() -> command("repos").contains("REFUSED"));
        assertThat(command("repos")).contains("no trusted key verifies", "The index read before stays in use");
        assertThat(value(installer.find(List.of(DOOR_CLOSED)))).extracting(c -> c.symbolicName)
                .as("the previous index is still in use").containsExactly(DOOR);

        // signed with the trusted key, the new index is taken
        repo.sign(keys);
        Files.setLastModifiedTime(repo.index, FileTime.fromMillis(System.currentTimeMillis() + 10_000));
        await().atMost(DEADLINE).until(() -> value(installer.find(List.of(DOOR_CLOSED))).isEmpty());
        assertThat(value(installer.find(List.of(ROBOT_UNLOAD)))).extracting(c -> c.symbolicName)
                .containsExactly(ROBOT);
        assertThat(command("repos")).contains("signature: valid");
    }

    @Test
    void aTrustedKeyThatIsNoKeyStopsTheInstallerInsteadOfTurningChecksOff() throws Exception {
        var settings = settings();
        settings.put("trusted.keys", new String[] { "not-a-key" });

        configureOnly(settings);

        await().atMost(DEADLINE).until(() -> logMessages().stream().anyMatch(m -> m.contains("NOT started")));
        assertThat(logMessages()).filteredOn(m -> m.contains("NOT started")).first().asString()
                .contains("trusted.keys", "'not-a-key'", "neither an existing key file nor an Ed25519 public key");
        assertThat(context.getServiceReference(BundleInstaller.class)).isNull();
    }
}
