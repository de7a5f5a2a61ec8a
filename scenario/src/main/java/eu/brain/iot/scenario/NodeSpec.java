package eu.brain.iot.scenario;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * One fabric node of a run, before it starts: its name, its place among the run's nodes (its share of the fleet is
 * {@code number/of}), its folder (configuration, state, journal, federation state, log) and the port of its REST API.
 * One node alone keeps the run's folder as its own, as it always did; node K of several has {@code <run>/nodeK}.
 *
 * @param name     the node's name ({@code fabric.node.name}), or null: one node alone, the node's default name
 * @param number   K, from 1
 * @param of       N, how many nodes the run has
 * @param folder   the node's folder
 * @param httpPort its REST API's port on 127.0.0.1
 */
record NodeSpec(String name, int number, int of, Path folder, int httpPort) {

    /** The nodes of a run: one in the run's folder, or node1..nodeN each in a folder of its own, on free ports. */
    static List<NodeSpec> forRun(Options o) throws IOException {
        if (o.nodes() < 2) {
            return List.of(new NodeSpec(o.fabric() == null ? null : Options.Fabric.NODE, 1, 1, o.runDir(),
                    NodeSetup.freePort()));
        }
        List<NodeSpec> nodes = new ArrayList<>();
        List<Integer> ports = new ArrayList<>();
        for (int k = 1; k <= o.nodes(); k++) {
            int port = NodeSetup.freePort();
            while (ports.contains(port)) { // the system may hand out a port again once its socket is closed
                port = NodeSetup.freePort();
            }
            ports.add(port);
            String name = Options.nodeName(k);
            nodes.add(new NodeSpec(name, k, o.nodes(), o.runDir().resolve(name), port));
        }
        return List.copyOf(nodes);
    }

    /** One of several nodes (a fabric of nodes sharing the fleet). */
    boolean shared() {
        return of >= 2;
    }

    /** The name as the runner prints it: {@code node} for one node alone. */
    String label() {
        return shared() ? name : "node";
    }

    Path configDir() {
        return folder.resolve("node-config");
    }

    Path log() {
        return folder.resolve("node.log");
    }
}
