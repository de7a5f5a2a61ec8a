package eu.brain.iot.bis.sign;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.security.KeyPair;

import org.junit.jupiter.api.Test;

class IndexSigningTest {

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
