package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.federation.impl.FabricKey;

class OptionsParserTest {

    @Test
    void defaultsAreThePapersWarehouseFiveTimesFasterWithATenSecondLimit() throws Exception {
        Options o = OptionsParser.parse();
        assertThat(o.map()).isNull();
        assertThat(o.generate()).isNull();
        assertThat(o.speed()).isEqualTo(5);
        assertThat(o.pollPeriodMs()).as("twice per step of 0.5 s of warehouse time").isEqualTo(50);
        assertThat(o.waitLimitMs()).isEqualTo(10_000);
        assertThat(o.waitLimitSteps()).as("robot-sim's --deadlock-steps").isEqualTo(20);
        assertThat(o.deadlineMs()).isEqualTo(30 * 60_000);
        assertThat(o.behaviours()).isTrue();
        assertThat(o.traffic()).as("the traffic planner drives the robots").isTrue();
        assertThat(o.report()).isEqualTo(o.runDir().resolve("report.json"));
    }

    @Test
    void noTrafficRunsTheFleetWithoutThePlanner() throws Exception {
        assertThat(OptionsParser.parse("--no-traffic").traffic()).isFalse();
        assertThat(OptionsParser.parse("--traffic").traffic()).isTrue();
        assertThat(BehaviourSettings.forRun(OptionsParser.parse("--no-traffic")).get(BehaviourSettings.ROBOT_PID))
                .containsEntry("traffic", false);
        assertThat(BehaviourSettings.forRun(OptionsParser.parse()).get(BehaviourSettings.ROBOT_PID))
                .containsEntry("traffic", true);
        assertThatThrownBy(() -> OptionsParser.parse("--traffic", "--no-traffic"))
                .hasMessage("--traffic and --no-traffic: choose one");
    }

    @Test
    void generateTakesTheIssuesLargerWarehouseByDefault() throws Exception {
        Options o = OptionsParser.parse("--generate", "--seed", "7", "--wait-limit", "7.5", "--speed", "4");
        assertThat(o.generate()).isEqualTo(new Options.Generate(60, 30, 30, 60, 1));
        assertThat(o.deadlineMs()).as("3 warehouse minutes per cart").isEqualTo(180 * 60_000L);
        assertThat(o.waitLimitSteps()).isEqualTo(15);
        assertThat(o.pollPeriodMs()).isEqualTo(63);
        assertThat(o.seed()).isEqualTo(7);
    }

    @Test
    void faultsAreReadWithTheirTimes() throws Exception {
        Options o = OptionsParser.parse("--fault-offline", "robot2@60s+30s", "--fault-offline", "robot1@1.5min+500ms",
                "--stop-behaviour", "robot@90s");
        assertThat(o.faults()).containsExactly(new PlannedFault.Offline("robot2", 60_000, 30_000),
                new PlannedFault.Offline("robot1", 90_000, 500), new PlannedFault.StopBehaviour("robot", 90_000));
        assertThat(((PlannedFault.StopBehaviour) o.faults().get(2)).symbolicName())
                .isEqualTo("eu.brain.iot.behaviours.robot");
    }

    @Test
    void badOptionsSayWhatIsWrong() {
        assertThatThrownBy(() -> OptionsParser.parse("--speed", "fast"))
                .hasMessage("--speed must be a number 0.1..1000.0, found 'fast'");
        assertThatThrownBy(() -> OptionsParser.parse("--robots", "3"))
                .hasMessage("--robots needs --generate (it sizes a generated warehouse)");
        assertThatThrownBy(() -> OptionsParser.parse("--generate", "--map", "x.map"))
                .hasMessageContaining("exclude each other");
        assertThatThrownBy(() -> OptionsParser.parse("--map", "/no/such.map")).hasMessage("--map /no/such.map: no such file");
        assertThatThrownBy(() -> OptionsParser.parse("--fault-offline", "robot2@60s"))
                .hasMessageStartingWith("--fault-offline 'robot2@60s': write ROBOT@TIME+DURATION");
        assertThatThrownBy(() -> OptionsParser.parse("--fault-offline", "robot2@soon+3s"))
                .hasMessageContaining("'soon' is not a duration");
        assertThatThrownBy(() -> OptionsParser.parse("--stop-behaviour", "robot"))
                .hasMessageStartingWith("--stop-behaviour 'robot': write BEHAVIOUR@TIME");
        assertThatThrownBy(() -> OptionsParser.parse("--seed", "1", "--seed", "2")).hasMessage("--seed given twice");
        assertThatThrownBy(() -> OptionsParser.parse("--generate", "--seed"))
                .hasMessage("--seed needs a value: N, robot-sim's seed, and the generated map's (1)");
        assertThatThrownBy(() -> OptionsParser.parse("--deadline")).hasMessage("--deadline needs a value: MINUTES, warehouse minutes before an unfinished run"
                + " fails (30, or 3 per cart if more)");
        assertThatThrownBy(() -> OptionsParser.parse("--colour")).hasMessage("unknown option '--colour'");
        assertThatThrownBy(() -> OptionsParser.parse("fast")).hasMessageStartingWith("unexpected argument 'fast'");
        assertThatThrownBy(() -> OptionsParser.parse("--node-config", "pom.xml"))
                .hasMessageContaining("not a readable .cfg or .config file");
    }

    @Test
    void aBrokerMakesTheNodeJoinAFabricAndItsConfigurationIsWritten(@TempDir Path dir) throws Exception {
        assertThat(OptionsParser.parse().fabric()).as("alone by default").isNull();
        Options o = OptionsParser.parse("--broker", "tcp://127.0.0.1:18830", "--run-dir", dir.toString());
        assertThat(o.fabric()).isEqualTo(new Options.Fabric("tcp://127.0.0.1:18830", null));

        Map<String, Object> cfg = NodeSetup.federation(o);
        assertThat(cfg).containsEntry("broker.uri", "tcp://127.0.0.1:18830").containsEntry("fabric.name", "warehouse")
                .containsEntry("key.file", dir.resolve("fabric.key").toString())
                .containsEntry("state.dir", dir.resolve("federation").toString()).doesNotContainKey("node.name");
        assertThat(dir.resolve("fabric.key")).as("a new key, read as a node reads it").isRegularFile();
        assertThat(FabricKey.read(dir.resolve("fabric.key"))).isNotNull();

        Options given = OptionsParser.parse("--broker", "ssl://broker.example:8883", "--fabric-key",
                dir.resolve("fabric.key").toString());
        assertThat(given.fabric().key()).isEqualTo(dir.resolve("fabric.key"));
    }

    @Test
    void aBadBrokerOrKeySaysWhatIsWrong(@TempDir Path dir) {
        assertThatThrownBy(() -> OptionsParser.parse("--broker", "127.0.0.1:1883")).hasMessage("--broker must be an "
                + "MQTT broker's URI with its port (1..65535), e.g. tcp://127.0.0.1:1883 or ssl://broker.example:8883, "
                + "found '127.0.0.1:1883'");
        assertThatThrownBy(() -> OptionsParser.parse("--broker", "tcp://127.0.0.1"))
                .hasMessageStartingWith("--broker must be an MQTT broker's URI with its port");
        assertThatThrownBy(() -> OptionsParser.parse("--fabric-key", "k")).hasMessage("--fabric-key needs --broker "
                + "or --nodes 2 or more (the key signs what the nodes send through the broker)");
        assertThatThrownBy(() -> OptionsParser.parse("--broker", "tcp://127.0.0.1:1883", "--fabric-key",
                dir.resolve("none").toString())).hasMessageContaining("no such readable file");
        assertThatThrownBy(() -> OptionsParser.parse("--broker", "tcp://127.0.0.1:99999"))
                .hasMessageStartingWith("--broker must be an MQTT broker's URI with its port (1..65535)");
    }

    @Test
    void aKeyFileThatHoldsNoKeyIsABadOption(@TempDir Path dir) throws Exception {
        Path shortKey = java.nio.file.Files.writeString(dir.resolve("short.key"), "AAECAwQ=\n");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--fabric-key", shortKey.toString()))
                .hasMessage("--fabric-key " + shortKey + ": the fabric key in " + shortKey + " is too short (5 bytes, "
                        + "at least 32); make a new one with fabric:keygen for every node");
        Path text = java.nio.file.Files.writeString(dir.resolve("hello.key"), "hello\n");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--fabric-key", text.toString()))
                .hasMessageStartingWith("--fabric-key " + text + ": the fabric key file " + text + " is not a key");
    }

    @Test
    void mainPrintsWhatWasWrongOnOneLineAndWhereTheOptionsAreAndExitsWith2() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.run(new String[] {"--wait-limit", "-3"}, new PrintStream(out), new PrintStream(err));
        assertThat(code).isEqualTo(2);
        String text = err.toString(StandardCharsets.UTF_8);
        assertThat(text).isEqualTo("warehouse-scenario: --wait-limit must be a number 0.5..3600.0, found '-3'\n"
                + "(./warehouse-scenario --help lists the options)\n");
        assertThat(text).doesNotContain("Exception");
        assertThat(out.size()).isZero();
    }

    @Test
    void aRunFolderThatHoldsAnEarlierRunIsRefused(@TempDir Path dir) throws Exception {
        assertThat(OptionsParser.parse("--run-dir", dir.toString()).runDir()).as("empty: taken").isEqualTo(dir);
        java.nio.file.Files.writeString(dir.resolve("mosquitto.conf"), "listener 18830 127.0.0.1\n");
        assertThat(OptionsParser.parse("--run-dir", dir.toString()).runDir()).as("a file of the user's: taken")
                .isEqualTo(dir);
        java.nio.file.Files.createDirectories(dir.resolve("journal"));
        assertThatThrownBy(() -> OptionsParser.parse("--run-dir", dir.toString())).hasMessage("--run-dir " + dir
                + ": the folder holds an earlier run (its journal would bring that run's behaviours back, and the"
                + " nodes would not start bare): remove it, or choose a folder where no run was");
    }

    @Test
    void anUnknownRobotInAFaultIsABadOptionToo(@org.junit.jupiter.api.io.TempDir Path dir) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.run(new String[] {"--fault-offline", "robot9@1s+1s", "--run-dir", dir.toString()},
                new PrintStream(new ByteArrayOutputStream()), new PrintStream(err));
        assertThat(code).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8))
                .startsWith("warehouse-scenario: --fault-offline: no robot 'robot9' in this warehouse (robot1, robot2, "
                        + "robot3)");
    }

    @Test
    void aMapThatDoesNotParseIsABadOptionNamingThePlace(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path map = dir.resolve("bad.map");
        java.nio.file.Files.writeString(map, "map:\n#####\n#RxC#\n#####\n");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.run(new String[] {"--map", map.toString(), "--run-dir", dir.resolve("run").toString()},
                new PrintStream(new ByteArrayOutputStream()), new PrintStream(err));
        assertThat(code).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).startsWith("warehouse-scenario: --map: ")
                .contains("bad.map:3:3: unknown cell 'x'");
        assertThat(dir.resolve("run")).as("nothing started").doesNotExist();
    }

    @Test
    void helpPrintsTheUsageAndExitsWith0() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        assertThat(Main.run(new String[] {"--help"}, new PrintStream(out), System.err)).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).startsWith("Usage: ./warehouse-scenario [options]")
                .contains("--fault-offline=R@T+D").contains("--stop-behaviour=B@T");
        out.reset();
        assertThat(Main.run(new String[] {"-h"}, new PrintStream(out), System.err)).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).startsWith("Usage: ./warehouse-scenario [options]");
    }

    @Test
    void aStopBehaviourNamesAKnownBehaviourOrAFullSymbolicName() throws Exception {
        assertThat(OptionsParser.parse("--stop-behaviour", "eu.brain.iot.behaviours.door@10s",
                "--stop-behaviour", "orchestrator@1min").faults()).containsExactly(
                new PlannedFault.StopBehaviour("eu.brain.iot.behaviours.door", 10_000),
                new PlannedFault.StopBehaviour("orchestrator", 60_000));
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.run(new String[] {"--stop-behaviour", "nosuchbundle@10s"},
                new PrintStream(new ByteArrayOutputStream()), new PrintStream(err));
        assertThat(code).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).startsWith("warehouse-scenario: --stop-behaviour "
                + "'nosuchbundle@10s': no behaviour 'nosuchbundle'; write BEHAVIOUR@TIME, e.g. robot@90s (BEHAVIOUR is "
                + "robot, door, orchestrator, or a bundle's full symbolic name, with a dot)\n"
                + "(./warehouse-scenario --help lists the options)\n");
        assertThatThrownBy(() -> OptionsParser.parse("--stop-behaviour", "@10s"))
                .hasMessageStartingWith("--stop-behaviour '@10s': the BEHAVIOUR before '@' is missing");
        assertThatThrownBy(() -> OptionsParser.parse("--stop-behaviour", "eu..robot@10s"))
                .hasMessageStartingWith("--stop-behaviour 'eu..robot@10s': no behaviour 'eu..robot'");
        assertThatThrownBy(() -> OptionsParser.parse("--stop-behaviour", "door@later"))
                .hasMessage("--stop-behaviour 'door@later': the TIME 'later' is not a duration: write a number and "
                        + "a unit, ms, s, min or h (90s, 1.5min)");
    }

    @Test
    void aFaultOfflineMistakeNamesThePartThatIsWrong() {
        assertThatThrownBy(() -> OptionsParser.parse("--fault-offline", "robot2@abc"))
                .hasMessage("--fault-offline 'robot2@abc': the TIME 'abc' is not a duration: write a number and a "
                        + "unit, ms, s, min or h (90s, 1.5min)");
        assertThatThrownBy(() -> OptionsParser.parse("--fault-offline", "robot2@1s+abc"))
                .hasMessageStartingWith("--fault-offline 'robot2@1s+abc': the DURATION 'abc' is not a duration");
        assertThatThrownBy(() -> OptionsParser.parse("--fault-offline", "robot2@1s"))
                .hasMessageEndingWith("; the +DURATION is missing");
        assertThatThrownBy(() -> OptionsParser.parse("--fault-offline", "robot2"))
                .hasMessageEndingWith("; the @TIME is missing");
        assertThatThrownBy(() -> OptionsParser.parse("--fault-offline", "@1s+1s"))
                .hasMessageEndingWith("; the ROBOT before '@' is missing");
        assertThatThrownBy(() -> OptionsParser.parse("--fault-offline", "robot2@1s+0s"))
                .hasMessage("--fault-offline 'robot2@1s+0s': the DURATION must be above 0");
    }

    @Test
    void aSeedThatIsNoNumberDoesNotListTheWholeRange() {
        assertThatThrownBy(() -> OptionsParser.parse("--seed", "-x")).hasMessage("--seed must be a whole number, found '-x'");
        assertThatThrownBy(() -> OptionsParser.parse("--generate", "--width", "3"))
                .hasMessage("--width must be a whole number 7..5000, found '3'");
        assertThatThrownBy(() -> OptionsParser.parse("--generate=yes")).hasMessage("--generate takes no value");
    }
}
