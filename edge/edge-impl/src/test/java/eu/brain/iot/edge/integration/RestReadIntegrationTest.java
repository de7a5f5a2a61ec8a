package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static eu.brain.iot.edge.integration.EdgeTestSupport.json;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.net.http.HttpResponse;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import com.fasterxml.jackson.databind.JsonNode;

import eu.brain.iot.robotsim.view.RobotView;

/** GET on the edge's REST API in a real framework, over real HTTP, against the simulator: live values and errors. */
class RestReadIntegrationTest extends EdgeRestTestBase {

    @Test
    void listsEveryProviderWithKindStatusAndLastPoll() throws Exception {
        HttpResponse<String> r = edge.get("/sensinact/providers");
        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        JsonNode list = json(r);
        List<String> ids = new ArrayList<>();
        list.forEach(p -> {
            ids.add(p.get("id").asText());
            assertThat(p.get("status").asText()).isEqualTo("OK");
            assertThat(p.get("lastPoll").asText()).matches("\\d{4}-\\d\\d-\\d\\dT.*Z");
            assertThat(p.get("kind").asText()).isIn("robot", "door");
        });
        assertThat(ids).containsExactly("door1", "robot1", "robot2", "robot3");
    }

    @Test
    void aProviderShowsItsLivePositionThenTheNextOne() throws Exception {
        RobotView before = edge.sim.robot("robot1");
        JsonNode p = json(edge.get("/sensinact/providers/robot1"));
        assertThat(p.get("kind").asText()).isEqualTo("robot");
        JsonNode position = p.get("services").get("position");
        assertThat(position.get("x").get("value").asInt()).isEqualTo(before.x());
        assertThat(position.get("y").get("value").asInt()).isEqualTo(before.y());
        assertThat(position.get("x").get("status").asText()).isEqualTo("OK");
        assertThat(p.get("actions").get("control").toString()).contains("goTo(x,y)");

        // the robot moves in the simulator; the next GET shows where it is now
        assertThat(model.act("robot1", "control", "goTo", Map.of("x", before.x(), "y", 3)).toCompletableFuture()
                .join().accepted).isTrue();
        edge.sim.step(3);
        await().atMost(DEADLINE).untilAsserted(() -> {
            JsonNode y = json(edge.get("/sensinact/providers/robot1/services/position/resources/y"));
            assertThat(y.get("value").asInt()).isEqualTo(3).isEqualTo(edge.sim.robot("robot1").y());
        });
    }

    @Test
    void aServiceAndAResource() throws Exception {
        JsonNode service = json(edge.get("/sensinact/providers/door1/services/door"));
        assertThat(service.get("provider").asText()).isEqualTo("door1");
        assertThat(service.get("resources").get("state").get("value").asText())
                .isEqualTo(edge.sim.door("door1").state());

        JsonNode resource = json(edge.get("/sensinact/providers/robot2/services/state/resources/state"));
        assertThat(resource.get("provider").asText()).isEqualTo("robot2");
        assertThat(resource.get("service").asText()).isEqualTo("state");
        assertThat(resource.get("resource").asText()).isEqualTo("state");
        assertThat(resource.get("value").asText()).isEqualTo(edge.sim.robot("robot2").state());
        assertThat(resource.get("timestamp").asText()).endsWith("Z");
        assertThat(resource.get("status").asText()).isEqualTo("OK");

        JsonNode control = json(edge.get("/sensinact/providers/robot2/services/control"));
        assertThat(control.get("actions").toString()).contains("goTo(x,y)", "pick", "place", "cancel");
    }

    @Test
    void unknownNamesAnswer404SayingWhatExists() throws Exception {
        assertError(edge.get("/sensinact/providers/robot9"), 404, "no provider 'robot9'", "robot1", "door1");
        assertError(edge.get("/sensinact/providers/robot1/services/wheels"), 404, "no service 'wheels'",
                "position", "control");
        assertError(edge.get("/sensinact/providers/robot1/services/position/resources/z"), 404,
                "no resource 'z'", "x", "y", "heading");
        assertError(edge.get("/sensinact/robots"), 404, "no such path: /sensinact/robots", "/sensinact/providers");
    }

    @Test
    void aWrongMethodAnswers405WithWhatIsAllowed() throws Exception {
        HttpResponse<String> r = edge.send("DELETE", "/sensinact/providers/robot1", null);
        assertError(r, 405, "DELETE is not allowed", "GET");
        assertThat(r.headers().firstValue("Allow")).hasValue("GET");
        assertError(edge.get("/sensinact/providers/robot1/services/control/resources/goTo"), 405,
                "goTo is an action", "POST", "/act");
    }

    static void assertError(HttpResponse<String> r, int status, String... fragments) throws Exception {
        assertThat(r.statusCode()).as(r.body()).isEqualTo(status);
        JsonNode error = json(r);
        assertThat(error.get("status").asInt()).isEqualTo(status);
        assertThat(error.get("error").asText()).contains(fragments).doesNotContain("Exception", "\tat ");
    }
}
