package eu.brain.iot.robotsim.cli;

import static org.assertj.core.api.Assertions.assertThat;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.world.MapParser;
import eu.brain.iot.robotsim.world.WarehouseMap;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class MainTest {
    @TempDir
    Path dir;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) {
        PrintStream printed = new PrintStream(out, true, StandardCharsets.UTF_8);
        ServeCommand serve = new ServeCommand(printed);
        int code = Main.run(serve, args, printed, new PrintStream(err, true, StandardCharsets.UTF_8));
        if (serve.started() != null) {
            serve.started().close();
        }
        return code;
    }

    private String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "--port abc                | robot-sim: --port must be a whole number 0..65535, found 'abc'",
        "--port 70000              | robot-sim: --port must be a whole number 0..65535, found '70000'",
        "--port                    | robot-sim: --port needs a value",
        "--colour red              | robot-sim: unknown option --colour",
        "--speed 0                 | robot-sim: --speed must be a number > 0.0 and <= 10000.0, found '0'",
        "--map /no/such.map        | robot-sim: --map: no such file '/no/such.map'",
        "--fault errorRate=2       | robot-sim: --fault 'errorRate=2': errorRate must be a number from 0 to 1",
        "--fault robot9:offline=true --port 0 | robot-sim: --fault: fault for unknown robot 'robot9' (the map has 3 robots: robot1..robot3)",
        "--manual-step=yes         | robot-sim: --manual-step takes no value",
        "fly                       | robot-sim: unknown command 'fly'",
        "--max-queue 0             | robot-sim: --max-queue must be a whole number 1..1000000, found '0'",
        "--allow-host http://x.example | robot-sim: --allow-host: 'http://x.example' is not a host name (give a name or an address, without scheme, port or path, e.g. robots.example or 192.168.1.20)",
        "--allow-host x.example:80 | robot-sim: --allow-host: 'x.example:80' is not a host name (give a name or an address, without scheme, port or path, e.g. robots.example or 192.168.1.20)",
        "--bind 0.0.0.0/8          | robot-sim: --bind: '0.0.0.0/8' is not a host name (give a name or an address, without scheme, port or path, e.g. robots.example or 192.168.1.20)",
        "--request-timeout-ms 5    | robot-sim: --request-timeout-ms must be a whole number 100..3600000, found '5'",
        "--seed -x                 | robot-sim: --seed must be a whole number, found '-x'",
        "--port 1 --port 2         | robot-sim: --port given more than once",
        "--port --quiet            | robot-sim: --port needs a value",
        "-x                        | robot-sim: unexpected argument '-x'",
        "generate --width 3        | robot-sim: --width must be a whole number 7..5000, found '3'",
        "generate --seed 1.5       | robot-sim: --seed must be a whole number, found '1.5'",
        "generate --colour red     | robot-sim: unknown option --colour",
        "generate fly              | robot-sim: unexpected argument 'fly'",
    })
    void badCommandLinesGiveOneLineAndUsageWithoutStackTrace(String args, String firstLine) {
        assertThat(run(args.split(" "))).isEqualTo(2);
        String[] lines = err().split("\n");
        assertThat(lines[0]).isEqualTo(firstLine);
        assertThat(lines[1]).startsWith("Usage: java -jar robot-sim.jar " + (args.startsWith("generate") ? "generate" : "["));
        assertThat(err()).doesNotContain("Exception").doesNotContain("\tat ");
    }

    @Test
    void badMapFileSaysWhere() throws Exception {
        Path map = dir.resolve("bad.map");
        Files.writeString(map, "map:\n###\n#Q#\n");
        assertThat(run("--map", map.toString())).isEqualTo(2);
        assertThat(err()).startsWith("robot-sim: --map: " + map + ":3:2: unknown cell 'Q'");
    }

    @Test
    void helpIsPrintedAndExitsZero() {
        assertThat(run("--help")).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).contains("--manual-step").contains("--fault=SPEC")
                .contains("robot-sim.jar generate --help");
        out.reset();
        assertThat(run("generate", "--help")).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).startsWith("Usage: java -jar robot-sim.jar generate")
                .contains("--doors=N").contains("Example: ");
        assertThat(err()).isEmpty();
    }

    @Test
    void startsAndPrintsEveryRobotAndDoorUrl() throws Exception {
        ServeCommand serve = new ServeCommand(new PrintStream(out, true, StandardCharsets.UTF_8));
        assertThat(Main.run(serve, new String[] {"--port", "0", "--manual-step", "--seed", "5"}, System.out,
                new PrintStream(err, true, StandardCharsets.UTF_8))).isEqualTo(ServeCommand.RUNNING);
        RobotSim sim = serve.started();
        try {
            String printed = out.toString(StandardCharsets.UTF_8);
            String base = "http://127.0.0.1:" + sim.port() + "/";
            assertThat(printed).contains("listening on " + base)
                    .contains("robot robot1 " + base + "robot1/robot_local_control/state")
                    .contains("robot robot3 " + base + "robot3/robot_local_control/state")
                    .contains("door  door1 " + base + "door1/door_controller/state");
            assertThat(sim.config().rules().seed()).isEqualTo(5);
        } finally {
            sim.close();
        }
    }

    @Test
    void flagsReachTheConfiguration() throws Exception {
        SimConfig c = ServeCommand.parse("--bind=0.0.0.0", "--speed", "100", "--door-open-steps", "0",
                "--deadlock-steps", "9", "--fault", "latencyMs=20,dropRate=0.25", "--fault", "robot2:offline=true")
                .config();
        assertThat(c.bindAddress()).isEqualTo("0.0.0.0");
        assertThat(c.port()).isEqualTo(ServeCommand.DEFAULT_PORT);
        assertThat(c.stepPeriodNanos()).isEqualTo(5_000_000L);
        assertThat(c.rules().doorOpenSteps()).isZero();
        assertThat(c.rules().deadlockSteps()).isEqualTo(9);
        assertThat(c.fleetFaults().latencyMs()).isEqualTo(20);
        assertThat(c.fleetFaults().dropRate()).isEqualTo(0.25);
        assertThat(c.robotFaults().get("robot2").offline()).isTrue();
        assertThat(c.maxQueuedMissions()).isEqualTo(SimConfig.DEFAULT_MAX_QUEUED_MISSIONS).isEqualTo(64);
        assertThat(c.requestTimeoutMillis()).isEqualTo(10_000);
        assertThat(c.allowedHosts()).isEmpty();
    }

    @Test
    void hardeningFlagsReachTheConfiguration() throws Exception {
        SimConfig c = ServeCommand.parse("--max-queue", "5", "--allow-host", "Robots.Example", "--allow-host",
                "fe80::1", "--request-timeout-ms", "2500").config();
        assertThat(c.maxQueuedMissions()).isEqualTo(5);
        assertThat(c.allowedHosts()).containsExactlyInAnyOrder("robots.example", "[fe80::1]");
        assertThat(c.requestTimeoutMillis()).isEqualTo(2500);
    }

    @Test
    void generateWritesAMapThatLoads() throws Exception {
        Path file = dir.resolve("big.map");
        assertThat(run("generate", "--width", "60", "--height", "30", "--robots", "40", "--carts", "80",
                "--out", file.toString())).isZero();
        WarehouseMap map = MapParser.parse(file);
        assertThat(map.robots()).hasSize(40);
        assertThat(map.carts()).hasSize(80);
        assertThat(map.doors()).as("width/40: one door, every trip crosses it").hasSize(1);
        Path two = dir.resolve("two.map");
        assertThat(run("generate", "--width", "60", "--height", "30", "--robots", "30", "--carts", "60",
                "--doors", "2", "--out", two.toString())).isZero();
        assertThat(MapParser.parse(two).doors()).hasSize(2);
        assertThat(run("generate", "--width", "20", "--height", "20", "--robots", "5", "--carts", "5000")).isEqualTo(2);
        assertThat(err()).contains("carts do not fit");
    }

    @Test
    void aMapThatCannotBeWrittenIsOneLineAndExitCode1() {
        Path file = dir.resolve("no-such-folder/big.map");
        assertThat(run("generate", "--robots", "5", "--carts", "5", "--out", file.toString())).isEqualTo(1);
        assertThat(err()).isEqualTo("robot-sim: --out: cannot write '" + file + "': no such folder\n");
    }

    @Test
    void theDefaultsAreThoseTheUsageStates() throws Exception {
        SimConfig c = ServeCommand.parse().config();
        assertThat(c.port()).isEqualTo(8090);
        assertThat(c.bindAddress()).isEqualTo("127.0.0.1");
        assertThat(c.rules().seed()).isEqualTo(1);
        assertThat(c.rules().deadlockSteps()).isEqualTo(4);
        assertThat(c.stepMillis()).isEqualTo(500);
        assertThat(c.speed()).isEqualTo(1.0);
        assertThat(c.manualStep()).isFalse();
    }
}
