package eu.brain.iot.bis.integration;

import static eu.brain.iot.bis.integration.TestRepository.EVENTS;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT_UNLOAD;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.Set;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;

/** A failed install leaves the framework exactly as it was. */
class RollbackIntegrationTest extends BisTestBase {

    @Test
    void aMissingDependencyFailsTheInstallAndLeavesTheFrameworkAsItWas() throws Exception {
        repo.drop(EVENTS::equals); // the robot imports the events package, which now no bundle offers
        repo.sign(keys);
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, ROBOT_UNLOAD);
        Set<String> before = frameworkBundles();

        InstallException e = failure(installer.install(byType(ROBOT_UNLOAD)));

        assertThat(e.problem()).isEqualTo(Problem.UNRESOLVED);
        assertThat(e.getMessage()).contains(ROBOT, "osgi.wiring.package", "eu.brain.iot.behaviours.events",
                "add a bundle that does to an index");
        assertThat(frameworkBundles()).isEqualTo(before);
        assertThat(installer.installed()).isEmpty();
    }

    @Test
    void aBehaviourThatNeverReachesTheBusIsRolledBackAfterTheActivationTimeout() throws Exception {
        var settings = settings();
        settings.put("activation.timeout.ms", 300L);
        BundleInstaller installer = configure(settings);
        awaitOffered(installer, ROBOT_UNLOAD);
        Set<String> before = frameworkBundles();
        // simulate a behaviour whose services cannot come: the bus is the behaviours' mandatory reference
        org.osgi.framework.Bundle bus = bundle("eu.brain.iot.eventbus");
        bus.stop();
        try {
            InstallException e = failure(installer.install(byType(ROBOT_UNLOAD)));
            assertThat(e.problem()).isEqualTo(Problem.ACTIVATION_TIMEOUT);
            assertThat(e.getMessage()).contains(ROBOT, "300 ms", "activation.timeout.ms");
            assertThat(e.getMessage()).as("what Declarative Services says of the behaviour's components")
                    .containsPattern("components not active: .*FleetLeadership missing reference bus")
                    .contains("the bundle registered no smart behaviour");
        } finally {
            bus.start();
        }
        assertThat(frameworkBundles()).isEqualTo(before);
    }
}
