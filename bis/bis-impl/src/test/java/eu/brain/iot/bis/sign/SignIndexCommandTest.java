package eu.brain.iot.bis.sign;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.KeyPair;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SignIndexCommandTest {

    @TempDir
    Path dir;
    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private final SignIndexCommand command = new SignIndexCommand(new PrintStream(out, true), new PrintStream(err, true));

    @Test
    void signsWithAGeneratedKeyAndVerifies() throws Exception {
        Path index = Files.writeString(dir.resolve("index.xml"), "<repository/>");
        Path key = dir.resolve("keys/index-signing.key");
        Path pub = dir.resolve("keys/index-signing.pub");

        int code = command.run("sign-index", "--generate-if-missing", "--key", key.toString(), "--public",
                pub.toString(), index.toString());

        assertThat(code).as(err.toString()).isZero();
        assertThat(Files.readString(pub)).startsWith("-----BEGIN PUBLIC KEY-----");
        assertThat(Files.getPosixFilePermissions(key)).isEqualTo(PosixFilePermissions.fromString("rw-------"));
        assertThat(command.run("verify-index", "--public", pub.toString(), index.toString())).isZero();
        assertThat(out.toString()).contains("signature valid");

        // the same key is used again, not replaced
        String keyText = Files.readString(key);
        assertThat(command.run("sign-index", "--generate-if-missing", "--key", key.toString(), "--public",
                pub.toString(), index.toString())).isZero();
        assertThat(Files.readString(key)).isEqualTo(keyText);
    }

    @Test
    void aChangedIndexOrAnotherKeyFailsVerification() throws Exception {
        Path index = Files.writeString(dir.resolve("index.xml"), "<repository/>");
        KeyPair keys = IndexSigning.generateKeyPair();
        Path key = Files.writeString(dir.resolve("k.key"), IndexSigning.privateKeyPem(keys.getPrivate()));
        Path pub = Files.writeString(dir.resolve("k.pub"), IndexSigning.publicKeyPem(keys.getPublic()));
        Path other = Files.writeString(dir.resolve("o.pub"),
                IndexSigning.publicKeyPem(IndexSigning.generateKeyPair().getPublic()));
        assertThat(command.run("sign-index", "--key", key.toString(), index.toString())).isZero();

        assertThat(command.run("verify-index", "--public", other.toString(), index.toString())).isEqualTo(1);
        assertThat(err.toString()).contains("signature INVALID");

        Files.writeString(index, "<repository name='changed'/>");
        assertThat(command.run("verify-index", "--public", pub.toString(), index.toString())).isEqualTo(1);
    }

    @Test
    void badUsageAndBadKeysAreExplainedWithoutAStackTrace() throws Exception {
        assertThat(command.run("sign-index", "index.xml")).isEqualTo(2);
        assertThat(err.toString()).contains("sign-index needs --key", "usage:");

        Path notAKey = Files.writeString(dir.resolve("bad.key"), "hello");
        Path index = Files.writeString(dir.resolve("index.xml"), "<repository/>");
        assertThat(command.run("sign-index", "--key", notAKey.toString(), index.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("bad key", "Ed25519").doesNotContain("Exception\n\tat");

        assertThat(command.run("sign-index", "--key", dir.resolve("missing.key").toString(), index.toString()))
                .isEqualTo(2);
        assertThat(err.toString()).contains("no such file");
    }

    @Test
    void verifiesAnOpensslStyleKeyAndRejectsAMalformedSignature() throws Exception {
        KeyPair keys = IndexSigning.generateKeyPair();
        byte[] data = "index".getBytes(StandardCharsets.UTF_8);
        String signature = IndexSigning.sign(keys.getPrivate(), data);
        // bare base64 (no PEM armour) is accepted too
        String bare = IndexSigning.publicKeyPem(keys.getPublic()).lines().filter(l -> !l.startsWith("-----"))
                .reduce("", String::concat);
        assertThat(IndexSigning.verify(IndexSigning.readPublicKey(bare), data, signature)).isTrue();
        assertThat(IndexSigning.verify(keys.getPublic(), data, "not base64 !")).isFalse();
        assertThat(IndexSigning.fingerprint(keys.getPublic())).hasSize(16);
    }
}
