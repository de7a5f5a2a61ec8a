package eu.brain.iot.node.ready;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleException;
import org.osgi.framework.Constants;
import org.osgi.framework.launch.Framework;
import org.osgi.framework.launch.FrameworkFactory;
import org.osgi.framework.startlevel.BundleStartLevel;
import org.osgi.framework.wiring.FrameworkWiring;

import eu.brain.iot.node.TestBundles;

/** {@link BundleHealth} against bundles in every state a launch can leave them in, in a real Felix framework. */
class BundleHealthTest {

    @TempDir
    Path dir;

    private Framework framework;

    @BeforeEach
    void startFramework() throws BundleException {
        FrameworkFactory factory = ServiceLoader.load(FrameworkFactory.class).findFirst().orElseThrow();
        framework = factory.newFramework(Map.of(Constants.FRAMEWORK_STORAGE, dir.resolve("cache").toString(),
                Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT));
        framework.start();
    }

    @AfterEach
    void stopFramework() throws Exception {
        framework.stop();
        framework.waitForStop(10_000);
    }

    @Test
    void namesOnlyTheBundlesThatShouldRunAndDoNot() throws Exception {
        Bundle host = install("test.host");
        install("test.fragment", Constants.FRAGMENT_HOST, "test.host");
        assertThat(framework.adapt(FrameworkWiring.class).resolveBundles(null)).isTrue();
        host.start();
        install("test.lazy", Constants.BUNDLE_ACTIVATIONPOLICY, Constants.ACTIVATION_LAZY)
                .start(Bundle.START_ACTIVATION_POLICY);
        Bundle unresolvable = install("test.unresolvable", Constants.IMPORT_PACKAGE, "no.such.pkg");
        assertThatThrownBy(unresolvable::start).isInstanceOf(BundleException.class);
        Bundle brokenActivator = install("test.broken.activator", Constants.BUNDLE_ACTIVATOR, "no.such.Activator");
        assertThatThrownBy(brokenActivator::start).isInstanceOf(BundleException.class);
        Bundle later = install("test.later");
        later.adapt(BundleStartLevel.class).setStartLevel(5);
        later.start();

        List<String> problems = BundleHealth.problems(framework.getBundleContext().getBundles(), 1);

        assertThat(problems).hasSize(2);
        assertThat(problems.get(0)).startsWith("bundle test.unresolvable 1.0.0 (id " + unresolvable.getBundleId()
                + ") is not resolved").contains("start " + unresolvable.getBundleId());
        assertThat(problems.get(1)).startsWith("bundle test.broken.activator 1.0.0 (id "
                + brokenActivator.getBundleId() + ") is resolved but not started");
    }

    @Test
    void aBundleAboveTheStartLevelIsLookedAtOnceTheLevelIsIncluded() throws Exception {
        Bundle later = install("test.later");
        later.adapt(BundleStartLevel.class).setStartLevel(5);
        later.start();

        assertThat(BundleHealth.problems(framework.getBundleContext().getBundles(), 1)).isEmpty();
        assertThat(BundleHealth.problems(framework.getBundleContext().getBundles(), Integer.MAX_VALUE))
                .singleElement().asString().startsWith("bundle test.later 1.0.0");
    }

    private Bundle install(String symbolicName, String... headers) throws IOException, BundleException {
        Path jar = TestBundles.write(dir.resolve(symbolicName + ".jar"), symbolicName, headers);
        return framework.getBundleContext().installBundle(jar.toUri().toString());
    }
}
