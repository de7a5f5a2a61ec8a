package eu.brain.iot.benchmarks.robotsim;

import static org.assertj.core.api.Assertions.assertThat;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The robot-sim drivers run against the real simulator, and say what is wrong with a bad command line. */
class RobotSimDriversTest {
    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private final PrintStream outStream = new PrintStream(out, true, StandardCharsets.UTF_8);
    private final PrintStream errStream = new PrintStream(err, true, StandardCharsets.UTF_8);

    private String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    private String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    @Test
    void pollLoadPollsEveryRobotOfARunningSimulatorWithoutErrors() throws Exception {
        try (RobotSim sim = RobotSim.start(SimConfig.builder().port(0).manualStep(true).build())) {
            int code = PollLoad.run(new String[] {"--url", sim.baseUri().toString(), "--connections", "4",
                "--warmup", "0", "--duration", "1", "--check-every", "1"}, outStream, errStream);
            assertThat(code).as(out() + err()).isZero();
            assertThat(out()).contains("poll-load: 3 robots at " + sim.baseUri()).containsPattern(
                    "polls [1-9][0-9]* in .* polls/s; errors 0; bad bodies 0; latency p50");
        }
    }

    @Test
    void pollLoadWithoutASimulatorSaysSoAndExitsWith1() throws Exception {
        int port;
        try (ServerSocket free = new ServerSocket(0)) {
            port = free.getLocalPort();
        }
        assertThat(PollLoad.run(new String[] {"--url", "http://127.0.0.1:" + port}, outStream, errStream))
                .isEqualTo(1);
        assertThat(err()).startsWith("poll-load: cannot reach the simulator at http://127.0.0.1:" + port
                + "/ (is it running?)").doesNotContain("\tat ");
    }

    @Test
    void badCommandLinesAreOneLineThenTheUsageAndExitCode2() {
        assertThat(PollLoad.run(new String[] {"--connections", "0"}, outStream, errStream)).isEqualTo(2);
        assertThat(err()).startsWith("poll-load: --connections must be a whole number 1..10000, found '0'\n"
                + "Usage: java -cp benchmarks/target/benchmarks.jar eu.brain.iot.benchmarks.robotsim.PollLoad");
        err.reset();
        assertThat(PollLoad.run(new String[] {"--url", "http://127.0.0.1/"}, outStream, errStream)).isEqualTo(2);
        assertThat(err()).startsWith("poll-load: --url must be http://HOST:PORT/, found 'http://127.0.0.1/'");
        err.reset();
        assertThat(StepBench.run(new String[] {"--seed", "-x"}, outStream, errStream)).isEqualTo(2);
        assertThat(err()).startsWith("step-bench: --seed must be a whole number, found '-x'\nUsage: ");
        err.reset();
        assertThat(StepBench.run(new String[] {"--robots", "5", "--carts", "5000", "--width", "20", "--height",
            "20"}, outStream, errStream)).isEqualTo(2);
        assertThat(err()).startsWith("step-bench: ").contains("carts do not fit");
        assertThat(out()).isEmpty();
    }

    @Test
    void stepBenchTimesStepsOfAGeneratedWarehouse() {
        assertThat(StepBench.run(new String[] {"--robots", "20", "--carts", "40", "--width", "60", "--height", "30",
            "--steps", "5", "--warmup", "2"}, outStream, errStream)).as(err()).isZero();
        assertThat(out()).contains("step-bench: generated-60x30-20r, 20 robots, 40 carts; 2 warm-up steps, 5 measured")
                .contains("step time: mean ").contains("after 12 steps: near misses");
    }
}
