package eu.brain.iot.edge.impl;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/** Answers are trusted only when whole: every defect is named with the device and the field. */
class AnswerParserTest {

    private final AnswerParser parser = new AnswerParser();

    private static byte[] json(String text) {
        return text.getBytes(UTF_8);
    }

    private static final String ROBOT = "{\"id\":\"robot1\",\"x\":2,\"y\":1,\"heading\":\"N\",\"area\":1,"
            + "\"state\":\"running\",\"detect\":0,\"cart\":null,\"mission\":{\"id\":3,\"type\":\"goto\","
            + "\"state\":\"running\",\"reason\":null,\"goal\":{\"x\":9,\"y\":7}},\"nearMisses\":1,\"deadlocks\":0}";

    @Test
    void readsARobot() throws Exception {
        RobotAnswer r = parser.robot("robot1", json(ROBOT));
        assertThat(r).isEqualTo(new RobotAnswer("robot1", 2, 1, "N", 1, "running", 0, null,
                new RobotAnswer.Mission(3, "goto", "running", null, 9, 7), 1, 0));
    }

    @Test
    void ignoresFieldsItDoesNotKnow() throws Exception {
        assertThat(parser.robot("robot1", json(ROBOT.replace("{\"id\"", "{\"battery\":0.9,\"id\"")))).isNotNull();
    }

    @Test
    void namesWhereJsonIsBroken() {
        assertThatThrownBy(() -> parser.robot("robot1", json("{\"id\":\"robot1\",\"x\":2,")))
                .isInstanceOf(DeviceIOException.class)
                .hasMessageStartingWith("malformed JSON from robot1 at line 1, column 22:");
    }

    @Test
    void namesTheFieldThatIsWrong() {
        assertThatThrownBy(() -> parser.robot("robot1", json(ROBOT.replace("\"x\":2", "\"x\":\"2\""))))
                .hasMessage("answer of robot1: 'x' must be a whole number, found \"2\"");
        assertThatThrownBy(() -> parser.robot("robot1", json(ROBOT.replace("\"running\",\"detect\"",
                "\"flying\",\"detect\"")))).hasMessage(
                        "answer of robot1: 'state' is 'flying', expected one of [running, stopped]");
        assertThatThrownBy(() -> parser.robot("robot1", json(ROBOT.replace("\"detect\":0", "\"detect\":7"))))
                .hasMessage("answer of robot1: 'detect' must be 0, 1 or 2, found 7");
        assertThatThrownBy(() -> parser.robot("robot2", json(ROBOT))).hasMessage("answer of robot2 is about 'robot1'");
        assertThatThrownBy(() -> parser.robot("robot1", json("[1,2]")))
                .hasMessage("answer of robot1 is not a JSON object");
    }

    @Test
    void readsADoorAndTheFleetInventory() throws Exception {
        assertThat(parser.door("door1", json("{\"id\":\"door1\",\"x\":9,\"y\":5,\"state\":\"open\",\"data\":1.0,"
                + "\"stepsLeft\":0}"))).isEqualTo(new DoorAnswer("door1", 9, 5, "open", 1.0, 0));
        assertThat(parser.inventory(json("{\"robots\":[\"robot1\",\"robot2\"],\"doors\":[\"door1\"]}")))
                .isEqualTo(new AnswerParser.Inventory(java.util.List.of("robot1", "robot2"),
                        java.util.List.of("door1")));
    }

    @Test
    void errorTextComesFromTheFleetsErrorDocument() {
        assertThat(parser.errorText(new HttpAnswer(422, json("{\"error\":\"goal (0,0) is a wall\",\"field\":\"x\","
                + "\"status\":422}"), 0))).isEqualTo("goal (0,0) is a wall");
        assertThat(parser.errorText(new HttpAnswer(502, json("<html>bad gateway</html>"), 0)))
                .isEqualTo("<html>bad gateway</html>");
        assertThat(parser.errorText(new HttpAnswer(500, new byte[0], 0))).isEqualTo("(no body)");
    }
}
