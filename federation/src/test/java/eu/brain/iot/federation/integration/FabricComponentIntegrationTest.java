package eu.brain.iot.federation.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Base64;
import java.util.Dictionary;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

import org.eclipse.paho.mqttv5.client.IMqttToken;
import org.eclipse.paho.mqttv5.client.MqttAsyncClient;
import org.eclipse.paho.mqttv5.client.MqttCallback;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.MqttDisconnectResponse;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttMessage;
import org.eclipse.paho.mqttv5.common.packet.MqttProperties;
import org.eclipse.paho.mqttv5.common.packet.UserProperty;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.service.component.runtime.ServiceComponentRuntime;
import org.osgi.service.component.runtime.dto.ComponentConfigurationDTO;
import org.osgi.service.log.LogEntry;
import org.osgi.service.log.LogReaderService;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import org.osgi.util.promise.Promise;
import org.osgi.util.promise.Promises;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.edge.model.api.DeviceOwnership;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.eventing.spi.EventForwarder;
import eu.brain.iot.federation.monitoring.api.FabricMonitor;

/**
 * The federation bundle in a real Felix with the real bus, joined to a real Mosquitto (a process started by the test
 * on a free port; skipped where it is not installed). The test plays a second node by hand with its own MQTT client
 * and the fabric's key: it sees this node's signed interest, announces its own, receives the events this node's bus
 * routes to it, and sends an event that this node's behaviour receives and acknowledges.
 */
class FabricComponentIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(30);
    static final Path MOSQUITTO = Path.of("/usr/sbin/mosquitto");
    static final String PID = "eu.brain.iot.federation";
    static final String BASE = "brainiot/it/nodes/";

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 5000)
    EventBus bus;

    @InjectService(timeout = 5000)
    ConfigurationAdmin cm;

    @InjectService(timeout = 5000)
    ServiceComponentRuntime scr;

    final ObjectMapper json = new ObjectMapper();
    Process mosquitto;
    MqttAsyncClient peer;
    Configuration config;
    ServiceRegistration<?> behaviourReg;
    ServiceRegistration<?> installerReg;
    ServiceRegistration<?> ownershipReg;
    final Map<String, byte[]> retained = new ConcurrentHashMap<>();
    final List<String> received = new CopyOnWriteArrayList<>();
    final Map<String, String> signatures = new ConcurrentHashMap<>();

    @AfterEach
    void tearDown() throws Exception {
        if (config != null) {
            config.delete();
        }
        if (behaviourReg != null) {
            behaviourReg.unregister();
        }
        if (installerReg != null) {
            installerReg.unregister();
        }
        if (ownershipReg != null) {
            ownershipReg.unregister();
        }
        if (peer != null) {
            peer.disconnectForcibly(0, 1, false);
            peer.close(true);
        }
        if (mosquitto != null) {
            mosquitto.destroy();
            mosquitto.waitFor(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void withoutItsConfigurationTheNodeRunsAlone() throws Exception {
        assertThat(context.getServiceReference("eu.brain.iot.federation.impl.FabricComponent")).isNull();
        assertThat(command("nodes")).contains("not a member of a fabric").contains(PID);
    }

    @Test
    void aConfiguredNodeJoinsRoutesByInterestAndAcknowledges() throws Exception {
        Assumptions.assumeTrue(Files.isExecutable(MOSQUITTO),
                "Mosquitto is not installed (" + MOSQUITTO + " missing: apt-get install mosquitto): skipped");
        Path dir = Files.createTempDirectory("fabric-it");
        int port = freePort();
        Path conf = dir.resolve("mosquitto.conf");
        Files.writeString(conf, "listener " + port + " 127.0.0.1\nallow_anonymous true\n");
        mosquitto = new ProcessBuilder(MOSQUITTO.toString(), "-c", conf.toString()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("mosquitto.log").toFile()).start();
        await().atMost(DEADLINE).until(() -> listening(port));

        Path keyFile = dir.resolve("it.key");
        assertThat(command("keygen", keyFile.toString())).contains("fabric key written");
        byte[] key = Base64.getDecoder().decode(Files.readString(keyFile).trim());

        // this node's behaviour, registered as any behaviour is
        List<Map<String, ?>> got = new CopyOnWriteArrayList<>();
        Dictionary<String, Object> props = new Hashtable<>();
        props.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { "it.Ping" });
        behaviourReg = context.registerService(UntypedSmartBehaviour.class,
                (UntypedSmartBehaviour) (type, fields) -> got.add(fields), props);

        connectPeer(port);
        config = cm.getConfiguration(PID, "?");
        Dictionary<String, Object> cfg = new Hashtable<>();
        cfg.put("broker.uri", "tcp://127.0.0.1:" + port);
        cfg.put("fabric.name", "it");
        cfg.put("node.name", "it-node");
        cfg.put("key.file", keyFile.toString());
        cfg.put("state.dir", dir.resolve("state").toString());
        cfg.put("keep.alive.s", 2);
        cfg.put("resend.timeout.ms", 1000L);
        config.update(cfg);

        // its interest, retained and signed with the fabric's key
        String interestTopic = BASE + "it-node/interest";
        try {
            await().atMost(DEADLINE).until(() -> retained.containsKey(interestTopic)
                    && new String(retained.get(interestTopic), StandardCharsets.UTF_8).contains("it.Ping"));
        } catch (org.awaitility.core.ConditionTimeoutException e) {
            throw new AssertionError("no interest announced; fabric:nodes says: " + command("nodes") + "; log: "
                    + log() + threads(), e);
        }
        // (a later announcement may replace both between two reads: its own signature then follows)
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(signatures.get(interestTopic))
                .isEqualTo(sign(key, interestTopic, retained.get(interestTopic))));
        // an unsigned message claiming a name no verified message came from: in the monitor's total of such
        peer.publish(BASE + "stranger/status", new MqttMessage("{}".getBytes(StandardCharsets.UTF_8), 1, false,
                new MqttProperties())).waitForCompletion(10_000);
        FabricMonitor monitor = context.getService(context.getServiceReference(FabricMonitor.class));
        await().atMost(DEADLINE).until(() -> monitor.unverifiedRefused() == 1);

        // the peer announces itself: this node registers a forwarder for it and routes it.Pong there
        long now = System.currentTimeMillis();
        publish(key, BASE + "peer/status", "{\"node\":\"peer\",\"state\":\"online\",\"sent\":" + now + "}", true);
        publish(key, BASE + "peer/interest", "{\"node\":\"peer\",\"sent\":" + now
                + ",\"entries\":[{\"types\":[\"it.Pong\"],\"filter\":\"(n>=1)\"}]}", true);
        await().atMost(DEADLINE).until(() -> forwarderTo("peer") != null);

        // a Last Will of a connection the peer replaced already (a broker restarted with its sessions publishes it
        // late) does not take the peer offline; its current connection's does, and its next online brings it back
        publish(key, BASE + "peer/status", "{\"node\":\"peer\",\"state\":\"online\",\"sent\":" + now
                + ",\"since\":" + (now + 2) + "}", true);
        publish(key, BASE + "peer/status", "{\"node\":\"peer\",\"state\":\"offline\",\"sent\":" + now
                + ",\"since\":" + (now + 1) + "}", true);
        // then an interest with one more entry: once its forwarder is there, the statuses before it were applied
        publish(key, BASE + "peer/interest", "{\"node\":\"peer\",\"sent\":" + (now + 1) + ",\"entries\":[{\"types\":"
                + "[\"it.Pong\"],\"filter\":\"(n>=1)\"},{\"types\":[\"it.Marker\"]}]}", true);
        await().atMost(DEADLINE).until(() -> forwarderFor("it.Marker") != null);
        assertThat(forwarderTo("peer")).as("a late Last Will is ignored").isNotNull();
        publish(key, BASE + "peer/status", "{\"node\":\"peer\",\"state\":\"offline\",\"sent\":" + now
                + ",\"since\":" + (now + 2) + "}", true);
        await().atMost(DEADLINE).until(() -> forwarderTo("peer") == null);
        publish(key, BASE + "peer/status", "{\"node\":\"peer\",\"state\":\"online\",\"sent\":" + now
                + ",\"since\":" + (now + 3) + "}", true);
        await().atMost(DEADLINE).until(() -> forwarderTo("peer") != null);
        bus.deliver("it.Pong", Map.of("n", 0)); // the peer's filter does not take it
        bus.deliver("it.Pong", Map.of("n", 1));
        String eventsTopic = BASE + "peer/events/it-node";
        await().atMost(DEADLINE).until(() -> received.stream().anyMatch(m -> m.startsWith(eventsTopic)));
        String batch = received.stream().filter(m -> m.startsWith(eventsTopic)).findFirst().orElseThrow()
                .substring(eventsTopic.length() + 1);
        JsonNode events = json.readTree(batch).path("events");
        assertThat(events.size()).isEqualTo(1);
        assertThat(events.get(0).path("type").asText()).isEqualTo("it.Pong");
        assertThat(events.get(0).path("data").path("n").asInt()).isEqualTo(1);

        // the peer sends an event: this node's behaviour gets it, and the peer gets an acknowledgement
        publish(key, BASE + "it-node/events/peer", "{\"from\":\"peer\",\"to\":\"it-node\",\"epoch\":\"e1\",\"sent\":"
                + System.currentTimeMillis() + ",\"events\":[{\"seq\":1,\"type\":\"it.Ping\",\"types\":[\"it.Ping\"],"
                + "\"data\":{\"n\":5}}]}", false);
        await().atMost(DEADLINE).until(() -> got.size() == 1);
        assertThat(((Number) got.get(0).get("n")).intValue()).isEqualTo(5);
        String acks = BASE + "peer/acks/it-node";
        await().atMost(DEADLINE).until(() -> received.stream().anyMatch(m -> m.startsWith(acks)
                && m.contains("\"through\":1")));
        assertThat(command("nodes")).contains("peer").contains("online");
        assertThat(command("stats")).contains("peer");

        // a behaviour that comes after the node joined (e.g. a bundle started later) is announced at once, with an
        // empty filter meaning none
        Dictionary<String, Object> lateProps = new Hashtable<>();
        lateProps.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { "it.Late" });
        lateProps.put(SmartBehaviourNamespace.FILTER_PROPERTY, "");
        ServiceRegistration<UntypedSmartBehaviour> late = context.registerService(UntypedSmartBehaviour.class,
                (UntypedSmartBehaviour) (type, fields) -> { }, lateProps);
        try {
            await().atMost(DEADLINE).until(() -> {
                JsonNode entries = json.readTree(retained.get(interestTopic)).path("entries");
                for (JsonNode e : entries) {
                    if (e.path("types").toString().contains("it.Late")) {
                        return e.path("filter").isNull();
                    }
                }
                return false;
            });
        } finally {
            late.unregister();
        }
        await().atMost(DEADLINE).until(() -> !new String(retained.get(interestTopic), StandardCharsets.UTF_8)
                .contains("it.Late"));

        // the node's own installer: the fabric's is registered above it (the BMS takes the best-ranked one), and
        // answers the peer's signed bid from it, saying which of the devices the bid names this node's edge owns
        installerReg = context.registerService(BundleInstaller.class, new OwnInstaller(), null);
        ownershipReg = context.registerService(DeviceOwnership.class, new EdgeOwning("robot2"), null);
        await().atMost(DEADLINE).until(() -> active("eu.brain.iot.federation.impl.EdgeOwnedDevices"));
        await().atMost(DEADLINE).until(() -> fabricInstaller() != null);
        assertThat(fabricInstaller().getProperty(Constants.SERVICE_RANKING)).isEqualTo(100);
        assertThat(context.getServiceReference(BundleInstaller.class)).as("the best-ranked installer")
                .isEqualTo(fabricInstaller());
        publish(key, BASE + "it-node/install/peer", "{\"op\":\"bid\",\"from\":\"peer\",\"to\":\"it-node\","
                + "\"sent\":" + System.currentTimeMillis() + ",\"id\":\"q1\",\"types\":[\"it.Nobody\"],"
                + "\"devices\":[\"robot1\",\"robot2\"]}", false);
        String offers = BASE + "peer/install/it-node";
        await().atMost(DEADLINE).until(() -> received.stream().anyMatch(m -> m.startsWith(offers)));
        String offerText = received.stream().filter(m -> m.startsWith(offers)).findFirst().orElseThrow()
                .substring(offers.length() + 1);
        JsonNode offer = json.readTree(offerText);
        assertThat(offer.path("op").asText()).isEqualTo("offer");
        assertThat(offer.path("id").asText()).isEqualTo("q1");
        assertThat(offer.path("candidates").get(0).path("symbolicName").asText()).isEqualTo("it.behaviour");
        assertThat(offer.path("owns").toString()).isEqualTo("[\"robot2\"]");
        assertThat(signatures.get(offers)).isEqualTo(sign(key, offers, offerText.getBytes(StandardCharsets.UTF_8)));
        installerReg.unregister();
        installerReg = null;
        await().atMost(DEADLINE).until(() -> fabricInstaller() == null);

        // without its configuration the node leaves: offline, no forwarder left
        config.delete();
        config = null;
        await().atMost(DEADLINE).until(() -> forwarderTo("peer") == null);
        await().atMost(DEADLINE).until(() -> retained.containsKey(BASE + "it-node/status") && new String(
                retained.get(BASE + "it-node/status"), StandardCharsets.UTF_8).contains("offline"));
    }

    private static String threads() {
        StringBuilder out = new StringBuilder();
        Thread.getAllStackTraces().forEach((t, trace) -> {
            if (t.getName().contains("fabric") || t.getName().contains("MQTT")) {
                out.append("\n").append(t.getName()).append(' ').append(t.getState());
                for (int i = 0; i < Math.min(12, trace.length); i++) {
                    out.append("\n    at ").append(trace[i]);
                }
            }
        });
        return out.toString();
    }

    private String log() {
        ServiceReference<LogReaderService> ref = context.getServiceReference(LogReaderService.class);
        if (ref == null) {
            return "(no log reader)";
        }
        StringBuilder out = new StringBuilder();
        java.util.Enumeration<LogEntry> entries = context.getService(ref).getLog();
        while (entries.hasMoreElements()) {
            LogEntry e = entries.nextElement();
            if (e.getLogLevel().ordinal() <= org.osgi.service.log.LogLevel.INFO.ordinal()
                    && !e.getMessage().startsWith("ServiceEvent") && !e.getMessage().startsWith("BundleEvent")) {
                out.append('\n').append(e.getLogLevel()).append(' ').append(e.getMessage())
                        .append(e.getException() == null ? "" : " " + e.getException());
            }
        }
        return out.toString();
    }

    private ServiceReference<?> fabricInstaller() throws Exception {
        ServiceReference<?>[] refs = context.getServiceReferences(BundleInstaller.class.getName(),
                "(eu.brain.iot.fabric.installer=it-node)");
        return refs == null ? null : refs[0];
    }

    private boolean active(String component) {
        return scr.getComponentDescriptionDTOs().stream().filter(d -> d.name.equals(component))
                .flatMap(d -> scr.getComponentConfigurationDTOs(d).stream())
                .anyMatch(c -> c.state == ComponentConfigurationDTO.ACTIVE);
    }

    /** The node's edge, as far as the fabric asks it: it owns one device. */
    record EdgeOwning(String device) implements DeviceOwnership {
        @Override
        public String nodeName() {
            return "it-node";
        }

        @Override
        public Set<String> owned() {
            return Set.of(device);
        }

        @Override
        public Set<String> share() {
            return owned();
        }

        @Override
        public Set<String> fleet() {
            return owned();
        }

        @Override
        public boolean owns(String deviceId) {
            return device.equals(deviceId);
        }

        @Override
        public Set<String> take(Set<String> deviceIds) {
            return Set.of();
        }

        @Override
        public Set<String> release(Set<String> deviceIds) {
            return Set.of();
        }
    }

    /** The node's own installer, as far as the fabric asks it: one behaviour for {@code it.Nobody}. */
    static final class OwnInstaller implements BundleInstaller {
        @Override
        public Promise<List<BehaviourCandidate>> find(List<String> consumedTypes) {
            BehaviourCandidate c = new BehaviourCandidate();
            c.symbolicName = "it.behaviour";
            c.version = "1.0.0";
            c.consumed = List.of("it.Nobody");
            return Promises.resolved(consumedTypes.contains("it.Nobody") ? List.of(c) : List.of());
        }

        @Override
        public Promise<InstalledBehaviour> install(InstallRequest request) {
            return Promises.failed(new UnsupportedOperationException("not asked in this test"));
        }

        @Override
        public Promise<InstalledBehaviour> uninstall(String symbolicName, String reason, boolean byOperator) {
            return Promises.failed(new UnsupportedOperationException("not asked in this test"));
        }

        @Override
        public void allow(String symbolicName) {
        }

        @Override
        public List<InstalledBehaviour> installed() {
            return List.of();
        }
    }

    private ServiceReference<?> forwarderFor(String type) throws Exception {
        ServiceReference<?>[] refs = context.getServiceReferences(EventForwarder.class.getName(),
                "(" + SmartBehaviourNamespace.CONSUMED_PROPERTY + "=" + type + ")");
        return refs == null ? null : refs[0];
    }

    private ServiceReference<?> forwarderTo(String node) throws Exception {
        ServiceReference<?>[] refs = context.getServiceReferences(EventForwarder.class.getName(),
                "(" + EventForwarder.DESTINATION_PROPERTY + "=" + node + ")");
        return refs == null ? null : refs[0];
    }

    private String command(String name, String... args) throws Exception {
        ServiceReference<?> ref = context.getServiceReference("eu.brain.iot.federation.impl.FabricCommands");
        Object commands = context.getService(ref);
        try {
            if (args.length == 0 && name.equals("nodes") || name.equals("stats")) {
                return (String) commands.getClass().getMethod(name).invoke(commands);
            }
            return (String) commands.getClass().getMethod(name, String.class).invoke(commands, args[0]);
        } finally {
            context.ungetService(ref);
        }
    }

    private void connectPeer(int port) throws MqttException {
        peer = new MqttAsyncClient("tcp://127.0.0.1:" + port, "it.peer", new MemoryPersistence());
        peer.setCallback(new MqttCallback() {
            @Override
            public void messageArrived(String topic, MqttMessage message) {
                // the signature before the payload: a test that sees the payload finds its signature
                List<UserProperty> up = message.getProperties().getUserProperties();
                if (up != null) {
                    up.stream().filter(p -> p.getKey().equals("sig")).forEach(p -> signatures.put(topic, p.getValue()));
                }
                if (message.isRetained() || topic.endsWith("/status") || topic.endsWith("/interest")) {
                    retained.put(topic, message.getPayload());
                }
                received.add(topic + " " + new String(message.getPayload(), StandardCharsets.UTF_8));
            }

            @Override
            public void disconnected(MqttDisconnectResponse r) {
            }

            @Override
            public void mqttErrorOccurred(MqttException e) {
            }

            @Override
            public void deliveryComplete(IMqttToken token) {
            }

            @Override
            public void connectComplete(boolean reconnect, String uri) {
            }

            @Override
            public void authPacketArrived(int code, MqttProperties p) {
            }
        });
        peer.connect(new MqttConnectionOptions()).waitForCompletion(10_000);
        peer.subscribe(BASE + "it-node/#", 1).waitForCompletion(10_000);
        peer.subscribe(BASE + "peer/#", 1).waitForCompletion(10_000);
    }

    private void publish(byte[] key, String topic, String payload, boolean retain) throws Exception {
        byte[] bytes = payload.getBytes(StandardCharsets.UTF_8);
        MqttProperties props = new MqttProperties();
        props.setUserProperties(List.of(new UserProperty("sig", sign(key, topic, bytes))));
        peer.publish(topic, new MqttMessage(bytes, 1, retain, props)).waitForCompletion(10_000);
    }

    static String sign(byte[] key, String topic, byte[] payload) throws Exception {
        Mac mac = Mac.getInstance("HmacSHA256");
        mac.init(new SecretKeySpec(key, "HmacSHA256"));
        mac.update(topic.getBytes(StandardCharsets.UTF_8));
        mac.update((byte) 0);
        return Base64.getEncoder().encodeToString(mac.doFinal(payload));
    }

    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    static boolean listening(int port) {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            return true;
        } catch (IOException e) {
            return false;
        }
    }
}
