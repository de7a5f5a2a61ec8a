package eu.brain.iot.edge.rest.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.HashMap;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.service.servlet.runtime.HttpServiceRuntime;
import org.osgi.service.servlet.runtime.dto.FilterDTO;
import org.osgi.service.servlet.runtime.dto.ServletContextDTO;
import org.osgi.service.servlet.runtime.dto.ServletDTO;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import com.fasterxml.jackson.databind.JsonNode;

import eu.brain.iot.edge.model.api.DeviceModel;

/**
 * What every test of the REST API's HTTP surface shares: a {@link ScriptedModel} registered as the device model, the
 * API's servlets, gate and Jetty setup running on Felix HTTP, the URI they answer on, and a client.
 * Configuration (PID {@value #PID}) that a test class sets is deleted after it.
 */
abstract class RestTestBase {

    static final String PID = "eu.brain.iot.edge.rest";
    static final Duration DEADLINE = Duration.ofSeconds(20);
    /** The whiteboard names of the API's servlets and filter. */
    private static final List<String> SERVLETS = List.of("eu.brain.iot.edge.rest", "eu.brain.iot.edge.rest.subscribe");
    private static final String GATE = "eu.brain.iot.edge.rest.gate";

    @InjectBundleContext
    static BundleContext context;
    @InjectService(timeout = 10_000)
    static ConfigurationAdmin cm;

    static ScriptedModel model;
    static URI base;
    static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    private static ServiceRegistration<DeviceModel> registration;
    private static final Map<String, Object> configured = new HashMap<>();

    @BeforeAll
    static void startApi() throws Exception {
        model = new ScriptedModel();
        registration = context.registerService(DeviceModel.class, model, null);
        base = awaitApi(Map.of(), List.of());
    }

    @AfterAll
    static void stopApi() throws Exception {
        Configuration[] found = cm.listConfigurations("(service.pid=" + PID + ")");
        if (found != null) {
            for (Configuration c : found) {
                c.delete();
            }
        }
        registration.unregister();
        configured.clear();
    }

    /** Sets these properties of the API (keeping those set before) and returns once it runs with them. */
    static void configure(Map<String, Object> properties) throws Exception {
        configured.putAll(properties);
        // DS registers the servlets and the gate again even for values already in force: wait for the new ones, not
        // the old ones about to go (a request sent to those would meet no servlet: 404)
        List<Long> before = registeredIds();
        cm.getConfiguration(PID, "?").update(new Hashtable<>(configured));
        base = awaitApi(properties, before);
    }

    /**
     * The servlets and the gate are in Felix HTTP's runtime with these property values (Config Admin applies a
     * change asynchronously and DS re-activates the components: a request sent at once could meet the old ones),
     * and Jetty answers JSON errors (the Jetty setup is in place); returns where Felix HTTP listens.
     */
    private static URI awaitApi(Map<String, Object> properties, List<Long> stale) {
        return await("the edge's REST API with " + properties).atMost(DEADLINE).until(() -> {
            ServiceReference<HttpServiceRuntime> ref = context.getServiceReference(HttpServiceRuntime.class);
            if (ref == null) {
                return null;
            }
            List<Long> ids = registeredIds();
            if (ids.size() != SERVLETS.size() + 1 || !Collections.disjoint(ids, stale)) {
                return null;
            }
            for (long id : ids) {
                ServiceReference<?>[] refs = context.getServiceReferences((String) null, "(service.id=" + id + ")");
                if (refs == null || !properties.entrySet().stream()
                        .allMatch(e -> Objects.deepEquals(e.getValue(), refs[0].getProperty(e.getKey())))) {
                    return null;
                }
            }
            ServiceReference<?>[] setups = context.getServiceReferences("org.apache.felix.http.jetty.ConnectorFactory",
                    null);
            if (setups == null || !properties.entrySet().stream()
                    .allMatch(e -> Objects.deepEquals(e.getValue(), setups[0].getProperty(e.getKey())))) {
                return null;
            }
            URI uri = endpoint(ref);
            if (uri == null) {
                return null;
            }
            // the Jetty setup (JSON error pages) is installed once Felix HTTP has called it
            RawHttp.Answer a = RawHttp.exchange(uri, "GET /nowhere HTTP/1.1\r\n" + RawHttp.host(uri), null);
            return a.status() == 404 && String.valueOf(a.header("Content-Type")).startsWith("application/json")
                    ? uri : null;
        }, u -> u != null);
    }

    /** The service ids of the edge's servlets and gate that Felix HTTP runs now. */
    private static List<Long> registeredIds() {
        ServiceReference<HttpServiceRuntime> ref = context.getServiceReference(HttpServiceRuntime.class);
        List<Long> ids = new ArrayList<>();
        if (ref == null) {
            return ids;
        }
        HttpServiceRuntime runtime = context.getService(ref);
        try {
            for (ServletContextDTO c : runtime.getRuntimeDTO().servletContextDTOs) {
                for (ServletDTO s : c.servletDTOs) {
                    if (SERVLETS.contains(s.name)) {
                        ids.add(s.serviceId);
                    }
                }
                for (FilterDTO f : c.filterDTOs) {
                    if (GATE.equals(f.name)) {
                        ids.add(f.serviceId);
                    }
                }
            }
        } finally {
            context.ungetService(ref);
        }
        return ids;
    }

    private static URI endpoint(ServiceReference<HttpServiceRuntime> ref) {
        Object endpoints = ref.getProperty("osgi.http.endpoint");
        List<String> all = endpoints instanceof String[] a ? List.of(a)
                : endpoints instanceof Collection<?> c ? c.stream().map(String::valueOf).toList()
                : endpoints == null ? List.of() : List.of(endpoints.toString());
        return all.stream().filter(e -> e.startsWith("http://") && !e.contains(":0/")).findFirst()
                .map(e -> URI.create(e.endsWith("/") ? e : e + "/")).orElse(null);
    }

    static URI uri(String path) {
        return base.resolve(path.startsWith("/") ? path.substring(1) : path);
    }

    static HttpResponse<String> get(String path) throws IOException, InterruptedException {
        return HTTP.send(HttpRequest.newBuilder(uri(path)).timeout(Duration.ofSeconds(15)).build(),
                HttpResponse.BodyHandlers.ofString());
    }

    static HttpResponse<String> post(String path, String body) throws IOException, InterruptedException {
        return HTTP.send(HttpRequest.newBuilder(uri(path)).timeout(Duration.ofSeconds(15))
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(body)).build(),
                HttpResponse.BodyHandlers.ofString());
    }

    static RawHttp.Answer raw(String head, String body) throws IOException {
        return RawHttp.exchange(base, head, body);
    }

    /** A JSON error of this status whose message contains each of {@code parts}. */
    static JsonNode assertError(int status, String body, String contentType, int expected, String... parts)
            throws IOException {
        assertThat(status).as(body).isEqualTo(expected);
        assertThat(contentType).as("Content-Type of " + body).startsWith("application/json");
        JsonNode e = RawHttp.JSON.readTree(body);
        assertThat(e.get("status").asInt()).isEqualTo(expected);
        if (parts.length > 0) {
            assertThat(e.get("error").asText()).contains(parts);
        }
        return e;
    }

    static JsonNode assertError(HttpResponse<String> r, int expected, String... parts) throws IOException {
        return assertError(r.statusCode(), r.body(), r.headers().firstValue("Content-Type").orElse(""), expected,
                parts);
    }

    static JsonNode assertError(RawHttp.Answer a, int expected, String... parts) throws IOException {
        return assertError(a.status(), a.body(), String.valueOf(a.header("Content-Type")), expected, parts);
    }
}
