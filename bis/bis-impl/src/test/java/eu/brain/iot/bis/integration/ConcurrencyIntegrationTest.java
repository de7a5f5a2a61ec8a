package eu.brain.iot.bis.integration;

import static eu.brain.iot.bis.integration.TestRepository.ROBOT;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT_COLLISION;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT_UNLOAD;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.util.promise.Promise;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstalledBehaviour;

/** Requests that arrive together for the same behaviour lead to one install. */
class ConcurrencyIntegrationTest extends BisTestBase {

    @Test
    void concurrentRequestsForTheSameBehaviourShareOneInstall() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, ROBOT_UNLOAD);
        ExecutorService threads = Executors.newFixedThreadPool(8);
        CountDownLatch go = new CountDownLatch(1);
        List<Future<Promise<InstalledBehaviour>>> requests = new ArrayList<>();
        try {
            for (int i = 0; i < 8; i++) {
                // two event types the robot consumes, as two unhandled events would ask
                String type = i % 2 == 0 ? ROBOT_UNLOAD : ROBOT_COLLISION;
                requests.add(threads.submit(() -> {
                    go.await();
                    return installer.install(byType(type));
                }));
            }
            go.countDown();
            List<InstalledBehaviour> results = new ArrayList<>();
            for (Future<Promise<InstalledBehaviour>> f : requests) {
                results.add(value(f.get()));
            }
            assertThat(results).extracting(b -> b.bundleId).containsOnly(results.get(0).bundleId);
        } finally {
            threads.shutdownNow();
        }
        assertThat(bundleCount(ROBOT)).isEqualTo(1);
        assertThat(installer.installed()).hasSize(1);
        assertThat(busStatistics.consumers().stream().filter(c -> ROBOT.equals(c.bundle)).count()).isEqualTo(1);
    }

    @Test
    void aRequestWhileAnInstallRunsGetsThatInstallsPromise() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, ROBOT_UNLOAD);
        // hold the install in its last step: without the bus, the robot's smart behaviour cannot be registered
        Bundle bus = bundle("eu.brain.iot.eventbus");
        bus.stop();
        Promise<InstalledBehaviour> first;
        Promise<InstalledBehaviour> second;
        try {
            first = installer.install(byType(ROBOT_UNLOAD));
            await().atMost(DEADLINE).until(() -> bundle(ROBOT) != null && bundle(ROBOT).getState() == Bundle.ACTIVE);
            second = installer.install(byName(ROBOT, false));
            assertThat(first.isDone()).isFalse();
            assertThat(second).isSameAs(first);
        } finally {
            bus.start();
        }
        assertThat(value(second).bundleId).isEqualTo(value(first).bundleId);
        assertThat(bundleCount(ROBOT)).isEqualTo(1);
        assertThat(installer.installed()).hasSize(1);
    }
}
