package eu.brain.iot.edge.integration;

import java.util.Map;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.osgi.framework.BundleContext;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.robotsim.RobotSim;

/**
 * What the tests of the edge on the bus share: before each test a {@link BusRecorder} on the bus, then a simulator
 * and the edge configured to poll it ({@link EdgeTestSupport}); after it, both gone.
 */
abstract class EdgeBusTestBase {

    @InjectBundleContext
    BundleContext context;
    @InjectService(timeout = 5_000)
    ConfigurationAdmin configurationAdmin;
    @InjectService(timeout = 5_000)
    EventBus bus;
    @InjectService(timeout = 5_000)
    DeviceModel model;

    EdgeTestSupport edge;
    RobotSim sim;
    BusRecorder recorder;

    /** Edge settings of this class's tests, in effect from the first poll on (none: the defaults of the support). */
    Map<String, Object> edgeSettings() {
        return Map.of();
    }

    @BeforeEach
    void start() throws Exception {
        recorder = new BusRecorder(context);
        edge = EdgeTestSupport.start(context, configurationAdmin, model, edgeSettings());
        sim = edge.sim;
    }

    @AfterEach
    void stop() throws Exception {
        recorder.close();
        edge.close();
    }
}
