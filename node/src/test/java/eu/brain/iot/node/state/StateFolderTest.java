package eu.brain.iot.node.state;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.Map;

import org.junit.jupiter.api.Test;

/**
 * The node's state folder: the same formula, with the same expected values, as the Bundle Installer's
 * StateFolderTest (bis/bis-impl), so that the folder the node locks is the one the journal is in.
 */
class StateFolderTest {

    @Test
    void theDefaultFolderIsNamedAfterTheNodeAndItsCheckoutUnderXdgStateHome() {
        Path folder = StateFolder.of(Map.of("fabric.node.name", "alpha", "fabric.node.root", "/work/x")::get,
                Map.of("XDG_STATE_HOME", "/xdg", "HOME", "/home/u")::get);
        assertThat(folder).isEqualTo(Path.of("/xdg/brain-iot/alpha-0c9ce2d9"));
    }

    @Test
    void withoutXdgStateHomeItIsUnderHomeAndTheNameDefaultsToNode() {
        Path folder = StateFolder.of(Map.of("fabric.node.root", "/srv/checkout")::get, Map.of("HOME", "/home/u")::get);
        assertThat(folder).isEqualTo(Path.of("/home/u/.local/state/brain-iot/node-dd7318cb"));
    }

    @Test
    void anExplicitStateFolderWins() {
        Path folder = StateFolder.of(Map.of("fabric.node.state", "/tmp/n2", "fabric.node.name", "alpha")::get,
                Map.of("XDG_STATE_HOME", "/xdg")::get);
        assertThat(folder).isEqualTo(Path.of("/tmp/n2"));
    }

    @Test
    void aNameThatCannotNameAFolderIsRefusedByName() {
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> StateFolder.name(Map.of("fabric.node.name",
                "../evil")::get)).hasMessageContaining("fabric.node.name=../evil cannot name a node");
    }
}
