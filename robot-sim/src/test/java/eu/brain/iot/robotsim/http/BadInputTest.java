package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import java.net.http.HttpRequest;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Every bad request gets a JSON error naming what was wrong, and leaves the world exactly as it was. */
class BadInputTest {
    private static final String GOTO = "robot1/robot_local_control/NavigationComponent/GoToComponent/add";
    private RobotSim sim;
    private Client client;

    @BeforeEach
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        client = new Client(sim.baseUri());
    }

    @AfterEach
    void worldIsUnchanged() throws Exception {
        try {
            sim.step(5);
            RobotSim fresh = RobotSim.start(SimConfig.builder().manualStep(true).build());
            try {
                fresh.step(5);
                assertThat(withoutCommandCounts(client.get("world").json())).as("the world after 5 more steps")
                        .isEqualTo(withoutCommandCounts(new Client(fresh.baseUri()).get("world").json()));
            } finally {
                fresh.close();
            }
        } finally {
            sim.close();
        }
    }

    /** The world without the count of commands answered, which a refused command raises (and only that). */
    private static String withoutCommandCounts(com.fasterxml.jackson.databind.JsonNode world) {
        com.fasterxml.jackson.databind.node.ObjectNode copy = world.deepCopy();
        ((com.fasterxml.jackson.databind.node.ObjectNode) copy.get("counters")).remove("commands");
        return copy.toString();
    }

    @ParameterizedTest(name = "{0} -> 400 naming {1}")
    @CsvSource(delimiter = '|', value = {
        "{\"x\":3,                    | body",
        "[1,2]                        | body",
        "{\"x\":\"3\",\"y\":1}        | x",
        "{\"x\":3.5,\"y\":1}          | x",
        "{\"x\":null,\"y\":1}         | x",
        "{\"x\":3}                    | y",
        "{\"x\":3,\"y\":true}         | y",
        "{\"x\":3,\"y\":1,\"z\":0}    | z",
        "{}                           | x",
    })
    void badGoToBodies(String body, String field) throws Exception {
        Client.Answer a = client.post(GOTO, body);
        assertThat(a.status()).isEqualTo(400);
        assertThat(a.json().get("field").asText()).isEqualTo(field);
        assertThat(a.json().get("error").asText()).isNotBlank();
    }

    /** Every endpoint that takes a POST body. */
    static final String[] POST_ENDPOINTS = {
        GOTO,
        "robot1/robot_local_control/NavigationComponent/PickComponent/add",
        "robot1/robot_local_control/NavigationComponent/PlaceComponent/add",
        "robot1/robot_local_control/PickComponent/add",
        "robot1/robot_local_control/NavigationComponent/GoToComponent/cancel",
        "robot1/robot_local_control/NavigationComponent/PickComponent/cancel",
        "robot1/robot_local_control/NavigationComponent/PlaceComponent/cancel",
        "robot1/robot_local_control/NavigationComponent/GoToComponent/query_state",
        "door1/door_controller/command",
        "admin/step",
        "admin/faults",
        "admin/faults/robot1",
    };

    static String deepJson(int depth) {
        return "{\"x\":" + "[".repeat(depth) + "]".repeat(depth) + ",\"y\":1}";
    }

    @Test
    void deeplyNestedJsonIsA400OnEveryPostEndpoint() throws Exception {
        for (String deep : new String[] {deepJson(5000), deepJson(17), "[".repeat(5000) + "]".repeat(5000),
                "{\"a\":".repeat(3000) + "1" + "}".repeat(3000)}) {
            for (String path : POST_ENDPOINTS) {
                Client.Answer a = client.post(path, deep);
                assertThat(a.status()).as(path).isEqualTo(400);
                assertThat(a.json().get("field").asText()).as(path).isEqualTo("body");
                assertThat(a.json().get("error").asText()).as(path)
                        .startsWith("JSON nesting depth exceeds 16 at line 1, column ");
            }
        }
    }

    @ParameterizedTest(name = "{0} {1} -> 400 naming {2}")
    @CsvSource(delimiter = '|', value = {
        GOTO + "                          | {\"x\":9,\"y\":7,\"x\":1}          | x",
        "door1/door_controller/command    | {\"data\":0.0,\"data\":1.0}         | data",
        "admin/step                       | {\"steps\":1,\"steps\":100}         | steps",
        "admin/faults                     | {\"errorRate\":0,\"errorRate\":1}   | errorRate",
        "admin/faults/robot1              | {\"offline\":false,\"offline\":true} | offline",
        "robot1/robot_local_control/NavigationComponent/GoToComponent/cancel | {\"id\":1,\"id\":2} | id",
    })
    void aKeyGivenTwiceIsRefusedNamingIt(String path, String body, String key) throws Exception {
        Client.Answer a = client.post(path, body);
        assertThat(a.status()).isEqualTo(400);
        assertThat(a.json().get("field").asText()).isEqualTo(key);
        assertThat(a.json().get("error").asText()).startsWith("field '" + key + "' given twice at line 1, column ");
    }

    @Test
    void contentAfterTheDocumentIsRefused() throws Exception {
        Client.Answer a = client.post(GOTO, "{\"x\":6,\"y\":4} {\"x\":8,\"y\":4}");
        assertThat(a.status()).isEqualTo(400);
        assertThat(a.json().get("error").asText()).startsWith("unexpected '{' after the JSON document");
    }

    @ParameterizedTest(name = "goal ({0},{1}) -> 422 naming {2}")
    @CsvSource({"20,3,x", "-1,3,x", "3,10,y", "3,-5,y", "0,0,x", "9,0,x"})
    void goalOutsideTheMapOrInAWall(int x, int y, String field) throws Exception {
        Client.Answer a = client.post(GOTO, "{\"x\":" + x + ",\"y\":" + y + "}");
        assertThat(a.status()).isEqualTo(422);
        assertThat(a.json().get("field").asText()).isEqualTo(field);
        assertThat(a.json().get("error").asText()).contains("(" + x + "," + y + ")");
    }

    @ParameterizedTest(name = "door body {0} -> 400")
    @CsvSource(delimiter = '|', value = {
        "{\"data\":\"open\"}  | data",
        "{\"data\":0.5}       | data",
        "{}                   | data",
        "{\"data\":1,\"x\":1} | x",
        "{data:1}             | body",
    })
    void badDoorCommands(String body, String field) throws Exception {
        Client.Answer a = client.post("door1/door_controller/command", body);
        assertThat(a.status()).isEqualTo(400);
        assertThat(a.json().get("field").asText()).isEqualTo(field);
    }

    @Test
    void pickAndCancelRefuseUnknownFields() throws Exception {
        Client.Answer pick = client.post("robot1/robot_local_control/NavigationComponent/PickComponent/add",
                "{\"cart\":\"cart1\"}");
        assertThat(pick.status()).isEqualTo(400);
        assertThat(pick.json().get("field").asText()).isEqualTo("cart");
        Client.Answer cancel = client.post(
                "robot1/robot_local_control/NavigationComponent/GoToComponent/cancel", "{\"id\":\"one\"}");
        assertThat(cancel.status()).isEqualTo(400);
        assertThat(cancel.json().get("field").asText()).isEqualTo("id");
    }

    @Test
    void unknownRobotDoorAndEndpointAre404() throws Exception {
        Client.Answer robot = client.get("robot9/robot_local_control/state");
        assertThat(robot.status()).isEqualTo(404);
        assertThat(robot.json().get("error").asText()).isEqualTo("unknown robot 'robot9'");
        Client.Answer goTo = client.post("robot9/robot_local_control/NavigationComponent/GoToComponent/add",
                "{\"x\":3,\"y\":3}");
        assertThat(goTo.status()).isEqualTo(404);
        assertThat(client.post("door7/door_controller/command", "{\"data\":1.0}").status()).isEqualTo(404);
        assertThat(client.get("robot1/robot_local_control/battery").status()).isEqualTo(404);
        assertThat(client.get("robot1/robot_local_control/NavigationComponent/FlyComponent/add").status())
                .isEqualTo(404);
        assertThat(client.get("nothing/here").status()).isEqualTo(404);
        assertThat(client.get("admin/faults/robot9").status()).isEqualTo(404);
    }

    @Test
    void wrongMethodIs405WithAllow() throws Exception {
        Client.Answer a = client.get(GOTO);
        assertThat(a.status()).isEqualTo(405);
        JsonNode error = a.json();
        assertThat(error.get("error").asText()).contains("use POST");
        Client.Answer put = client.send(HttpRequest.newBuilder(sim.baseUri().resolve("robot1/robot_local_control/state"))
                .header("Content-Type", "application/json").PUT(HttpRequest.BodyPublishers.ofString("{}")));
        assertThat(put.status()).isEqualTo(405);
    }

    @Test
    void badStepAndFaultRequests() throws Exception {
        Client.Answer steps = client.post("admin/step", "{\"steps\":0}");
        assertThat(steps.status()).isEqualTo(400);
        assertThat(steps.json().get("field").asText()).isEqualTo("steps");
        Client.Answer rate = client.post("admin/faults", "{\"errorRate\":2}");
        assertThat(rate.status()).isEqualTo(400);
        assertThat(rate.json().get("field").asText()).isEqualTo("errorRate");
        Client.Answer offline = client.post("admin/faults/robot1", "{\"offline\":\"yes\"}");
        assertThat(offline.status()).isEqualTo(400);
        assertThat(offline.json().get("field").asText()).isEqualTo("offline");
        Client.Answer unknown = client.post("admin/faults", "{\"fire\":true}");
        assertThat(unknown.status()).isEqualTo(400);
        assertThat(unknown.json().get("field").asText()).isEqualTo("fire");
        assertThat(client.get("admin/faults").json().get("fleet").get("errorRate").asDouble()).isZero();
    }
}
