package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.Base64;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * The fabric's signing key: HMAC-SHA256 with one secret shared by every node of a fabric. A shared key rather than a
 * key pair per node: one file to hand to every node, signing and checking cost about a microsecond per message (an
 * Ed25519 check costs ~100 times more, and the fabric signs every batch and every acknowledgement), and every member
 * is trusted alike anyway (any member may publish any event). The source node is inside the signed bytes.
 * <p>
 * The file holds the key in Base64 on one line (32 random bytes); it is created with owner-only permissions where
 * the file system has them. Thread-safe: every thread gets its own {@link Mac}.
 */
public final class FabricKey {

    static final String ALGORITHM = "HmacSHA256";
    static final int KEY_BYTES = 32;

    private final SecretKeySpec key;
    private final ThreadLocal<Mac> macs;

    private FabricKey(byte[] secret) {
        this.key = new SecretKeySpec(secret, ALGORITHM);
        this.macs = ThreadLocal.withInitial(this::newMac);
    }

    /**
     * Read a key file.
     *
     * @throws IOException with a message saying what is wrong and what to do
     */
    public static FabricKey read(Path file) throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new IOException("the fabric key file " + file + " does not exist: create it once with the Gogo "
                    + "command 'fabric:keygen " + file + "' (or java -cp <federation jar> "
                    + KeyGen.class.getName() + " " + file + ") and copy it to every node of the fabric");
        }
        byte[] secret;
        try {
            secret = Base64.getDecoder().decode(Files.readString(file, StandardCharsets.US_ASCII).trim());
        } catch (IllegalArgumentException | CharacterCodingException e) {
            throw new IOException("the fabric key file " + file + " is not a key: a key file holds one line of Base64, "
                    + "as fabric:keygen writes it (here: " + e.getMessage() + "); copy the fabric's key file here, or "
                    + "make a new one with fabric:keygen for every node");
        }
        if (secret.length < KEY_BYTES) {
            throw new IOException("the fabric key in " + file + " is too short (" + secret.length + " bytes, at least "
                    + KEY_BYTES + "); make a new one with fabric:keygen for every node");
        }
        return new FabricKey(secret);
    }

    /** Create a new random key file; refuses to overwrite one. */
    public static void generate(Path file) throws IOException {
        byte[] secret = new byte[KEY_BYTES];
        new SecureRandom().nextBytes(secret);
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        try {
            Files.createFile(file, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        } catch (UnsupportedOperationException e) {
            Files.createFile(file);
        } catch (FileAlreadyExistsException e) {
            throw new IOException("the key file " + file + " exists already; it is not overwritten (every node of "
                    + "the fabric shares it): remove it first to make a new key");
        }
        Files.writeString(file, Base64.getEncoder().encodeToString(secret) + "\n", StandardCharsets.US_ASCII,
                StandardOpenOption.TRUNCATE_EXISTING);
    }

    /** A key from raw bytes (tests). */
    static FabricKey of(byte[] secret) {
        return new FabricKey(secret.clone());
    }

    /** @return the Base64 HMAC-SHA256 of the topic and the payload */
    String sign(String topic, byte[] payload) {
        return Base64.getEncoder().encodeToString(mac(topic, payload));
    }

    /** @return whether {@code signature} is the HMAC-SHA256 of the topic and the payload (constant time) */
    boolean verify(String topic, byte[] payload, String signature) {
        byte[] given;
        try {
            given = Base64.getDecoder().decode(signature);
        } catch (IllegalArgumentException e) {
            return false;
        }
        return MessageDigest.isEqual(mac(topic, payload), given);
    }

    private byte[] mac(String topic, byte[] payload) {
        Mac mac = macs.get();
        mac.update(topic.getBytes(StandardCharsets.UTF_8));
        mac.update((byte) 0);
        return mac.doFinal(payload);
    }

    private Mac newMac() {
        try {
            Mac mac = Mac.getInstance(ALGORITHM);
            mac.init(key);
            return mac;
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("this Java runtime has no " + ALGORITHM, e);
        }
    }
}
