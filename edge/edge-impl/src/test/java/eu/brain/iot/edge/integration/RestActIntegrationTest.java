package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static eu.brain.iot.edge.integration.EdgeTestSupport.json;
import static eu.brain.iot.edge.integration.RestReadIntegrationTest.assertError;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.net.http.HttpResponse;

import org.junit.jupiter.api.Test;

import com.fasterxml.jackson.databind.JsonNode;


/** ACT on the edge's REST API: commands reach the simulated devices, refusals and bad input say why. */
class RestActIntegrationTest extends EdgeRestTestBase {

    private static final String GOTO = "/sensinact/providers/%s/services/control/resources/goTo/act";

    @Test
    void goToMovesTheRobot() throws Exception {
        HttpResponse<String> r = edge.post(GOTO.formatted("robot3"), "{\"x\":9,\"y\":3}");
        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        JsonNode outcome = json(r);
        assertThat(outcome.get("accepted").asBoolean()).isTrue();
        assertThat(outcome.get("provider").asText()).isEqualTo("robot3");
        assertThat(outcome.get("action").asText()).isEqualTo("goTo");
        assertThat(outcome.get("missionId").isIntegralNumber()).isTrue();

        edge.sim.step(8); // from (6,1): 3 cells east, 2 south, with steps to spare
        assertThat(edge.sim.robot("robot3").x()).isEqualTo(9);
        await().atMost(DEADLINE).untilAsserted(() -> {
            JsonNode position = json(edge.get("/sensinact/providers/robot3/services/position")).get("resources");
            assertThat(position.get("x").get("value").asInt()).isEqualTo(9);
            assertThat(position.get("y").get("value").asInt()).isEqualTo(3);
        });
    }

    @Test
    void openMovesTheDoor() throws Exception {
        HttpResponse<String> r = edge.post("/sensinact/providers/door1/services/control/resources/open/act", "");
        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(json(r).get("command").asText()).isEqualTo("OpenDoorCommand");
        edge.sim.step(4); // the paper's door takes 4 steps to open
        assertThat(edge.sim.door("door1").state()).isEqualTo("open");
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(
                json(edge.get("/sensinact/providers/door1/services/door/resources/state")).get("value").asText())
                .isEqualTo("open"));

        r = edge.post("/sensinact/providers/door1/services/control/resources/close/act", "{}");
        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        edge.sim.step(1);
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(
                json(edge.get("/sensinact/providers/door1/services/door/resources/state")).get("value").asText())
                .isEqualTo("closed"));
    }

    @Test
    void aRefusalOfTheDeviceAnswers409WithItsReason() throws Exception {
        HttpResponse<String> r = edge.post(GOTO.formatted("robot1"), "{\"x\":0,\"y\":0}");
        assertError(r, 409, "robot1 refused goTo", "wall");
        JsonNode body = json(r);
        assertThat(body.get("accepted").asBoolean()).isFalse();
        assertThat(body.get("deviceStatus").asInt()).isEqualTo(422);
    }

    @Test
    void badParametersAnswer400SayingWhichAndWhere() throws Exception {
        assertError(edge.post(GOTO.formatted("robot1"), "{\"x\":\"nine\",\"y\":7}"), 400,
                "parameter 'x' must be a whole number");
        assertError(edge.post(GOTO.formatted("robot1"), "{\"y\":7}"), 400, "parameter 'x' is missing");
        assertError(edge.post(GOTO.formatted("robot1"), "{\"x\":9,\n \"y\":}"), 400, "malformed JSON at line 2",
                "column");
        assertError(edge.post(GOTO.formatted("robot1"), "{\"x\":9,\"x\":7}"), 400, "malformed JSON",
                "Duplicate field 'x'");
        assertError(edge.post(GOTO.formatted("robot1"), "[9,7]"), 400, "must be a JSON object",
                "found a JSON array");
        // strict: an unknown parameter is refused, never ignored (robot1 stays where it is)
        assertError(edge.post(GOTO.formatted("robot1"), "{\"x\":9,\"y\":7,\"z\":1}"), 400,
                "unknown parameter 'z': goTo takes [x, y]");
        assertError(edge.post("/sensinact/providers/robot1/services/control/resources/pick/act", "{\"foo\":1}"), 400,
                "unknown parameter 'foo': pick takes no parameters");
        assertError(edge.post(GOTO.formatted("robot1"), "{\"x\":9,\"y\":7,\"x\":1}"), 400, "Duplicate field 'x'");
    }

    @Test
    void unknownProvidersAndActionsAnswer404() throws Exception {
        assertError(edge.post(GOTO.formatted("robot7"), "{\"x\":9,\"y\":3}"), 404, "no provider 'robot7'",
                "robot1", "door1");
        assertError(edge.post("/sensinact/providers/robot1/services/control/resources/fly/act", "{}"), 404,
                "no action 'fly'", "goTo");
        assertError(edge.post("/sensinact/providers/door1/services/control/resources/goTo/act", "{}"), 404,
                "no action 'goTo'", "open", "close");
    }

    @Test
    void actTakesOnlyPost() throws Exception {
        HttpResponse<String> r = edge.get(GOTO.formatted("robot1"));
        assertError(r, 405, "GET is not allowed", "POST");
        assertThat(r.headers().firstValue("Allow")).hasValue("POST");
    }
}
