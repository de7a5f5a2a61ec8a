package eu.brain.iot.edge.impl;

import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.function.Function;

import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/**
 * For each test: a simulator of the paper's warehouse (manual steps: the test decides when time passes) and the
 * edge core polling it over real HTTP, with every event it publishes recorded; both closed after the test.
 * <pre>{@code
 * @RegisterExtension
 * final EdgeOnSim fleet = new EdgeOnSim(url -> FleetSettings.of(url, List.of(), List.of(), 100, 1000, 8, 1, 2, 400));
 * }</pre>
 */
final class EdgeOnSim implements BeforeEachCallback, AfterEachCallback {

    static final Duration DEADLINE = Duration.ofSeconds(15);

    private final Function<String, FleetSettings> settings;
    final RecordingSink sink = new RecordingSink();
    RobotSim sim;
    Edge edge;

    /** @param settings the edge's settings for the simulator's base URL */
    EdgeOnSim(Function<String, FleetSettings> settings) {
        this.settings = settings;
    }

    @Override
    public void beforeEach(ExtensionContext context) throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge = new Edge(settings.apply(sim.baseUri().toString()), sink, EdgeLog.stderr());
    }

    @Override
    public void afterEach(ExtensionContext context) {
        try {
            if (edge != null) {
                edge.close();
            }
        } finally {
            if (sim != null) {
                sim.close();
            }
        }
    }

    /** Replaces the edge by one with other settings, on the same simulator; what was recorded is forgotten. */
    void restart(Function<String, FleetSettings> other) {
        edge.close();
        sink.events.clear();
        edge = new Edge(other.apply(sim.baseUri().toString()), sink, EdgeLog.stderr());
    }

    /** Waits until the edge has this many providers and the last poll of each one answered. */
    void awaitAllOk(int providers) {
        await("all " + providers + " devices polled OK").atMost(DEADLINE)
                .until(() -> edge.providers().size() == providers
                        && edge.providers().stream().allMatch(p -> p.status() == ResourceStatus.OK));
    }
}
