package eu.brain.iot.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Asks a node's REST API ({@code GET /sensinact/providers}) what its edge shows: whether it sees every robot and door
 * of the fleet with status OK (the moment the scenario starts; with several nodes, over the union of what they show),
 * and which robots and doors it owns. Thread-safe (the JDK client is).
 */
final class EdgeProbe {
    /** The provider kinds that are devices a node owns. */
    private static final Set<String> DEVICE_KINDS = Set.of("robot", "door");
    private static final Duration REQUEST_TIMEOUT = Duration.ofSeconds(5);
    private static final long LOOK_EVERY_MS = 100;

    private final HttpClient client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(2)).build();
    private final URI base;
    private final URI providers;

    EdgeProbe(int httpPort) {
        base = URI.create("http://127.0.0.1:" + httpPort + "/sensinact/");
        providers = base.resolve("providers");
    }

    /** The devices the edge shows with status OK (none on an error: not listening yet, or no JSON). */
    Set<String> seenOk() throws InterruptedException {
        Set<String> ok = new HashSet<>();
        try {
            for (JsonNode p : get(providers)) {
                if (p.path("status").asText().equals("OK")) {
                    ok.add(p.path("id").asText());
                }
            }
        } catch (IOException e) {
            // not listening yet, or an answer that is not JSON: nothing seen
        }
        return ok;
    }

    /** The devices of {@code expected} that the edge does not show with status OK yet (all of them on an error). */
    Set<String> missing(List<String> expected) throws InterruptedException {
        return missing(List.of(this), expected);
    }

    /** The devices of {@code expected} that none of the nodes shows with status OK yet. */
    static Set<String> missing(List<EdgeProbe> probes, List<String> expected) throws InterruptedException {
        Set<String> missing = new HashSet<>(expected);
        for (EdgeProbe probe : probes) {
            missing.removeAll(probe.seenOk());
        }
        return missing;
    }

    /**
     * Waits until the edge shows every device with status OK.
     *
     * @throws IOException naming the devices still missing when the time ran out
     */
    void awaitDevices(List<String> expected, Duration timeout) throws IOException, InterruptedException {
        awaitDevices(List.of(this), expected, timeout);
    }

    /**
     * Waits until every device is shown with status OK by one of the nodes at least (each node's edge shows the
     * devices it owns; a device seen OK anywhere counts).
     *
     * @throws IOException naming the devices still missing when the time ran out
     */
    static void awaitDevices(List<EdgeProbe> probes, List<String> expected, Duration timeout)
            throws IOException, InterruptedException {
        long until = System.nanoTime() + timeout.toNanos();
        Set<String> missing = missing(probes, expected);
        while (!missing.isEmpty()) {
            if (System.nanoTime() > until) {
                throw new IOException((probes.size() == 1 ? "the node's edge" : "none of the nodes' edges")
                        + " showed " + missing + " with status OK within " + timeout.toSeconds() + " s ("
                        + String.join(", ", probes.stream().map(p -> p.providers.toString()).toList()) + ")");
            }
            Thread.sleep(LOOK_EVERY_MS);
            missing = missing(probes, expected);
        }
    }

    /**
     * The robots and doors this node's edge owns, sorted. A device the edge shows is its own unless its
     * {@code fabric} service's {@code node} resource names another node (an edge may show a device another node owns
     * that way).
     *
     * @param node this node's name
     * @throws IOException when the edge does not answer
     */
    List<String> owned(String node) throws IOException, InterruptedException {
        List<String> owned = new ArrayList<>();
        for (JsonNode p : get(providers)) {
            String id = p.path("id").asText();
            if (DEVICE_KINDS.contains(p.path("kind").asText()) && owner(id).map(node::equals).orElse(true)) {
                owned.add(id);
            }
        }
        owned.sort(null);
        return owned;
    }

    /** The node a device's {@code fabric}/{@code node} resource names, if the edge shows one. */
    private java.util.Optional<String> owner(String id) throws InterruptedException {
        try {
            JsonNode r = get(base.resolve("providers/" + id + "/services/fabric/resources/node"));
            String value = r.path("value").asText("");
            return value.isEmpty() ? java.util.Optional.empty() : java.util.Optional.of(value);
        } catch (IOException e) {
            return java.util.Optional.empty(); // no such resource (404): the edge shows only what it owns
        }
    }

    private JsonNode get(URI uri) throws IOException, InterruptedException {
        HttpResponse<byte[]> answer = client.send(HttpRequest.newBuilder(uri).timeout(REQUEST_TIMEOUT).GET().build(),
                HttpResponse.BodyHandlers.ofByteArray());
        if (answer.statusCode() != 200) {
            throw new IOException(uri + " answered " + answer.statusCode());
        }
        return ReportWriter.MAPPER.readTree(answer.body());
    }
}
