package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.List;

import org.junit.jupiter.api.Test;

/**
 * The install messages' device fields on the wire: a bid names the devices, an offer says which it owns, and both
 * stay compatible with nodes that do not know them (missing: none; unknown fields: ignored).
 */
class WireInstallTest {

    final Wire wire = new Wire();

    @Test
    void aBidNamesTheDevicesAndAnOfferWhichItOwns() throws Exception {
        Wire.Install bid = new Wire.Install(Wire.Install.BID, "a", "b", 1L, "q1", List.of("x.Moved"), null, 0, null,
                false, null, null, null, List.of("robot2"), null);
        assertThat(wire.readInstall(wire.install(bid)).devices()).containsExactly("robot2");
        Wire.Install offer = new Wire.Install(Wire.Install.OFFER, "b", "a", 1L, "q1", null,
                List.of(FakeInstaller.candidate("x", "x.Moved")), 3, null, false, null, null, null, null,
                List.of("robot2"));
        Wire.Install read = wire.readInstall(wire.install(offer));
        assertThat(read.owns()).containsExactly("robot2");
        assertThat(read.load()).isEqualTo(3);
    }

    @Test
    void anOfferFromANodeThatDoesNotSayOwnsNothing() throws Exception {
        String older = "{\"op\":\"offer\",\"from\":\"b\",\"to\":\"a\",\"sent\":1,\"id\":\"q1\",\"candidates\":[],"
                + "\"load\":2}";
        Wire.Install read = wire.readInstall(older.getBytes(StandardCharsets.UTF_8));
        assertThat(read.owns()).isNull();
        assertThat(new InstallChoice.Offer(read.from(), read.candidates(), read.load(), read.owns()).owns()).isEmpty();
        String newer = "{\"op\":\"bid\",\"from\":\"a\",\"to\":\"b\",\"sent\":1,\"id\":\"q1\",\"types\":[\"x\"],"
                + "\"devices\":[\"robot1\"],\"said\":\"more\"}";
        assertThat(wire.readInstall(newer.getBytes(StandardCharsets.UTF_8)).types()).containsExactly("x");
    }
}
