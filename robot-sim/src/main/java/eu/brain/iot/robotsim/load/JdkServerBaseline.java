package eu.brain.iot.robotsim.load;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import eu.brain.iot.robotsim.cli.Flags;
import eu.brain.iot.robotsim.cli.UsageException;
import eu.brain.iot.robotsim.view.Json;
import eu.brain.iot.robotsim.view.RobotView;
import eu.brain.iot.robotsim.world.MapGenerator;
import eu.brain.iot.robotsim.world.SimRules;
import eu.brain.iot.robotsim.world.WarehouseMap;
import eu.brain.iot.robotsim.world.World;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Executors;

/**
 * The measurement behind choosing Netty: the JDK's built-in {@code com.sun.net.httpserver} serving the same
 * pre-serialized robot states on the same paths, to be polled with {@code poll-load}. Not used by the simulator.
 * <pre>java -cp robot-sim.jar eu.brain.iot.robotsim.load.JdkServerBaseline --port 18092 --robots 10000 --threads 2</pre>
 */
public final class JdkServerBaseline {
    private JdkServerBaseline() {
    }

    public static void main(String[] args) throws IOException {
        try {
            Flags f = Flags.parse(args, Set.of("port", "robots", "threads"), Set.of());
            int port = f.intValue("port", 18092, 1, 65535);
            int robots = f.intValue("robots", 10_000, 1, 1_000_000);
            int threads = f.intValue("threads", 0, 0, 1024);
            serve(port, robots, threads);
        } catch (UsageException e) {
            System.err.println("jdk-baseline: " + e.getMessage()
                    + "\nUsage: --port N --robots N --threads N (0 = handlers on the dispatcher thread)");
            System.exit(2);
        }
    }

    private static void serve(int port, int robots, int threads) throws IOException {
        WarehouseMap map = MapGenerator.generate(400, 150, robots, 0, 10, 1);
        World world = new World(map, SimRules.DEFAULT);
        Map<String, byte[]> states = new HashMap<>();
        List<String> ids = new ArrayList<>();
        for (int i = 0; i < world.robotCount(); i++) {
            RobotView v = RobotView.of(world, world.robot(i));
            states.put("/" + v.id() + "/robot_local_control/state", Json.bytes(v));
            ids.add(v.id());
        }
        byte[] index = Json.bytes(Map.of("robots", ids));
        HttpServer server = HttpServer.create(new InetSocketAddress("127.0.0.1", port), 4096);
        server.createContext("/", exchange -> {
            String path = exchange.getRequestURI().getPath();
            byte[] body = path.equals("/") ? index : states.get(path);
            answer(exchange, body == null ? 404 : 200, body == null ? new byte[0] : body);
        });
        if (threads > 0) {
            server.setExecutor(Executors.newFixedThreadPool(threads));
        }
        server.start();
        System.out.println("jdk-baseline: " + robots + " robots on http://127.0.0.1:" + port + "/, "
                + (threads > 0 ? threads + " handler threads" : "handlers on the dispatcher thread"));
    }

    private static void answer(HttpExchange exchange, int status, byte[] body) throws IOException {
        exchange.getResponseHeaders().set("Content-Type", "application/json");
        exchange.sendResponseHeaders(status, body.length == 0 ? -1 : body.length);
        try (OutputStream out = exchange.getResponseBody()) {
            out.write(body);
        }
    }
}
