package eu.brain.iot.edge.impl;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;

import eu.brain.iot.robotsim.RobotSim;

/** Injects and clears the simulator's faults through its admin REST API, as an operator would. */
final class SimAdmin {

    private static final HttpClient HTTP = HttpClient.newHttpClient();

    private SimAdmin() {
    }

    static void fault(RobotSim sim, String robot, String json) {
        send(HttpRequest.newBuilder(sim.baseUri().resolve("admin/faults/" + robot))
                .header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(json)).build());
    }

    static void clear(RobotSim sim, String robot) {
        send(HttpRequest.newBuilder(sim.baseUri().resolve("admin/faults/" + robot))
                .header("Content-Type", "application/json").DELETE().build());
    }

    private static void send(HttpRequest request) {
        try {
            HttpResponse<String> answer = HTTP.send(request, HttpResponse.BodyHandlers.ofString());
            if (answer.statusCode() != 200) {
                throw new IllegalStateException(request.uri() + " answered " + answer.statusCode() + ": "
                        + answer.body());
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
    }
}
