package eu.brain.iot.edge.rest;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Which binds count as exposed, and the names the gate accepts. */
class RequestGateTest {

    @Test
    void onlyLoopbackBindsAreUnexposed() {
        assertThat(RequestGate.loopback("127.0.0.1")).isTrue();
        assertThat(RequestGate.loopback("::1")).isTrue();
        assertThat(RequestGate.loopback("localhost")).isTrue();
        assertThat(RequestGate.loopback("0.0.0.0")).isFalse();
        assertThat(RequestGate.loopback("::")).isFalse();
        assertThat(RequestGate.loopback("")).isFalse(); // every interface
        assertThat(RequestGate.loopback(null)).isFalse();
        assertThat(RequestGate.loopback("192.168.1.20")).isFalse();
        assertThat(RequestGate.loopback("no-such-host.invalid")).isFalse();
    }

    @Test
    void hostNamesWithThePort() {
        HostNames names = new HostNames("192.168.1.20", new String[] { "Edge.Example", "proxy.example:443" });
        assertThat(names.accepts("127.0.0.1:8181", 8181)).isTrue();
        assertThat(names.accepts("[::1]:8181", 8181)).isTrue();
        assertThat(names.accepts("192.168.1.20:8181", 8181)).isTrue();
        assertThat(names.accepts("edge.example:8181", 8181)).isTrue();
        assertThat(names.accepts("proxy.example:443", 8181)).isTrue();
        assertThat(names.accepts("proxy.example:8181", 8181)).isFalse();
        assertThat(names.accepts("localhost:9999", 8181)).isFalse();
        assertThat(names.accepts("localhost", 80)).isTrue(); // no port: 80
        assertThat(names.accepts("evil.example:8181", 8181)).isFalse();
        assertThat(names.accepts(null, 8181)).isFalse();
        assertThat(names.acceptsOrigin("http://localhost:8181", 8181)).isTrue();
        assertThat(names.acceptsOrigin("https://localhost:8181", 8181)).isFalse();
        assertThat(names.acceptsOrigin("null", 8181)).isFalse();
        assertThat(new HostNames("0.0.0.0", new String[0]).describe(8181)).doesNotContain("0.0.0.0");
    }
}
