package eu.brain.iot.benchmarks.robotsim;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import eu.brain.iot.robotsim.cli.CliErrors;
import eu.brain.iot.robotsim.cli.Values;
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
import java.util.concurrent.Callable;
import java.util.concurrent.Executors;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * The measurement behind choosing Netty: the JDK's built-in {@code com.sun.net.httpserver} serving the same
 * pre-serialized robot states on the same paths, to be polled with {@code poll-load}. Not used by the simulator.
 * The server's threads are the JDK's (its dispatcher, and the handler pool when {@code --threads} is above 0); they
 * only read the maps built before it starts.
 * <pre>java -cp benchmarks/target/benchmarks.jar eu.brain.iot.benchmarks.robotsim.JdkServerBaseline --port 18092 --robots 10000 --threads 2</pre>
 */
@Command(name = "jdk-baseline", sortOptions = false, usageHelpWidth = 120,
        customSynopsis = "java -cp benchmarks/target/benchmarks.jar "
                + "eu.brain.iot.benchmarks.robotsim.JdkServerBaseline [options]")
public final class JdkServerBaseline implements Callable<Integer> {
    /** What {@link #call()} returns: the server was started and keeps running. */
    static final int RUNNING = -1;

    @Spec
    private CommandSpec spec;
    private int port = 18092;
    private int robots = 10_000;
    private int threads;

    @Option(names = {"--help", "-h"}, usageHelp = true, order = 4, description = "show this help")
    private boolean help;

    private JdkServerBaseline() {
    }

    public static void main(String[] args) {
        int code = CliErrors.install(new CommandLine(new JdkServerBaseline()), "jdk-baseline", false, System.out,
                System.err).execute(args);
        if (code != RUNNING) {
            System.exit(code);
        }
    }

    @Option(names = "--port", paramLabel = "N", order = 1, description = "port to listen on (default 18092)")
    void port(String v) {
        port = Values.wholeInt(spec, "--port", v, 1, 65535);
    }

    @Option(names = "--robots", paramLabel = "N", order = 2, description = "robots served (default 10000)")
    void robots(String v) {
        robots = Values.wholeInt(spec, "--robots", v, 1, 1_000_000);
    }

    @Option(names = "--threads", paramLabel = "N", order = 3,
            description = "handler threads (default 0: handlers on the dispatcher thread)")
    void threads(String v) {
        threads = Values.wholeInt(spec, "--threads", v, 0, 1024);
    }

    @Override
    public Integer call() throws IOException {
        serve(port, robots, threads);
        return RUNNING;
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
