package eu.brain.iot.edge.rest;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.Set;
import java.util.function.Consumer;

/**
 * The API token that an exposed edge requires ({@code Authorization: Bearer <token>}): 32 random bytes, generated at
 * the first start that needs it and kept in the user's configuration directory (never in the work tree, where git
 * would see it), in a file only its owner may read (mode 600, folder 700).
 */
final class ApiToken {

    private final String token;
    final Path file;

    private ApiToken(String token, Path file) {
        this.token = token;
        this.file = file;
    }

    /**
     * {@code configured} if not blank, else {@code ${XDG_CONFIG_HOME:-~/.config}/brain-iot/<node>/api-token}.
     */
    static Path file(String configured, String nodeName) {
        if (configured != null && !configured.isBlank()) {
            return Path.of(configured);
        }
        String xdg = System.getenv("XDG_CONFIG_HOME");
        Path base = xdg == null || xdg.isBlank() ? Path.of(System.getProperty("user.home"), ".config") : Path.of(xdg);
        return base.resolve("brain-iot").resolve(nodeName == null || nodeName.isBlank() ? "node" : nodeName)
                .resolve("api-token");
    }

    /**
     * Reads the token, or creates it (and tells {@code console} the new token, the only time it is shown).
     *
     * @throws IllegalStateException saying what is wrong with the file and what to do
     */
    static ApiToken loadOrCreate(Path file, Consumer<String> console) {
        try {
            if (!Files.exists(file)) {
                create(file, console);
            }
            checkPrivate(file);
            String token = Files.readString(file, StandardCharsets.UTF_8).strip();
            if (token.length() < 32) {
                throw new IllegalStateException("the API token in " + file + " is shorter than 32 characters: "
                        + "delete the file and restart the node to generate a new one");
            }
            return new ApiToken(token, file);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read or create the API token file " + file + " (" + e
                    + "): make its folder writable by this user, or set api.token.file (PID " + RestConfig.PID + ")");
        }
    }

    private static void create(Path file, Consumer<String> console) throws IOException {
        byte[] random = new byte[32];
        new SecureRandom().nextBytes(random);
        String token = Base64.getUrlEncoder().withoutPadding().encodeToString(random);
        Path dir = file.toAbsolutePath().getParent();
        boolean posix = dir.getFileSystem().supportedFileAttributeViews().contains("posix");
        if (posix) {
            Files.createDirectories(dir, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
        } else {
            Files.createDirectories(dir);
        }
        try {
            if (posix) {
                Files.createFile(file, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
            } else {
                Files.createFile(file);
            }
        } catch (FileAlreadyExistsException e) {
            return; // another start made it meanwhile: use that one
        }
        Files.writeString(file, token + "\n", StandardCharsets.UTF_8);
        console.accept(token);
    }

    /** A token others can read is no secret: refuse it rather than serve with it. */
    private static void checkPrivate(Path file) throws IOException {
        if (!file.getFileSystem().supportedFileAttributeViews().contains("posix")) {
            return;
        }
        Set<PosixFilePermission> p = Files.getPosixFilePermissions(file);
        if (p.contains(PosixFilePermission.GROUP_READ) || p.contains(PosixFilePermission.OTHERS_READ)) {
            throw new IllegalStateException("the API token file " + file + " is readable by other users ("
                    + PosixFilePermissions.toString(p) + "): chmod 600 " + file + ", and as it may have leaked, "
                    + "delete it and restart the node for a new token");
        }
    }

    /** Compares in constant time, so that timing does not tell how much of a guess was right. */
    boolean matches(String candidate) {
        return candidate != null && MessageDigest.isEqual(token.getBytes(StandardCharsets.UTF_8),
                candidate.strip().getBytes(StandardCharsets.UTF_8));
    }
}
