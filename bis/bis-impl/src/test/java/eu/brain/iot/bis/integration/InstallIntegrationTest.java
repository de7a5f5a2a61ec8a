package eu.brain.iot.bis.integration;

import static eu.brain.iot.bis.integration.TestRepository.DOOR;
import static eu.brain.iot.bis.integration.TestRepository.DOOR_CLOSED;
import static eu.brain.iot.bis.integration.TestRepository.EDGE_API;
import static eu.brain.iot.bis.integration.TestRepository.EDGE_MODEL_API;
import static eu.brain.iot.bis.integration.TestRepository.EVENTS;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT_UNLOAD;
import static eu.brain.iot.bis.integration.TestRepository.WAREHOUSE;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bis.api.InstalledBundle;

/** Installs the real behaviour bundles from a real, signed index, with what they need, and uninstalls them. */
class InstallIntegrationTest extends BisTestBase {

    @Test
    void aBehaviourIsInstalledWithItsDependencyAndRegisteredWithTheBus() throws Exception {
        Set<String> before = frameworkBundles();
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);

        List<BehaviourCandidate> found = value(installer.find(List.of(DOOR_CLOSED)));
        assertThat(found).extracting(c -> c.symbolicName).containsExactly(DOOR);
        assertThat(found.get(0).sha256).hasSize(64);
        assertThat(found.get(0).url).startsWith("file:").contains(repo.dir.toString() + "/behaviour-door");

        InstalledBehaviour door = value(installer.install(byType(DOOR_CLOSED)));

        assertThat(door.symbolicName).isEqualTo(DOOR);
        assertThat(door.state).isEqualTo("ACTIVE");
        assertThat(door.reason).isEqualTo("test: event had no consumer");
        // the behaviour first, then what it needs: the events bundle, the warehouse helpers and the edge's two API bundles
        assertThat(door.bundles.get(0).symbolicName).isEqualTo(DOOR);
        assertThat(door.bundles).extracting(b -> b.symbolicName).containsExactlyInAnyOrder(DOOR, EVENTS, EDGE_API,
                EDGE_MODEL_API, WAREHOUSE);
        assertThat(bundle(DOOR).getState()).isEqualTo(Bundle.ACTIVE);
        assertThat(bundle(EVENTS).getState()).isEqualTo(Bundle.ACTIVE);
        assertThat(busKnows(DOOR)).as("the bus lists the door's smart behaviour when the promise resolves").isTrue();
        assertThat(installer.installed()).extracting(b -> b.symbolicName).containsExactly(DOOR);
        assertThat(command("list")).contains(DOOR, "ACTIVE", "test: event had no consumer", "needs: " + EVENTS);

        // a second behaviour shares the events bundle: counted, not installed twice
        InstalledBehaviour robot = value(installer.install(byType(ROBOT_UNLOAD)));
        assertThat(robot.bundles).extracting(b -> b.symbolicName).containsExactlyInAnyOrder(ROBOT, EVENTS, EDGE_API,
                EDGE_MODEL_API, WAREHOUSE);
        assertThat(bundleCount(EVENTS)).isEqualTo(1);
        assertThat(bundleCount(EDGE_API)).isEqualTo(1);
        InstalledBundle shared = installer.installed().get(0).bundles.stream()
                .filter(b -> b.symbolicName.equals(EVENTS)).findFirst().orElseThrow();
        assertThat(shared.users).isEqualTo(2);

        // uninstalling one keeps what the other needs; uninstalling both leaves the framework as it was
        value(installer.uninstall(DOOR, "test", false));
        assertThat(bundle(DOOR)).isNull();
        assertThat(bundle(EVENTS)).isNotNull();
        assertThat(busKnows(DOOR)).isFalse();
        value(installer.uninstall(ROBOT, "test", false));
        assertThat(bundle(EVENTS)).isNull();
        assertThat(bundle(EDGE_API)).isNull();
        assertThat(frameworkBundles()).isEqualTo(before);
    }

    @Test
    void theConfiguredPreferenceComesFirst() throws Exception {
        // without a preference the higher version comes first, and the test bundles' versions end with the minute
        // each was built in: the test prefers each in turn
        var preferDoor = settings();
        preferDoor.put("prefer", new String[] { DOOR });
        BundleInstaller installer = configure(preferDoor);
        awaitOffered(installer, DOOR_CLOSED);
        // both consume nothing in common: asking for either type lists both, the preferred first
        List<String> types = List.of(DOOR_CLOSED, ROBOT_UNLOAD);
        assertThat(value(installer.find(types))).extracting(c -> c.symbolicName).containsExactly(DOOR, ROBOT);

        var preferRobot = settings();
        preferRobot.put("prefer", new String[] { ROBOT });
        installer = configure(preferRobot);
        awaitOffered(installer, DOOR_CLOSED);
        assertThat(value(installer.find(types))).extracting(c -> c.symbolicName).containsExactly(ROBOT, DOOR);
    }
}
