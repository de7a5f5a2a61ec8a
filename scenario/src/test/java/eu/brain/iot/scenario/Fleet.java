package eu.brain.iot.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.world.MapParser;
import eu.brain.iot.robotsim.world.SimRules;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;

/**
 * A robot-sim in manual-step mode driven as the behaviours would drive it, by REST commands, to capture ground-truth
 * documents ({@code GET /world}) for the judge. Test-thread confined.
 */
final class Fleet implements AutoCloseable {
    private static final ObjectMapper JSON = new ObjectMapper();
    final RobotSim sim;
    private final HttpClient http = HttpClient.newHttpClient();

    private Fleet(RobotSim sim) {
        this.sim = sim;
    }

    /** The paper's warehouse, its deadlock threshold at the 10 s wait limit (20 steps). */
    static Fleet paper() throws IOException {
        return new Fleet(RobotSim.start(SimConfig.builder().manualStep(true)
                .rules(new SimRules(1, 2, 2, 20, -1)).build()));
    }

    static Fleet of(String mapText, int deadlockSteps) throws Exception {
        return new Fleet(RobotSim.start(SimConfig.builder().manualStep(true).map(MapParser.parse("test.map", mapText))
                .rules(new SimRules(1, 2, 2, deadlockSteps, -1)).build()));
    }

    /** POSTs a command; returns the HTTP status. */
    int post(String path, String body) throws IOException, InterruptedException {
        return http.send(HttpRequest.newBuilder(sim.baseUri().resolve(path)).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(body)).build(), HttpResponse.BodyHandlers.ofString())
                .statusCode();
    }

    int goTo(String robot, int x, int y) throws IOException, InterruptedException {
        return post(robot + "/robot_local_control/NavigationComponent/GoToComponent/add",
                "{\"x\":" + x + ",\"y\":" + y + "}");
    }

    int pick(String robot) throws IOException, InterruptedException {
        return post(robot + "/robot_local_control/NavigationComponent/PickComponent/add", "{}");
    }

    int place(String robot) throws IOException, InterruptedException {
        return post(robot + "/robot_local_control/NavigationComponent/PlaceComponent/add", "{}");
    }

    int openDoor() throws IOException, InterruptedException {
        return post("door1/door_controller/command", "{\"data\":1.0}");
    }

    void step(int n) {
        sim.step(n);
    }

    /** {@code GET /world} over HTTP, as the runner's judge reads it. */
    WorldSnapshot world() throws IOException, InterruptedException {
        String body = http.send(HttpRequest.newBuilder(sim.baseUri().resolve("world")).GET().build(),
                HttpResponse.BodyHandlers.ofString()).body();
        JsonNode doc = JSON.readTree(body);
        return new WorldSnapshot(doc);
    }

    URI base() {
        return sim.baseUri();
    }

    @Override
    public void close() {
        sim.close();
    }
}
