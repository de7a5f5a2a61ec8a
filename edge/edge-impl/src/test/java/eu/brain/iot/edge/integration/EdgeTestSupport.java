package eu.brain.iot.edge.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.service.servlet.runtime.HttpServiceRuntime;
import org.osgi.service.servlet.runtime.dto.ServletContextDTO;
import org.osgi.service.servlet.runtime.dto.ServletDTO;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/**
 * What every in-framework test of the edge needs: a robot simulator running inside the test framework (manual
 * steps: the test decides when time passes), the edge configured through Config Admin to poll it, and an HTTP
 * client for the edge's REST API on the port Felix HTTP bound.
 * <pre>{@code
 * @BeforeAll static void start() throws Exception { edge = EdgeTestSupport.start(context, cm, model); }
 * @AfterAll static void stop() { edge.close(); }
 * }</pre>
 */
final class EdgeTestSupport implements AutoCloseable {

    static final Duration DEADLINE = Duration.ofSeconds(20);
    static final String EDGE_PID = "eu.brain.iot.edge";
    static final String REST_PID = "eu.brain.iot.edge.rest";
    /** Backoff at most 400 ms after 2 failed polls in a row (500 ms each at most): faults show within a second. */
    static final long BACKOFF_MAX_MS = 400;
    static final Map<String, Object> FAIL_FAST = Map.of("request.timeout.ms", 500L, "unreachable.after.failures", 2,
            "backoff.max.ms", BACKOFF_MAX_MS);
    static final ObjectMapper JSON = new ObjectMapper();
    /** The whiteboard names of the edge's REST servlets. */
    private static final List<String> SERVLETS = List.of("eu.brain.iot.edge.rest", "eu.brain.iot.edge.rest.subscribe");

    final RobotSim sim;
    final URI base;
    private final ConfigurationAdmin cm;
    private final BundleContext context;
    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    private final List<String> configured = new ArrayList<>();
    private final Map<String, Object> restProperties = new HashMap<>();
    private final Map<String, Object> edgeProperties = new HashMap<>();

    private EdgeTestSupport(RobotSim sim, URI base, ConfigurationAdmin cm, BundleContext context) {
        this.sim = sim;
        this.context = context;
        this.base = base;
        this.cm = cm;
    }

    /**
     * Starts a simulator of the paper's warehouse, points the edge at it (polling every 100 ms), and returns once
     * every robot and door is polled and the REST servlets are registered.
     */
    static EdgeTestSupport start(BundleContext context, ConfigurationAdmin cm, DeviceModel model) throws Exception {
        return start(context, cm, model, Map.of());
    }

    /**
     * Like {@link #start(BundleContext, ConfigurationAdmin, DeviceModel)}, with these edge settings as well (for
     * example {@link #FAIL_FAST}); they are in effect when it returns, the fleet URL and they came in one update.
     */
    static EdgeTestSupport start(BundleContext context, ConfigurationAdmin cm, DeviceModel model,
            Map<String, Object> settings) throws Exception {
        return start(context, cm, model, SimConfig.builder().manualStep(true).build(), settings);
    }

    /** Like {@link #start(BundleContext, ConfigurationAdmin, DeviceModel, Map)}, with a simulator of this configuration. */
    static EdgeTestSupport start(BundleContext context, ConfigurationAdmin cm, DeviceModel model, SimConfig simConfig,
            Map<String, Object> settings) throws Exception {
        RobotSim sim = RobotSim.start(simConfig);
        try {
            EdgeTestSupport edge = new EdgeTestSupport(sim, awaitRest(context), cm, context);
            Instant configuredAt = Instant.now();
            // world.period.ms 0: these tests count robots and doors; the carts and map read from the world are
            // WorldReaderTest's (edge core) and the warehouse itests' subject
            edge.edgeProperties.putAll(Map.of("fleet.url", sim.baseUri().toString(), "poll.period.ms", 100L,
                    "world.period.ms", 0L));
            edge.configureEdge(settings);
            edge.awaitProvidersOk(model, configuredAt);
            return edge;
        } catch (Exception | Error e) {
            sim.close();
            throw e;
        }
    }

    /**
     * Changes these settings of the edge (PID {@value #EDGE_PID}) and keeps the others this test set: the edge
     * applies the new configuration in place.
     */
    void configureEdge(Map<String, Object> changes) throws IOException {
        edgeProperties.putAll(changes);
        configure(EDGE_PID, edgeProperties);
    }

    /** Sets a configuration (for any bundle: location "?"), to be deleted by {@link #close()}. */
    void configure(String pid, Map<String, Object> properties) throws IOException {
        Configuration c = cm.getConfiguration(pid, "?");
        c.update(new Hashtable<>(properties));
        if (!configured.contains(pid)) {
            configured.add(pid);
        }
    }

    /**
     * Changes these settings of the edge's REST servlets (PID {@value #REST_PID}), keeping the others this test
     * set, and returns once both servlets are registered again with them:
     * Config Admin applies a change asynchronously and DS re-activates the servlets, so a request sent at once
     * could meet the old servlet or none (404).
     */
    void configureRest(Map<String, Object> properties) throws IOException {
        restProperties.putAll(properties);
        configure(REST_PID, restProperties);
        awaitServlets(restProperties, true);
    }

    /**
     * Both REST servlets are in Felix HTTP's runtime, and their services carry these property values (or other
     * values: bnd gives every configuration property its default as a component property).
     */
    private void awaitServlets(Map<String, Object> properties, boolean carried) {
        await("the edge's REST servlets " + (carried ? "with " : "no longer with ") + properties).atMost(DEADLINE)
                .untilAsserted(() -> {
                    List<ServiceReference<?>> servlets = registeredServlets(context);
                    assertThat(servlets).hasSameSizeAs(SERVLETS).allSatisfy(ref -> properties.forEach((k, v) -> {
                        if (carried) {
                            assertThat(ref.getProperty(k)).as(k + " of " + ref).isEqualTo(v);
                        } else {
                            assertThat(ref.getProperty(k)).as(k + " of " + ref).isNotEqualTo(v);
                        }
                    }));
                });
    }

    /** The services of the edge's servlets that Felix HTTP has registered (empty before Felix HTTP runs). */
    private static List<ServiceReference<?>> registeredServlets(BundleContext context) throws InvalidSyntaxException {
        ServiceReference<HttpServiceRuntime> ref = context.getServiceReference(HttpServiceRuntime.class);
        if (ref == null) {
            return List.of();
        }
        HttpServiceRuntime runtime = context.getService(ref);
        try {
            List<ServiceReference<?>> found = new ArrayList<>();
            for (ServletContextDTO c : runtime.getRuntimeDTO().servletContextDTOs) {
                for (ServletDTO s : c.servletDTOs) {
                    ServiceReference<?>[] refs = SERVLETS.contains(s.name)
                            ? context.getServiceReferences((String) null, "(service.id=" + s.serviceId + ")")
                            : null;
                    if (refs != null) {
                        found.add(refs[0]);
                    }
                }
            }
            return found;
        } finally {
            context.ungetService(ref);
        }
    }

    /** Every device of the simulator is a provider whose last poll, after {@code since}, answered. */
    void awaitProvidersOk(DeviceModel model, Instant since) {
        List<String> ids = Stream.concat(sim.robotIds().stream(), sim.doorIds().stream()).sorted().toList();
        await("every device polled from " + sim.baseUri()).atMost(DEADLINE).untilAsserted(() -> {
            List<ProviderSnapshot> providers = model.providers();
            assertThat(providers).extracting(ProviderSnapshot::id).containsExactlyElementsOf(ids);
            assertThat(providers).allSatisfy(p -> {
                assertThat(p.status()).isEqualTo(ResourceStatus.OK);
                assertThat(p.lastPoll()).isAfter(since);
            });
        });
    }

    /**
     * Waits until the edge polls another fleet than the one at {@code base}, the last this test configured (Config
     * Admin applies a change later).
     */
    private void awaitFleetLeft(String base) {
        await("the edge leaves the fleet at " + base).atMost(DEADLINE).until(() -> {
            ServiceReference<PollMonitor> ref = context.getServiceReference(PollMonitor.class);
            if (ref == null) {
                return true; // no edge: nothing polls the simulator
            }
            try {
                PollMonitor monitor = context.getService(ref);
                return monitor == null || !base.equals(monitor.statistics().fleetUrl);
            } finally {
                context.ungetService(ref);
            }
        });
    }

    /** Where Felix HTTP listens (it binds a free port: run property org.osgi.service.http.port=0), once the edge's servlets are there. */
    private static URI awaitRest(BundleContext context) {
        return await("Felix HTTP with the edge's servlets").atMost(DEADLINE).until(() -> {
            if (registeredServlets(context).size() != SERVLETS.size()) {
                return null;
            }
            ServiceReference<HttpServiceRuntime> ref = context.getServiceReference(HttpServiceRuntime.class);
            if (ref == null) {
                return null;
            }
            Object endpoints = ref.getProperty("osgi.http.endpoint");
            List<String> all = endpoints instanceof String[] a ? List.of(a)
                    : endpoints instanceof java.util.Collection<?> c ? c.stream().map(String::valueOf).toList()
                    : endpoints == null ? List.of() : List.of(endpoints.toString());
            return all.stream().filter(e -> e.startsWith("http://") && !e.contains(":0/")).findFirst()
                    .map(e -> URI.create(e.endsWith("/") ? e : e + "/")).orElse(null);
        }, u -> u != null);
    }

    HttpResponse<String> get(String path) throws IOException, InterruptedException {
        return send("GET", path, null);
    }

    HttpResponse<String> post(String path, String body) throws IOException, InterruptedException {
        return send("POST", path, body);
    }

    HttpResponse<String> send(String method, String path, String body) throws IOException, InterruptedException {
        HttpRequest.Builder b = HttpRequest.newBuilder(uri(path)).timeout(Duration.ofSeconds(15));
        b.method(method, body == null ? HttpRequest.BodyPublishers.noBody() : HttpRequest.BodyPublishers.ofString(body));
        if (body != null) {
            b.header("Content-Type", "application/json");
        }
        return http.send(b.build(), HttpResponse.BodyHandlers.ofString());
    }

    URI uri(String path) {
        return base.resolve(path.startsWith("/") ? path.substring(1) : path);
    }

    HttpClient http() {
        return http;
    }

    static JsonNode json(HttpResponse<String> response) throws IOException {
        assertThat(response.headers().firstValue("Content-Type")).hasValueSatisfying(
                t -> assertThat(t).startsWith("application/json"));
        return JSON.readTree(response.body());
    }

    /** Deletes what this test configured (the edge goes back to its defaults) and stops the simulator. */
    @Override
    public void close() throws IOException {
        try {
            for (String pid : configured) {
                Configuration[] found = cm.listConfigurations("(service.pid=" + pid + ")");
                if (found != null) {
                    for (Configuration c : found) {
                        c.delete();
                    }
                }
            }
            // the next test class must not meet servlets that are going away
            awaitServlets(restProperties, false);
            // nor devices made UNREACHABLE by polls of this closed simulator: the edge keeps its devices across a
            // change of fleet and would tell their recovery on the next test's bus
            awaitFleetLeft((String) edgeProperties.get("fleet.url"));
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        } finally {
            sim.close();
        }
    }
}
