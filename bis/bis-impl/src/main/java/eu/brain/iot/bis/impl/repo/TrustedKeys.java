package eu.brain.iot.bis.impl.repo;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.PublicKey;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

import eu.brain.iot.bis.sign.IndexSigning;

/**
 * The public keys an index must be signed with (any one of them). Empty: signatures are not checked. Immutable.
 *
 * @param sources where each key came from (a file name, or "inline"), in the order of {@link #keys}
 */
public record TrustedKeys(List<PublicKey> keys, List<String> sources) {

    /**
     * @param entries each a path to a PEM public key file, or the PEM / base64 text of the key itself
     * @throws IllegalArgumentException naming the entry that is neither
     */
    public static TrustedKeys of(String[] entries) {
        List<PublicKey> keys = new ArrayList<>();
        List<String> sources = new ArrayList<>();
        for (String entry : entries) {
            if (entry == null || entry.isBlank()) {
                continue;
            }
            String text = entry.trim();
            String source = "inline key";
            if (!text.startsWith("-----") && (text.contains("/") || text.contains("\\") || text.endsWith(".pub"))
                    && Files.exists(Path.of(text))) {
                Path path = Path.of(text);
                try {
                    text = Files.readString(path, StandardCharsets.US_ASCII);
                    source = path.toString();
                } catch (IOException e) {
                    throw new IllegalArgumentException("trusted.keys: cannot read the public key file " + path + " ("
                            + e + "): give a readable PEM file, or the key's base64");
                }
            } else if (!text.startsWith("-----") && text.endsWith(".pub")) {
                throw new IllegalArgumentException("trusted.keys: the public key file " + text + " does not exist: "
                        + "build repository/ (it writes target/index-signing.pub) or give your own key's file");
            }
            try {
                keys.add(IndexSigning.readPublicKey(text));
                sources.add(source);
            } catch (GeneralSecurityException e) {
                String what = source.equals("inline key") ? "'" + abbreviate(entry.trim()) + "'" : source;
                throw new IllegalArgumentException("trusted.keys: " + what + " is neither an existing key file nor an"
                        + " Ed25519 public key (" + e.getMessage() + "): give the path of the .pub file that sign-index"
                        + " wrote, or its PEM text");
            }
        }
        return new TrustedKeys(List.copyOf(keys), List.copyOf(sources));
    }

    public boolean enabled() {
        return !keys.isEmpty();
    }

    /** @return the index of the key that verifies, or -1 */
    public int verify(byte[] data, String signature) {
        for (int i = 0; i < keys.size(); i++) {
            if (IndexSigning.verify(keys.get(i), data, signature)) {
                return i;
            }
        }
        return -1;
    }

    /** @return the keys for messages, e.g. "3f2a... (/path/index-signing.pub)" */
    public String describe() {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < keys.size(); i++) {
            names.add(IndexSigning.fingerprint(keys.get(i)) + " (" + sources.get(i) + ")");
        }
        return names.stream().collect(Collectors.joining(", "));
    }

    public String describe(int key) {
        return IndexSigning.fingerprint(keys.get(key)) + " (" + sources.get(key) + ")";
    }

    private static String abbreviate(String text) {
        return text.length() <= 40 ? text : text.substring(0, 37) + "...";
    }
}
