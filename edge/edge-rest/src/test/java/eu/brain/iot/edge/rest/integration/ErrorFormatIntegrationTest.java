package eu.brain.iot.edge.rest.integration;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;

import org.junit.jupiter.api.Test;

/**
 * Every error of the API is the same JSON ({@code {"error", "field"?, "status"}}), also those Jetty answers before
 * any servlet runs, and HEAD works wherever GET does.
 */
class ErrorFormatIntegrationTest extends RestTestBase {

    @Test
    void aQueryThatIsNotUtf8Answers400Json() throws Exception {
        for (String query : new String[] { "provider=%ff", "provider=%C0%AF", "service=%e2%28%a1" }) {
            RawHttp.Answer a = raw("GET /sensinact/subscribe?" + query + " HTTP/1.1\r\n" + RawHttp.host(base), null);
            assertError(a, 400, "not valid percent-encoded UTF-8", "?provider=robot1");
            assertThat(a.json().get("field").asText()).isEqualTo("query");
            assertThat(a.body()).doesNotContain("Exception", "<html");
        }
        // the API still streams afterwards
        assertThat(model.subscribers()).isZero();
    }

    @Test
    void jettysOwnErrorsAreJson() throws Exception {
        String head = "GET /sensinact/providers?q=" + "a".repeat(20_000) + " HTTP/1.1\r\n" + RawHttp.host(base);
        assertError(raw(head, null), 414, "URI is too long");
        head = "GET /sensinact/providers HTTP/1.1\r\n" + RawHttp.host(base) + "\r\nX-Big: " + "b".repeat(20_000);
        assertError(raw(head, null), 431, "headers are too large");
        // Jetty decodes a path that is not UTF-8 as ISO-8859-1: an unknown provider, not a failure
        assertError(raw("GET /sensinact/providers/%ff HTTP/1.1\r\n" + RawHttp.host(base), null), 404,
                "no provider");
        assertError(raw("BLAH\r\n" + RawHttp.host(base), null), 400, "malformed HTTP request");
        assertError(raw("GET /sensinact/providers HTTP/1.1\r\nHost: a\r\nHost: b", null), 400);
    }

    @Test
    void pathsOutsideTheApiAnswer404Json() throws Exception {
        assertError(get("/nothing/here"), 404, "no such path: /nothing/here", "/sensinact");
        assertError(raw("DELETE /nothing HTTP/1.1\r\n" + RawHttp.host(base), null), 404, "no such path");
    }

    @Test
    void headWorksWhereGetDoes() throws Exception {
        for (String path : new String[] { "/sensinact", "/sensinact/providers", "/sensinact/providers/robot1",
                "/sensinact/providers/robot1/services/position/resources/x" }) {
            HttpResponse<Void> head = HTTP.send(HttpRequest.newBuilder(uri(path)).timeout(Duration.ofSeconds(15))
                    .method("HEAD", HttpRequest.BodyPublishers.noBody()).build(), HttpResponse.BodyHandlers.discarding());
            assertThat(head.statusCode()).as(path).isEqualTo(200);
            assertThat(head.headers().firstValue("Content-Type")).hasValueSatisfying(
                    t -> assertThat(t).startsWith("application/json"));
        }
        HttpResponse<Void> stream = HTTP.send(HttpRequest.newBuilder(uri("/sensinact/subscribe?provider=robot1"))
                .timeout(Duration.ofSeconds(15)).method("HEAD", HttpRequest.BodyPublishers.noBody()).build(),
                HttpResponse.BodyHandlers.discarding());
        assertThat(stream.statusCode()).isEqualTo(200);
        assertThat(stream.headers().firstValue("Content-Type")).hasValueSatisfying(
                t -> assertThat(t).startsWith("text/event-stream"));
        assertThat(model.subscribers()).isZero();
        RawHttp.Answer a = raw("HEAD /sensinact/providers/robot9 HTTP/1.1\r\n" + RawHttp.host(base), null);
        assertThat(a.status()).isEqualTo(404);
        assertThat(a.body()).isEmpty();
    }

    @Test
    void actBodiesAreStrict() throws Exception {
        String act = "/sensinact/providers/robot1/services/control/resources/goTo/act";
        assertError(post(act, "{\"x\":9,\"y\":7,\"x\":1}"), 400, "Duplicate field 'x'");
        String deep = "{\"x\":" + "[".repeat(5_000) + "]".repeat(5_000) + ",\"y\":1}";
        assertThat(assertError(post(act, deep), 400, "nesting depth exceeds 16").get("field").asText())
                .isEqualTo("body");
        assertError(post(act, "{\"x\":9} trailing"), 400, "malformed JSON");
        assertThat(model.acts).isEmpty();
    }
}
