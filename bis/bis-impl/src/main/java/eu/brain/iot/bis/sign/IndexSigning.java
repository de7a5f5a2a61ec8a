package eu.brain.iot.bis.sign;

import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.KeyFactory;
import java.security.KeyPair;
import java.security.KeyPairGenerator;
import java.security.MessageDigest;
import java.security.PrivateKey;
import java.security.PublicKey;
import java.security.Signature;
import java.security.spec.PKCS8EncodedKeySpec;
import java.security.spec.X509EncodedKeySpec;
import java.util.Base64;
import java.util.HexFormat;

/**
 * Detached Ed25519 signatures of repository indexes, with the JDK's own {@code Signature}: an index at {@code U} is
 * signed by the file {@code U.sig}, which holds the base64 of the 64-byte signature of the index's exact bytes (the
 * gzipped index has its own {@code .sig}). Keys are PEM text: {@code PUBLIC KEY} (X.509 SubjectPublicKeyInfo) and
 * {@code PRIVATE KEY} (PKCS#8), as {@code openssl genpkey -algorithm ed25519} writes them. Stateless; thread-safe.
 */
public final class IndexSigning {

    public static final String ALGORITHM = "Ed25519";
    /** What a signature file's name adds to its index's name. */
    public static final String SUFFIX = ".sig";

    private IndexSigning() {
    }

    public static KeyPair generateKeyPair() throws GeneralSecurityException {
        return KeyPairGenerator.getInstance(ALGORITHM).generateKeyPair();
    }

    public static String publicKeyPem(PublicKey key) {
        return pem("PUBLIC KEY", key.getEncoded());
    }

    public static String privateKeyPem(PrivateKey key) {
        return pem("PRIVATE KEY", key.getEncoded());
    }

    /** @param text PEM, or the bare base64 of the X.509 encoding */
    public static PublicKey readPublicKey(String text) throws GeneralSecurityException {
        return KeyFactory.getInstance(ALGORITHM).generatePublic(new X509EncodedKeySpec(unarmour(text)));
    }

    /** @param text PEM, or the bare base64 of the PKCS#8 encoding */
    public static PrivateKey readPrivateKey(String text) throws GeneralSecurityException {
        return KeyFactory.getInstance(ALGORITHM).generatePrivate(new PKCS8EncodedKeySpec(unarmour(text)));
    }

    /** @return the text of a signature file for {@code data} */
    public static String sign(PrivateKey key, byte[] data) throws GeneralSecurityException {
        Signature signature = Signature.getInstance(ALGORITHM);
        signature.initSign(key);
        signature.update(data);
        return Base64.getEncoder().encodeToString(signature.sign()) + "\n";
    }

    /** @return whether {@code signatureText} (a signature file's content) is {@code key}'s signature of {@code data} */
    public static boolean verify(PublicKey key, byte[] data, String signatureText) {
        try {
            Signature signature = Signature.getInstance(ALGORITHM);
            signature.initVerify(key);
            signature.update(data);
            return signature.verify(Base64.getMimeDecoder().decode(signatureText.trim()));
        } catch (GeneralSecurityException | IllegalArgumentException e) {
            return false; // a malformed signature file is no valid signature
        }
    }

    /** @return a short name for a key in messages: the first 16 hex digits of the SHA-256 of its encoding */
    public static String fingerprint(PublicKey key) {
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(key.getEncoded());
            return HexFormat.of().formatHex(digest, 0, 8);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("SHA-256 is part of every JDK", e);
        }
    }

    private static String pem(String type, byte[] der) {
        String body = Base64.getMimeEncoder(64, "\n".getBytes(StandardCharsets.US_ASCII)).encodeToString(der);
        return "-----BEGIN " + type + "-----\n" + body + "\n-----END " + type + "-----\n";
    }

    private static byte[] unarmour(String text) throws GeneralSecurityException {
        StringBuilder base64 = new StringBuilder();
        for (String line : text.split("\\R")) {
            if (!line.startsWith("-----")) {
                base64.append(line.trim());
            }
        }
        try {
            return Base64.getDecoder().decode(base64.toString());
        } catch (IllegalArgumentException e) {
            throw new GeneralSecurityException("not a PEM key nor base64: " + e.getMessage(), e);
        }
    }
}
