package eu.brain.iot.bis.signtool;

import eu.brain.iot.bis.sign.IndexSigning;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
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
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.MissingParameterException;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * The index signing command: {@code sign-index} signs index files with an Ed25519 private key (writing
 * {@code INDEX.sig} beside each), {@code verify-index} checks them against a public key, {@code generate-key} makes a
 * key pair. The build runs {@code sign-index --generate-if-missing} on the project's index (repository/pom.xml);
 * a user signs their own index with their own key the same way:
 *
 * <pre>
 * java -jar bis/bis-sign/target/sign-index.jar sign-index --key my.key index.xml index.xml.gz
 * </pre>
 *
 * Exit code 0 on success, 1 on a failed verification, 2 on bad usage or an unreadable file; messages, never stack
 * traces. Single-threaded.
 */
@Command(name = "sign-index.jar", usageHelpWidth = 120, customSynopsis = {
    "sign-index --key PRIVATE.pem [--public PUBLIC.pem] [--generate-if-missing] INDEX...",
    "       verify-index --public PUBLIC.pem INDEX...",
    "       generate-key --key PRIVATE.pem --public PUBLIC.pem"},
        footer = {
            "sign-index writes INDEX.sig (base64 of the Ed25519 signature of INDEX's bytes) beside each INDEX;",
            "with --generate-if-missing a missing key pair is generated first (the private key readable by you only)."})
public final class SignIndexCommand implements Callable<Integer> {
    static final int OK = 0;
    static final int NOT_VERIFIED = 1;
    static final int BAD_USAGE = 2;

    private final PrintStream out;
    private final PrintStream err;
    private final CommandLine commandLine;

    SignIndexCommand(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
        this.commandLine = new CommandLine(this)
                .addSubcommand("sign-index", new Sign())
                .addSubcommand("verify-index", new Verify())
                .addSubcommand("generate-key", new GenerateKey());
        commandLine.setOut(new PrintWriter(out, true, StandardCharsets.UTF_8));
        commandLine.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
        commandLine.setParameterExceptionHandler((ex, args) -> usage(message(ex)));
    }

    public static void main(String[] args) {
        int code = new SignIndexCommand(System.out, System.err).run(args);
        if (code != OK) {
            System.exit(code);
        }
    }

    /** @return the exit code */
    public int run(String... args) {
        return commandLine.execute(args);
    }

    /** No command: the usage. */
    @Override
    public Integer call() {
        err.print(commandLine.getUsageMessage());
        err.flush();
        return BAD_USAGE;
    }

    private String message(ParameterException ex) {
        if (ex instanceof UnmatchedArgumentException u && !u.getUnmatched().isEmpty()) {
            String first = u.getUnmatched().get(0);
            return first.startsWith("-") || ex.getCommandLine() != commandLine ? "unknown option " + first
                    : "unknown command " + first;
        }
        if (ex instanceof MissingParameterException m && !m.getMissing().isEmpty()
                && m.getMissing().get(0) instanceof OptionSpec o) {
            return o.longestName() + " needs a value";
        }
        return ex.getMessage();
    }

    private int usage(String problem) {
        err.println(problem);
        err.print(commandLine.getUsageMessage());
        err.flush();
        return BAD_USAGE;
    }

    /** Runs a command's work; a file or key problem is one line and exit code 2. */
    private int guarded(Callable<Integer> work) throws Exception {
        try {
            return work.call();
        } catch (NoSuchFileException e) {
            err.println("no such file: " + e.getFile());
            return BAD_USAGE;
        } catch (IOException e) {
            err.println("cannot read or write a file: " + e);
            return BAD_USAGE;
        } catch (GeneralSecurityException e) {
            err.println("bad key: " + e.getMessage()
                    + " (expected an Ed25519 key in PEM, e.g. from generate-key or openssl genpkey -algorithm ed25519)");
            return BAD_USAGE;
        }
    }

    @Command(name = "sign-index", description = "sign each INDEX with the private key")
    final class Sign implements Callable<Integer> {
        @Option(names = "--key", paramLabel = "PRIVATE.pem")
        private Path key;
        @Option(names = "--public", paramLabel = "PUBLIC.pem")
        private Path publicKey;
        @Option(names = "--generate-if-missing", arity = "0")
        private boolean generate;
        @Parameters(paramLabel = "INDEX", arity = "0..*")
        private List<Path> indexes = new ArrayList<>();

        @Override
        public Integer call() throws Exception {
            if (key == null || indexes.isEmpty()) {
                return usage("sign-index needs --key and at least one INDEX");
            }
            if (generate && !Files.exists(key) && publicKey == null) {
                return usage("--generate-if-missing needs --public, where the public key is written");
            }
            return guarded(() -> {
                if (generate && !Files.exists(key)) {
                    generateKeyPair(key, publicKey);
                }
                PrivateKey privateKey = IndexSigning.readPrivateKey(Files.readString(key, StandardCharsets.US_ASCII));
                for (Path index : indexes) {
                    Path signature = index.resolveSibling(index.getFileName() + IndexSigning.SUFFIX);
                    Files.writeString(signature, IndexSigning.sign(privateKey, Files.readAllBytes(index)),
                            StandardCharsets.US_ASCII);
                    out.println("signed " + index + " -> " + signature);
                }
                return OK;
            });
        }
    }

    @Command(name = "verify-index", description = "check the signature of each INDEX against the public key")
    final class Verify implements Callable<Integer> {
        @Option(names = "--public", paramLabel = "PUBLIC.pem")
        private Path publicKey;
        @Parameters(paramLabel = "INDEX", arity = "0..*")
        private List<Path> indexes = new ArrayList<>();

        @Override
        public Integer call() throws Exception {
            if (publicKey == null || indexes.isEmpty()) {
                return usage("verify-index needs --public and at least one INDEX");
            }
            return guarded(() -> {
                PublicKey key = IndexSigning.readPublicKey(Files.readString(publicKey, StandardCharsets.US_ASCII));
                int code = OK;
                for (Path index : indexes) {
                    Path signature = index.resolveSibling(index.getFileName() + IndexSigning.SUFFIX);
                    if (!Files.exists(signature)) {
                        err.println(index + ": no signature file " + signature + " (sign it with sign-index)");
                        code = NOT_VERIFIED;
                    } else if (IndexSigning.verify(key, Files.readAllBytes(index),
                            Files.readString(signature, StandardCharsets.US_ASCII))) {
                        out.println(index + ": signature valid (key " + IndexSigning.fingerprint(key) + ")");
                    } else {
                        err.println(index + ": signature INVALID for key " + IndexSigning.fingerprint(key)
                                + " (the index changed after signing, or another key signed it)");
                        code = NOT_VERIFIED;
                    }
                }
                return code;
            });
        }
    }

    @Command(name = "generate-key", description = "make an Ed25519 key pair (the private key readable by you only)")
    final class GenerateKey implements Callable<Integer> {
        @Option(names = "--key", paramLabel = "PRIVATE.pem")
        private Path key;
        @Option(names = "--public", paramLabel = "PUBLIC.pem")
        private Path publicKey;

        @Override
        public Integer call() throws Exception {
            if (key == null || publicKey == null) {
                return usage("generate-key needs --key and --public");
            }
            return guarded(() -> {
                generateKeyPair(key, publicKey);
                return OK;
            });
        }
    }

    private void generateKeyPair(Path key, Path publicKey) throws IOException, GeneralSecurityException {
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
    }
}
