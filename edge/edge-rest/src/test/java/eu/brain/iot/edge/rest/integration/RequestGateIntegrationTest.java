package eu.brain.iot.edge.rest.integration;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Map;

import org.junit.jupiter.api.Test;

/** Requests a web page could send: a foreign Host (DNS rebinding), a foreign Origin, a POST that is not JSON. */
class RequestGateIntegrationTest extends RestTestBase {

    private static final String ACT = "/sensinact/providers/door1/services/control/resources/open/act";

    private static String post(String headers) {
        return "POST " + ACT + " HTTP/1.1\r\nContent-Length: 2" + (headers.isEmpty() ? "" : "\r\n" + headers);
    }

    @Test
    void aForeignHostIsRefused421() throws Exception {
        RawHttp.Answer a = raw("GET /sensinact/providers HTTP/1.1\r\nHost: evil.example:" + base.getPort(), null);
        assertThat(assertError(a, 421, "Host 'evil.example:" + base.getPort() + "' is not a name of this server",
                "127.0.0.1:" + base.getPort(), "allowed.hosts").get("field").asText()).isEqualTo("Host");
        assertError(raw("GET /sensinact HTTP/1.1\r\nHost: 127.0.0.1:1", null), 421);
        for (String host : new String[] { "127.0.0.1", "localhost", "LOCALHOST", "[::1]" }) {
            RawHttp.Answer ok = raw("GET /sensinact HTTP/1.1\r\nHost: " + host + ":" + base.getPort(), null);
            assertThat(ok.status()).as(host).isEqualTo(200);
        }
    }

    @Test
    void aForeignOriginIsRefused403() throws Exception {
        String own = "Origin: http://127.0.0.1:" + base.getPort();
        RawHttp.Answer a = raw(post(RawHttp.host(base) + "\r\nContent-Type: application/json\r\n"
                + "Origin: http://evil.example"), "{}");
        assertThat(assertError(a, 403, "cross-origin request refused", "evil.example").get("field").asText())
                .isEqualTo("Origin");
        assertError(raw("GET /sensinact HTTP/1.1\r\n" + RawHttp.host(base) + "\r\nOrigin: null", null), 403);
        assertThat(raw(post(RawHttp.host(base) + "\r\nContent-Type: application/json\r\n" + own), "{}").status())
                .isEqualTo(200);
        assertThat(model.acts).hasSize(1);
    }

    @Test
    void aPostMustBeJson415() throws Exception {
        int before = model.acts.size();
        for (String type : new String[] { "", "Content-Type: text/plain", 
                "Content-Type: application/x-www-form-urlencoded", "Content-Type: multipart/form-data; boundary=x" }) {
            RawHttp.Answer a = raw(post(RawHttp.host(base) + (type.isEmpty() ? "" : "\r\n" + type)), "{}");
            assertThat(assertError(a, 415, "POST needs Content-Type: application/json", "-H 'Content-Type")
                    .get("field").asText()).isEqualTo("Content-Type");
        }
        assertThat(model.acts).hasSize(before);
        RawHttp.Answer ok = raw(post(RawHttp.host(base) + "\r\nContent-Type: Application/JSON; charset=utf-8"), "{}");
        assertThat(ok.status()).as(ok.body()).isEqualTo(200);
    }

    @Test
    void configuredNamesAreAccepted() throws Exception {
        configure(Map.of("allowed.hosts", new String[] { "edge.example" }));
        String name = "edge.example:" + base.getPort();
        assertThat(raw("GET /sensinact HTTP/1.1\r\nHost: " + name, null).status()).isEqualTo(200);
        assertThat(raw(post("Host: " + name + "\r\nOrigin: http://" + name + "\r\nContent-Type: application/json"),
                "{}").status()).isEqualTo(200);
        assertError(raw("GET /sensinact HTTP/1.1\r\nHost: other.example:" + base.getPort(), null), 421,
                "edge.example:" + base.getPort());
    }
}
