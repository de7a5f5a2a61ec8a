package eu.brain.iot.bis.signtool;

import static org.assertj.core.api.Assertions.assertThat;

import eu.brain.iot.bis.sign.IndexSigning;
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
        assertThat(err.toString()).contains("sign-index needs --key", "Usage:");

        Path notAKey = Files.writeString(dir.resolve("bad.key"), "hello");
        Path index = Files.writeString(dir.resolve("index.xml"), "<repository/>");
        assertThat(command.run("sign-index", "--key", notAKey.toString(), index.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("bad key", "Ed25519").doesNotContain("Exception\n\tat");

        assertThat(command.run("sign-index", "--key", dir.resolve("missing.key").toString(), index.toString()))
                .isEqualTo(2);
        assertThat(err.toString()).contains("no such file");
    }

    @Test
    void badCommandLinesAreOneLineThenTheUsageAndExitCode2() throws Exception {
        assertThat(command.run()).isEqualTo(2);
        assertThat(err.toString()).startsWith("Usage: sign-index --key PRIVATE.pem");
        err.reset();
        assertThat(command.run("sign-index", "--colour", "index.xml")).isEqualTo(2);
        assertThat(err.toString()).startsWith("unknown option --colour\nUsage: sign-index --key PRIVATE.pem");
        err.reset();
        assertThat(command.run("sign-everything")).isEqualTo(2);
        assertThat(err.toString()).startsWith("unknown command sign-everything\nUsage: ");
        err.reset();
        assertThat(command.run("verify-index", "--public")).isEqualTo(2);
        assertThat(err.toString()).startsWith("--public needs a value\nUsage: ");
        err.reset();
        assertThat(command.run("verify-index", "index.xml")).isEqualTo(2);
        assertThat(err.toString()).startsWith("verify-index needs --public and at least one INDEX\nUsage: ");
        err.reset();
        assertThat(command.run("generate-key", "--key", dir.resolve("k").toString())).isEqualTo(2);
        assertThat(err.toString()).startsWith("generate-key needs --key and --public\nUsage: ");
        err.reset();
        assertThat(command.run("sign-index", "--generate-if-missing", "--key", dir.resolve("k").toString(), "i.xml"))
                .isEqualTo(2);
        assertThat(err.toString()).startsWith("--generate-if-missing needs --public, where the public key is written");
        assertThat(out.toString()).isEmpty();
    }

    @Test
    void anIndexWithoutSignatureFailsVerificationWithExitCode1() throws Exception {
        Path index = Files.writeString(dir.resolve("index.xml"), "<repository/>");
        Path pub = dir.resolve("k.pub");
        assertThat(command.run("generate-key", "--key", dir.resolve("k.key").toString(), "--public", pub.toString()))
                .isZero();
        assertThat(out.toString()).startsWith("generated key ");
        assertThat(command.run("verify-index", "--public", pub.toString(), index.toString())).isEqualTo(1);
        assertThat(err.toString()).isEqualTo(index + ": no signature file " + index + ".sig (sign it with sign-index)\n");
    }
}
