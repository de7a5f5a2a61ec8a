package eu.brain.iot.bis.impl;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.function.UnaryOperator;

/**
 * The node's state folder, where the installer keeps its journal unless {@code journal.dir} says otherwise: the
 * framework property {@value #STATE}, which {@code ./fabric-node} always sets (from {@code --state=DIR}, or as below);
 * without it {@code $XDG_STATE_HOME/brain-iot/<name>-<checkout>} ({@code $HOME/.local/state} when XDG_STATE_HOME is
 * not set), {@code <name>} being {@value #NAME} ({@value #DEFAULT_NAME} by default) and {@code <checkout>} the first 8
 * hex digits of the SHA-256 of the absolute path of {@value #ROOT} (the checkout the node runs from): two nodes, or
 * two checkouts, never share a journal by default. The node bundle computes the same folder (and locks it); the
 * formula is tested against the same expected values on both sides. Stateless.
 */
final class StateFolder {

    static final String STATE = "fabric.node.state";
    static final String NAME = "fabric.node.name";
    static final String ROOT = "fabric.node.root";
    static final String DEFAULT_NAME = "node";

    private StateFolder() {
    }

    /**
     * @param properties the framework's properties (system properties behind them)
     * @param environment the process's environment variables
     */
    static Path of(UnaryOperator<String> properties, UnaryOperator<String> environment) {
        String explicit = properties.apply(STATE);
        if (explicit != null && !explicit.isBlank()) {
            return Path.of(explicit.trim()).toAbsolutePath().normalize();
        }
        String name = properties.apply(NAME);
        name = name == null || name.isBlank() ? DEFAULT_NAME : name.trim();
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

    static String shortHash(String text) {
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(digest, 0, 4);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
