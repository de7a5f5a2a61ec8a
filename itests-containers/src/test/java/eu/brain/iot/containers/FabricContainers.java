package eu.brain.iot.containers;

import com.github.dockerjava.api.DockerClient;
import com.github.dockerjava.api.exception.DockerException;
import com.github.dockerjava.api.model.Container;
import java.nio.charset.StandardCharsets;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Base64;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import org.testcontainers.DockerClientFactory;
import org.testcontainers.containers.GenericContainer;
import org.testcontainers.containers.Network;
import org.testcontainers.images.builder.Transferable;
import org.testcontainers.lifecycle.Startables;

/**
 * The broker, robot-sim and fabric nodes, each in a container of its own on a network made for one test class,
 * reachable from the others by their names ({@code broker}, {@code robot-sim}, the node's name). Ryuk is off (no
 * registry to pull it from), so {@link #close} stops and removes every container and the network, and
 * {@link #removeLeftovers} removes what a killed run left (by the label {@value TestSettings#LABEL}).
 *
 * <p>Threads: used by the test thread only; Testcontainers follows the containers' logs on threads of its own.
 */
final class FabricContainers implements AutoCloseable {
    static final int MQTT_PORT = 1883;
    static final int HTTP_PORT = 8181;
    static final int FLEET_PORT = 8090;
    static final String BROKER = "broker";
    static final String ROBOT_SIM = "robot-sim";
    /** The line a node prints when its bus, installer and BMS are up. */
    static final String NODE_READY = "fabric node ready in";
    /** A node's configuration folder in its container (Apache Felix File Install watches it: .cfg files, bundles). */
    static final String CONFIG_DIR = "/app/node/config/";
    private static final Duration START_TIMEOUT = Duration.ofMinutes(3);
    /** Heap of each JVM in a container: the fabric's processes need far less; 2 cores, several JVMs. */
    private static final String HEAP = "-Xmx384m";
    /** A port where nothing answers: the edge of a node that owns no robots polls it. */
    private static final int NO_FLEET_PORT = 9;

    private final TestSettings settings;
    private final FabricImages.Names images;
    private final String runId = HexFormat.of().formatHex(new SecureRandom().generateSeed(3));
    private final Network network;
    private final List<GenericContainer<?>> containers = new ArrayList<>();

    FabricContainers(TestSettings settings) {
        this.settings = settings;
        removeLeftovers(settings);
        this.images = FabricImages.build(settings);
        this.network = Network.builder().createNetworkCmdModifier(cmd -> cmd
                .withName(settings.prefix() + "net-" + runId)
                .withLabels(Map.of(TestSettings.LABEL, settings.prefix()))).build();
    }

    /** The embedded broker (HiveMQ CE), file persistence in the container, MQTT on {@code broker:1883}. */
    GenericContainer<?> broker() {
        return start(BROKER, new GenericContainer<>(images.broker())
                .withCommand(HEAP, "-jar", "/app/broker.jar", "--port", String.valueOf(MQTT_PORT), "--bind", "0.0.0.0",
                        "--data", "/data/broker")
                .withExposedPorts(MQTT_PORT)
                .waitingFor(new LogLineWait("^broker listening on ")));
    }

    /**
     * The simulated warehouse, the paper's map, on {@code robot-sim:8090}.
     *
     * @param options more of robot-sim's options ({@code --seed}, {@code --speed}, ...)
     */
    GenericContainer<?> robotSim(String... options) {
        List<String> command = new ArrayList<>(List.of(HEAP, "-jar", "/app/robot-sim.jar", "--port",
                String.valueOf(FLEET_PORT), "--bind", "0.0.0.0", "--allow-host", ROBOT_SIM, "--quiet"));
        command.addAll(List.of(options));
        return start(ROBOT_SIM, new GenericContainer<>(images.robotSim())
                .withCommand(command.toArray(String[]::new))
                .withExposedPorts(FLEET_PORT)
                .waitingFor(new LogLineWait("^listening on ")));
    }

    /**
     * A fabric node named {@code name}: its REST API on every interface of its container (so with a token, which the
     * test gives it), its configuration folder {@code /app/node/config} holding the Bundle Installer's file and
     * the given files, the fleet polled at {@code robot-sim:8090} when {@code ownsFleet}.
     *
     * @param configFiles file name to content, dropped into the node's configuration folder before it starts
     */
    NodeContainer node(String name, boolean ownsFleet, Map<String, String> configFiles) {
        return node(name, ownsFleet, configFiles, Map.of());
    }

    /**
     * The same, with more files copied into the container before it starts.
     *
     * @param files path in the container to the file's content and mode
     */
    NodeContainer node(String name, boolean ownsFleet, Map<String, String> configFiles,
            Map<String, Transferable> files) {
        NodeContainer node = prepareNode(name, ownsFleet, configFiles, files);
        start(name, node.container());
        return node;
    }

    /**
     * Several nodes started at once (as the nodes of one site would be), each as {@link #node} makes it with the
     * fleet at {@code robot-sim:8090} (what each polls of it is its configuration's edge share).
     *
     * @param configFiles per node's name, the files for its configuration folder
     */
    List<NodeContainer> nodesTogether(Map<String, Map<String, String>> configFiles, Map<String, Transferable> files) {
        List<NodeContainer> nodes = new ArrayList<>();
        configFiles.forEach((name, config) -> {
            NodeContainer node = prepareNode(name, true, config, files);
            containers.add(configure(name, node.container()));
            nodes.add(node);
        });
        Startables.deepStart(nodes.stream().map(NodeContainer::container)).join();
        return nodes;
    }

    private NodeContainer prepareNode(String name, boolean ownsFleet, Map<String, String> configFiles,
            Map<String, Transferable> files) {
        String fleet = ownsFleet ? "http://" + ROBOT_SIM + ":" + FLEET_PORT + "/" : "http://127.0.0.1:" + NO_FLEET_PORT + "/";
        String token = newToken();
        GenericContainer<?> c = new GenericContainer<>(images.node())
                .withCommand(HEAP, "-Dgosh.args=--nointeractive", "-Dorg.apache.felix.http.host=0.0.0.0",
                        "-Dorg.osgi.service.http.port=" + HTTP_PORT, "-Dfabric.node.name=" + name,
                        "-Dfabric.node.root=/app", "-Dfelix.fileinstall.dir=" + CONFIG_DIR,
                        "-Deu.brain.iot.edge.fleet.url=" + fleet, "-jar", "/app/fabric-node.jar")
                .withExposedPorts(HTTP_PORT)
                .withCopyToContainer(Transferable.of(token.getBytes(StandardCharsets.UTF_8), 0600),
                        "/root/.config/brain-iot/" + name + "/api-token")
                .waitingFor(new LogLineWait("^" + NODE_READY));
        configFiles.forEach((file, content) -> c.withCopyToContainer(
                Transferable.of(content.getBytes(StandardCharsets.UTF_8), 0644), CONFIG_DIR + file));
        files.forEach((path, content) -> c.withCopyToContainer(content, path));
        return new NodeContainer(name, token, c);
    }

    private GenericContainer<?> start(String alias, GenericContainer<?> c) {
        containers.add(configure(alias, c));
        c.start();
        return c;
    }

    private GenericContainer<?> configure(String alias, GenericContainer<?> c) {
        return c.withNetwork(network).withNetworkAliases(alias)
                .withLabels(Map.of(TestSettings.LABEL, settings.prefix()))
                .withCreateContainerCmdModifier(cmd -> cmd.withName(settings.prefix() + alias + "-" + runId))
                .withStartupTimeout(START_TIMEOUT);
    }

    /** The embedded broker's URI as the nodes see it. */
    static String brokerUriInNetwork() {
        return "tcp://" + BROKER + ":" + MQTT_PORT;
    }

    private static String newToken() {
        byte[] random = new byte[32];
        new SecureRandom().nextBytes(random);
        return Base64.getUrlEncoder().withoutPadding().encodeToString(random);
    }

    /** Stops and removes every container this made, then the network. */
    @Override
    public void close() {
        for (int i = containers.size() - 1; i >= 0; i--) {
            GenericContainer<?> c = containers.get(i);
            try {
                c.stop();
            } catch (RuntimeException e) {
                System.out.println("container tests: could not stop " + c.getContainerName() + ": " + e);
            }
        }
        network.close();
    }

    /** Removes containers and networks carrying this prefix's label (left by a run that was killed). */
    static void removeLeftovers(TestSettings settings) {
        DockerClient docker = DockerClientFactory.instance().client();
        String label = TestSettings.LABEL + "=" + settings.prefix();
        for (Container c : docker.listContainersCmd().withShowAll(true).withLabelFilter(List.of(label)).exec()) {
            try {
                docker.removeContainerCmd(c.getId()).withForce(true).withRemoveVolumes(true).exec();
                System.out.println("container tests: removed the container " + String.join(",", c.getNames())
                        + " left by an earlier run");
            } catch (DockerException e) {
                System.out.println("container tests: could not remove " + c.getId() + ": " + e.getMessage());
            }
        }
        for (com.github.dockerjava.api.model.Network n : docker.listNetworksCmd()
                .withFilter("label", List.of(label)).exec()) {
            try {
                docker.removeNetworkCmd(n.getId()).exec();
            } catch (DockerException e) {
                System.out.println("container tests: could not remove the network " + n.getName() + ": "
                        + e.getMessage());
            }
        }
    }
}
