package eu.brain.iot.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Asks the node's REST API ({@code GET /sensinact/providers}) whether its edge sees every robot and door of the
 * fleet with status OK: the moment the scenario starts. Thread-safe (the JDK client is).
 */
final class EdgeProbe {
    private final HttpClient client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(2)).build();
    private final URI providers;

    EdgeProbe(int httpPort) {
        providers = URI.create("http://127.0.0.1:" + httpPort + "/sensinact/providers");
    }

    /** The devices of {@code expected} that the edge does not show with status OK yet (all of them on an error). */
    Set<String> missing(List<String> expected) throws InterruptedException {
        Set<String> missing = new HashSet<>(expected);
        try {
            HttpResponse<byte[]> answer = client.send(HttpRequest.newBuilder(providers).timeout(Duration.ofSeconds(5))
                    .GET().build(), HttpResponse.BodyHandlers.ofByteArray());
            if (answer.statusCode() == 200) {
                for (JsonNode p : ReportWriter.MAPPER.readTree(answer.body())) {
                    if (p.path("status").asText().equals("OK")) {
                        missing.remove(p.path("id").asText());
                    }
                }
            }
        } catch (IOException e) {
            // not listening yet, or an answer that is not JSON: every device still missing
        }
        return missing;
    }

    /**
     * Waits until the edge shows every device with status OK.
     *
     * @throws IOException naming the devices still missing when the time ran out
     */
    void awaitDevices(List<String> expected, Duration timeout) throws IOException, InterruptedException {
        long until = System.nanoTime() + timeout.toNanos();
        Set<String> missing = missing(expected);
        while (!missing.isEmpty()) {
            if (System.nanoTime() > until) {
                throw new IOException("the node's edge did not show " + missing + " with status OK within "
                        + timeout.toSeconds() + " s (" + providers + ")");
            }
            Thread.sleep(100);
            missing = missing(expected);
        }
    }
}
