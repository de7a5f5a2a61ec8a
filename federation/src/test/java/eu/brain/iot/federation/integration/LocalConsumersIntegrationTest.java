package eu.brain.iot.federation.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.Base64;
import java.util.Dictionary;
import java.util.Hashtable;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.federation.api.FabricProperties;
import eu.brain.iot.federation.monitoring.api.FabricMonitor;

/**
 * A consumer registered with {@link FabricProperties#LOCAL_ONLY} (the dashboard's) is not part of the node's
 * interest, whether it was there before the node took its configuration or came after, while a behaviour beside it
 * is; the interest the monitor shows is the one the node announces. No broker is needed: the node announces its
 * interest to itself before it reaches one (here a port nothing listens on).
 */
class LocalConsumersIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(30);
    static final String PID = "eu.brain.iot.federation";

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 5000)
    ConfigurationAdmin cm;

    Configuration config;
    final List<ServiceRegistration<?>> registrations = new CopyOnWriteArrayList<>();

    @AfterEach
    void tearDown() throws Exception {
        if (config != null) {
            config.delete();
        }
        registrations.forEach(ServiceRegistration::unregister);
    }

    @Test
    void aLocalOnlyConsumerIsNotAnnouncedToTheFabric() throws Exception {
        consumer("it.Watched", true); // there before the node joins, as the dashboard on a node's start
        consumer("it.Taken", false);

        Path dir = Files.createTempDirectory("fabric-local");
        Path keyFile = dir.resolve("it.key");
        byte[] secret = new byte[32];
        new SecureRandom().nextBytes(secret);
        Files.writeString(keyFile, Base64.getEncoder().encodeToString(secret));
        int nowhere;
        try (ServerSocket s = new ServerSocket(0)) {
            nowhere = s.getLocalPort();
        }
        config = cm.getConfiguration(PID, "?");
        Dictionary<String, Object> cfg = new Hashtable<>();
        cfg.put("broker.uri", "tcp://127.0.0.1:" + nowhere);
        cfg.put("fabric.name", "it-local");
        cfg.put("node.name", "it-local-node");
        cfg.put("key.file", keyFile.toString());
        cfg.put("state.dir", dir.resolve("state").toString());
        config.update(cfg);

        await().atMost(DEADLINE).until(() -> eventTypes().contains("it.Taken"));
        assertThat(eventTypes()).as("the local-only consumer is not announced").doesNotContain("it.Watched");

        consumer("it.WatchedLater", true); // and one that comes after the node took its configuration
        consumer("it.TakenLater", false);
        await().atMost(DEADLINE).until(() -> eventTypes().contains("it.TakenLater"));
        assertThat(eventTypes()).containsExactly("it.Taken", "it.TakenLater");
    }

    private void consumer(String type, boolean localOnly) {
        Dictionary<String, Object> props = new Hashtable<>();
        props.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { type });
        if (localOnly) {
            props.put(FabricProperties.LOCAL_ONLY, Boolean.TRUE);
        }
        registrations.add(context.registerService(UntypedSmartBehaviour.class,
                (UntypedSmartBehaviour) (t, fields) -> { }, props));
    }

    /** The event types this node announces, as its monitor shows them; empty while it has no configuration. */
    private List<String> eventTypes() {
        ServiceReference<FabricMonitor> ref = context.getServiceReference(FabricMonitor.class);
        if (ref == null) {
            return List.of();
        }
        try {
            List<String> types = context.getService(ref).status().eventTypes;
            return types == null ? List.of() : types;
        } finally {
            context.ungetService(ref);
        }
    }
}
