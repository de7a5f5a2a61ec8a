package eu.brain.iot.edge.integration;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.osgi.framework.BundleContext;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.edge.model.api.DeviceModel;

/**
 * What the tests of the edge's REST API share: one simulator and one configured edge for the whole class
 * ({@link EdgeTestSupport}), with the REST servlets registered on Felix HTTP. A subclass's own {@code @BeforeAll}
 * runs after this one's, its {@code @AfterAll} before.
 */
abstract class EdgeRestTestBase {

    @InjectBundleContext
    static BundleContext context;
    @InjectService(timeout = 10_000)
    static ConfigurationAdmin cm;
    @InjectService(timeout = 10_000)
    static DeviceModel model;

    static EdgeTestSupport edge;

    @BeforeAll
    static void startEdge() throws Exception {
        edge = EdgeTestSupport.start(context, cm, model);
    }

    @AfterAll
    static void stopEdge() throws Exception {
        edge.close();
    }
}
