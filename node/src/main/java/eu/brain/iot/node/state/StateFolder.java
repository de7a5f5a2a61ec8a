package eu.brain.iot.node.state;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.function.UnaryOperator;

/**
 * The node's state folder (the Bundle Installer's journal and whatever else a node keeps between runs): the framework
 * property {@value #STATE} ({@code ./fabric-node --state=DIR}); without it {@code $XDG_STATE_HOME/brain-iot/<name>-
 * <checkout>} ({@code $HOME/.local/state} when XDG_STATE_HOME is not set), {@code <name>} being {@value #NAME}
 * ({@value #DEFAULT_NAME} by default, {@code --name=NAME}) and {@code <checkout>} the first 8 hex digits of the
 * SHA-256 of the absolute path of {@value #ROOT} (the checkout the node runs from): two nodes of different names, or
 * of two checkouts, never share their state. The Bundle Installer (bis-impl) computes the same folder for its
 * journal; each side's test checks the formula against the same expected values. Stateless.
 */
public final class StateFolder {

    public static final String STATE = "fabric.node.state";
    public static final String NAME = "fabric.node.name";
    static final String ROOT = "fabric.node.root";
    static final String DEFAULT_NAME = "node";
    /** What a node's name may be: it names a folder. */
    static final java.util.regex.Pattern VALID_NAME = java.util.regex.Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");

    private StateFolder() {
    }

    /**
     * @param properties the framework's properties (system properties behind them)
     * @param environment the process's environment variables
     */
    public static Path of(UnaryOperator<String> properties, UnaryOperator<String> environment) {
        String explicit = properties.apply(STATE);
        if (explicit != null && !explicit.isBlank()) {
            return Path.of(explicit.trim()).toAbsolutePath().normalize();
        }
        String name = name(properties);
        String root = properties.apply(ROOT);
        Path checkout = Path.of(root == null || root.isBlank() ? "." : root).toAbsolutePath().normalize();
        String xdg = environment.apply("XDG_STATE_HOME");
        Path base;
        if (xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute()) {
            base = Path.of(xdg);
        } else {
            String home = environment.apply("HOME");
            base = Path.of(home == null || home.isBlank() ? System.getProperty("user.home") : home, ".local",
                    "state");
        }
        return base.resolve("brain-iot").resolve(name + "-" + shortHash(checkout.toString()));
    }

    /** @throws IllegalArgumentException for a name that cannot name a folder */
    public static String name(UnaryOperator<String> properties) {
        String name = properties.apply(NAME);
        name = name == null || name.isBlank() ? DEFAULT_NAME : name.trim();
        if (!VALID_NAME.matcher(name).matches()) {
            throw new IllegalArgumentException(NAME + "=" + name + " cannot name a node: use letters, digits, '.', '_'"
                    + " and '-' (at most 64, the first a letter or digit), e.g. --name=node2");
        }
        return name;
    }

    static String shortHash(String text) {
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(digest, 0, 4);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
