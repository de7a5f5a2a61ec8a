package eu.brain.iot.node;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What {@code ./fabric-node} itself prints while it builds, with a stand-in for {@code mvn} (first on the PATH) that
 * writes what Debian's Maven 3.8.7 writes: colour resets (ESC[0m) even with -B, no newline at its end, the module
 * lines and, on a first build, download lines. The script's lines carry no escape code, each starts a line, and a
 * failed build shows Maven's errors and exits with 1.
 */
class FabricNodeScriptTest {

    private static final Path SCRIPT = Path.of("..", "fabric-node").toAbsolutePath().normalize();
    private static final String ESC = "\u001b";

    @TempDir
    Path bin;
    @TempDir
    Path configDir;

    @Test
    void aFirstBuildSaysWhatItBuildsThatItDownloadsAndHowLongItTook() throws Exception {
        fakeMaven(0, """
                printf '\\033[0m\\033[0m[INFO] Scanning for projects...\\n'
                printf '[INFO] Building BRAIN-IoT fabric 0.1.0-SNAPSHOT                    [1/2]\\n'
                printf '[INFO] Downloading from central: https://repo.maven.apache.org/x.pom\\n'
                printf '[INFO] Downloaded from central: https://repo.maven.apache.org/x.pom (2 kB at 9 kB/s)\\n'
                printf '[INFO] Building BRAIN-IoT fabric: runnable fabric node 0.1.0-SNAPSHOT [2/2]\\n'
                printf '[INFO] BUILD SUCCESS\\n\\033[0m\\033[0m'
                """);
        Result result = run("--rebuild", "--check", "-Dfelix.fileinstall.dir=" + configDir,
                "--http-port=" + NodeProcess.freePort(), "--state=" + configDir.resolve("state"));
        assertThat(result.code).as(result.output).isZero();
        assertThat(result.output).doesNotContain(ESC);
        List<String> lines = result.output.lines().toList();
        assertThat(lines.get(0)).startsWith("fabric-node: building node and the modules it needs (mvn -B -pl node -am "
                + "package -DskipTests; log: node/target/fabric-node-build.log)");
        assertThat(lines.get(1)).startsWith("fabric-node: first build here: Maven downloads");
        assertThat(lines.get(2)).matches("fabric-node: built in \\d+ s \\(1 file downloaded\\)");
        assertThat(result.output).containsPattern("(?m)^fabric node ready in ");
    }

    @Test
    void aFailedBuildShowsMavensErrorsAndExitsWith1() throws Exception {
        fakeMaven(1, """
                printf '[INFO] Building BRAIN-IoT fabric: event bus 0.1.0-SNAPSHOT [1/2]\\n'
                printf '\\033[1;31m[ERROR]\\033[m Failed to execute goal on project eventbus: Compilation failure\\n'
                printf '[ERROR] -> [Help 1]\\n\\033[0m'
                """);
        Result result = run("--rebuild", "--check", "-Dfelix.fileinstall.dir=" + configDir);
        assertThat(result.code).as(result.output).isEqualTo(1);
        assertThat(result.output).doesNotContain(ESC).doesNotContain("[Help 1]").containsPattern(
                "(?m)^fabric-node: the build failed \\(mvn exit code 1\\).*\\n  \\[ERROR\\] Failed to execute goal on "
                        + "project eventbus: Compilation failure$")
                .doesNotContain("fabric node ready");
    }

    @Test
    void onATerminalTheBuildsStatusLineNamesNoModuleBeforeMavenNamesOne() throws Exception {
        fakeMaven(0, """
                printf '[INFO] Scanning for projects...\\n'
                printf '[INFO] Downloaded from central: https://repo.maven.apache.org/x.pom (2 kB at 9 kB/s)\\n'
                printf '[INFO] Building BRAIN-IoT fabric: event bus 0.1.0-SNAPSHOT [1/2]\\n'
                printf '[INFO] BUILD SUCCESS\\n'
                """);
        String command = String.join(" ", "bash", SCRIPT.toString(), "--rebuild", "--check",
                "-Dfelix.fileinstall.dir=" + configDir, "--http-port=" + NodeProcess.freePort(),
                "--state=" + configDir.resolve("state"));
        Result result = run(List.of("script", "-qefc", command, "/dev/null"), Map.of()); // a terminal: the status line

        assertThat(result.code).as(result.output).isZero();
        assertThat(result.output).contains("fabric-node: reading the project, 1 file downloaded")
                .contains("fabric-node: module 1/2: event bus, 1 file downloaded")
                .doesNotContain("module 0/?").doesNotContain("module /").doesNotContain(": ,");
    }

    @Test
    void theDefaultStateFolderIsTheNodesNameAndCheckoutUnderXdgStateHome() throws Exception {
        fakeMaven(0, "");
        Path xdg = configDir.resolve("xdg");
        String checkout = SCRIPT.getParent().toString();
        String hash = java.util.HexFormat.of().formatHex(java.security.MessageDigest.getInstance("SHA-256")
                .digest(checkout.getBytes(StandardCharsets.UTF_8)), 0, 4);

        Result result = run(List.of("bash", SCRIPT.toString(), "--check", "--name=alpha",
                "-Dfelix.fileinstall.dir=" + configDir, "--http-port=" + NodeProcess.freePort()),
                Map.of("XDG_STATE_HOME", xdg.toString()));

        assertThat(result.code).as(result.output).isZero();
        assertThat(xdg.resolve("brain-iot").resolve("alpha-" + hash).resolve("node.lock")).exists();
    }

    @Test
    void aBadNameOrPortIsRefusedByTheScript() throws Exception {
        Result name = run(List.of("bash", SCRIPT.toString(), "--name=../x"), Map.of());
        assertThat(name.code).isEqualTo(2);
        assertThat(name.output).contains("--name needs letters, digits");
        Result port = run(List.of("bash", SCRIPT.toString(), "--http-port=99999"), Map.of());
        assertThat(port.code).isEqualTo(2);
        assertThat(port.output).contains("--http-port needs a port 1..65535, found '99999'");
    }

    @Test
    void severalNodesAreRefusedBeforeAnythingStartsWhenAnOptionOrTheBrokerIsWrong() throws Exception {
        Result spaced = run("--nodes", "3");
        assertThat(spaced.code).isEqualTo(2);
        assertThat(spaced.output).contains("--nodes takes its value after '=', e.g. --nodes=3");
        Result port = run("--nodes=2", "--broker=tcp://127.0.0.1:99999");
        assertThat(port.code).isEqualTo(2);
        assertThat(port.output).contains("--broker needs a broker URI with a port 1..65535, such as "
                + "tcp://127.0.0.1:1883, found 'tcp://127.0.0.1:99999'");

        int closed;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            closed = s.getLocalPort();
        }
        Path state = configDir.resolve("fabric");
        Result nobody = run("--nodes=2", "--broker=tcp://127.0.0.1:" + closed, "--state=" + state);
        assertThat(nobody.code).isEqualTo(1);
        assertThat(nobody.output).contains("nothing answers at 127.0.0.1:" + closed + " (--broker=tcp://127.0.0.1:"
                + closed + ") within 3 s: start the broker there, or leave --broker out for the embedded one");
        assertThat(state).as("nothing made, no key").doesNotExist();

        try (java.net.ServerSocket taken = new java.net.ServerSocket(0, 1,
                java.net.InetAddress.getLoopbackAddress())) {
            Result busy = run("--nodes=2", "--broker-port=" + taken.getLocalPort(), "--state=" + state);
            assertThat(busy.code).isEqualTo(1);
            assertThat(busy.output).contains("port " + taken.getLocalPort() + " of 127.0.0.1 is taken")
                    .doesNotContain("building");
            assertThat(state).as("nothing made or built before the port is found taken").doesNotExist();
        }
    }

    @Test
    void aTakenRestPortIsRefusedBeforeAnythingIsMadeOrBuilt() throws Exception {
        fakeMaven(3, "echo 'mvn must not run: the port is found taken first' >&2\n");
        Path state = configDir.resolve("fabric");
        try (java.net.ServerSocket broker = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress());
                java.net.ServerSocket taken = new java.net.ServerSocket(0, 1,
                        java.net.InetAddress.getLoopbackAddress())) {
            int port = taken.getLocalPort();
            // one node joining a broker (the test's socket answers as one would), on the taken port
            Result one = run("--broker=tcp://127.0.0.1:" + broker.getLocalPort(), "--name=node3", "--no-shell",
                    "--http-port=" + port, "--state=" + state);
            assertThat(one.code).as(one.output).isEqualTo(1);
            assertThat(one.output).contains("port " + port + " of 127.0.0.1, for node3's REST API and dashboard, is "
                    + "taken (another node or program listens there): choose another with --http-port=N")
                    .doesNotContain("mvn must not run").doesNotContain("ready");
            assertThat(state).as("nothing made or built before the port is found taken").doesNotExist();

        }
        // several nodes: node K's port is N+K-1, here node2's is the taken one
        try (java.net.ServerSocket taken = secondOfTwoPorts()) {
            int port = taken.getLocalPort();
            Result several = run("--nodes=2", "--http-port=" + (port - 1), "--broker-port=" + NodeProcess.freePort(),
                    "--state=" + state);
            assertThat(several.code).as(several.output).isEqualTo(1);
            assertThat(several.output).contains("port " + port + " of 127.0.0.1, for node2's REST API and dashboard,"
                    + " is taken (another node or program listens there): choose other ports with --http-port=N (node"
                    + " K gets N+K-1; now N is " + (port - 1) + ")").doesNotContain("mvn must not run");
            assertThat(state).as("nothing made or built before the port is found taken").doesNotExist();
        }
    }

    /** A socket listening on port N+1 of 127.0.0.1 where port N is free now. */
    private static java.net.ServerSocket secondOfTwoPorts() throws IOException {
        for (int tries = 0; tries < 50; tries++) {
            int port = NodeProcess.freePort();
            if (port < 65535) {
                try {
                    return new java.net.ServerSocket(port + 1, 1, java.net.InetAddress.getLoopbackAddress());
                } catch (IOException taken) {
                    // try another
                }
            }
        }
        throw new IOException("no two free consecutive ports on 127.0.0.1");
    }

    private void fakeMaven(int exitCode, String body) throws IOException {
        Path mvn = bin.resolve("mvn");
        Files.writeString(mvn, "#!/bin/sh\n" + body + "exit " + exitCode + "\n");
        Files.setPosixFilePermissions(mvn, PosixFilePermissions.fromString("rwxr-xr-x"));
    }

    private record Result(int code, String output) {
    }

    private Result run(String... args) throws Exception {
        List<String> command = new java.util.ArrayList<>(List.of("bash", SCRIPT.toString()));
        command.addAll(List.of(args));
        return run(command, Map.of());
    }

    private Result run(List<String> command, Map<String, String> environment) throws Exception {
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null")));
        builder.environment().put("PATH", bin + ":" + System.getenv("PATH"));
        builder.environment().putAll(environment);
        Process process = builder.start();
        byte[] output = process.getInputStream().readAllBytes();
        if (!process.waitFor(NodeProcess.DEADLINE.toSeconds(), TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("the script did not end; output:\n" + new String(output, StandardCharsets.UTF_8));
        }
        return new Result(process.exitValue(), new String(output, StandardCharsets.UTF_8));
    }

}
