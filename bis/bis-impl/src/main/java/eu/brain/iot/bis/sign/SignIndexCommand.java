package eu.brain.iot.bis.sign;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.GeneralSecurityException;
import java.security.KeyPair;
import java.security.PrivateKey;
import java.security.PublicKey;
import java.util.ArrayList;
import java.util.List;

/**
 * The index signing command: {@code sign-index} signs index files with an Ed25519 private key (writing
 * {@code INDEX.sig} beside each), {@code verify-index} checks them against a public key, {@code generate-key} makes a
 * key pair. The build runs {@code sign-index --generate-if-missing} on the project's index (repository/pom.xml);
 * a user signs their own index with their own key the same way:
 *
 * <pre>
 * java -cp bis-impl.jar eu.brain.iot.bis.sign.SignIndexCommand sign-index --key my.key index.xml index.xml.gz
 * </pre>
 *
 * Exit code 0 on success, 1 on a failed verification, 2 on bad usage or an unreadable file; messages, never stack
 * traces. Single-threaded.
 */
public final class SignIndexCommand {

    private static final String USAGE = String.join("\n",
            "usage: sign-index --key PRIVATE.pem [--public PUBLIC.pem] [--generate-if-missing] INDEX...",
            "       verify-index --public PUBLIC.pem INDEX...",
            "       generate-key --key PRIVATE.pem --public PUBLIC.pem",
            "sign-index writes INDEX.sig (base64 of the Ed25519 signature of INDEX's bytes) beside each INDEX;",
            "with --generate-if-missing a missing key pair is generated first (the private key readable by you only).");

    private final PrintStream out;
    private final PrintStream err;

    SignIndexCommand(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
    }

    public static void main(String[] args) {
        int code = new SignIndexCommand(System.out, System.err).run(args);
        if (code != 0) {
            System.exit(code);
        }
    }

    /** @return the exit code */
    public int run(String... args) {
        if (args.length == 0) {
            err.println(USAGE);
            return 2;
        }
        Path key = null;
        Path publicKey = null;
        boolean generate = false;
        List<Path> indexes = new ArrayList<>();
        for (int i = 1; i < args.length; i++) {
            switch (args[i]) {
            case "--key" -> key = i + 1 < args.length ? Path.of(args[++i]) : null;
            case "--public" -> publicKey = i + 1 < args.length ? Path.of(args[++i]) : null;
            case "--generate-if-missing" -> generate = true;
            default -> {
                if (args[i].startsWith("--")) {
                    err.println("unknown option " + args[i] + "\n" + USAGE);
                    return 2;
                }
                indexes.add(Path.of(args[i]));
            }
            }
        }
        try {
            return switch (args[0]) {
            case "sign-index" -> sign(key, publicKey, generate, indexes);
            case "verify-index" -> verify(publicKey, indexes);
            case "generate-key" -> generate(key, publicKey);
            default -> usage("unknown command " + args[0]);
            };
        } catch (NoSuchFileException e) {
            err.println("no such file: " + e.getFile());
            return 2;
        } catch (IOException e) {
            err.println("cannot read or write a file: " + e);
            return 2;
        } catch (GeneralSecurityException e) {
            err.println("bad key: " + e.getMessage()
                    + " (expected an Ed25519 key in PEM, e.g. from generate-key or openssl genpkey -algorithm ed25519)");
            return 2;
        }
    }

    private int sign(Path key, Path publicKey, boolean generate, List<Path> indexes)
            throws IOException, GeneralSecurityException {
        if (key == null || indexes.isEmpty()) {
            return usage("sign-index needs --key and at least one INDEX");
        }
        if (generate && !Files.exists(key)) {
            if (publicKey == null) {
                return usage("--generate-if-missing needs --public, where the public key is written");
            }
            generate(key, publicKey);
        }
        PrivateKey privateKey = IndexSigning.readPrivateKey(Files.readString(key, StandardCharsets.US_ASCII));
        for (Path index : indexes) {
            Path signature = index.resolveSibling(index.getFileName() + IndexSigning.SUFFIX);
            Files.writeString(signature, IndexSigning.sign(privateKey, Files.readAllBytes(index)),
                    StandardCharsets.US_ASCII);
            out.println("signed " + index + " -> " + signature);
        }
        return 0;
    }

    private int verify(Path publicKey, List<Path> indexes) throws IOException, GeneralSecurityException {
        if (publicKey == null || indexes.isEmpty()) {
            return usage("verify-index needs --public and at least one INDEX");
        }
        PublicKey key = IndexSigning.readPublicKey(Files.readString(publicKey, StandardCharsets.US_ASCII));
        int code = 0;
        for (Path index : indexes) {
            Path signature = index.resolveSibling(index.getFileName() + IndexSigning.SUFFIX);
            if (!Files.exists(signature)) {
                err.println(index + ": no signature file " + signature + " (sign it with sign-index)");
                code = 1;
            } else if (IndexSigning.verify(key, Files.readAllBytes(index),
                    Files.readString(signature, StandardCharsets.US_ASCII))) {
                out.println(index + ": signature valid (key " + IndexSigning.fingerprint(key) + ")");
            } else {
                err.println(index + ": signature INVALID for key " + IndexSigning.fingerprint(key)
                        + " (the index changed after signing, or another key signed it)");
                code = 1;
            }
        }
        return code;
    }

    private int generate(Path key, Path publicKey) throws IOException, GeneralSecurityException {
        if (key == null || publicKey == null) {
            return usage("generate-key needs --key and --public");
        }
        KeyPair pair = IndexSigning.generateKeyPair();
        Path parent = key.toAbsolutePath().getParent();
        Files.createDirectories(parent);
        Files.deleteIfExists(key);
        if (FileSystems.getDefault().supportedFileAttributeViews().contains("posix")) {
            Files.createFile(key, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        }
        Files.writeString(key, IndexSigning.privateKeyPem(pair.getPrivate()), StandardCharsets.US_ASCII);
        Files.createDirectories(publicKey.toAbsolutePath().getParent());
        Files.writeString(publicKey, IndexSigning.publicKeyPem(pair.getPublic()), StandardCharsets.US_ASCII);
        out.println("generated key " + IndexSigning.fingerprint(pair.getPublic()) + ": private " + key + ", public "
                + publicKey);
        return 0;
    }

    private int usage(String problem) {
        err.println(problem + "\n" + USAGE);
        return 2;
    }
}
