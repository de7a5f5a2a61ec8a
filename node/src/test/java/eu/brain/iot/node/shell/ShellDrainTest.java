package eu.brain.iot.node.shell;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.apache.felix.gogo.runtime.CommandSessionImpl;
import org.apache.felix.gogo.shell.Console;
import org.junit.jupiter.api.Test;

class ShellDrainTest {

    @Test
    void theFrameworkStopWaitsForTheRunningCommandToReturn() throws Exception {
        CommandSessionImpl command = new CommandSessionImpl();
        Thread console = new Thread(new Console(command), "console");
        console.start();
        assertThat(command.entered.await(10, TimeUnit.SECONDS)).isTrue();
        assertThat(ShellDrain.commandRunning()).as("a console thread inside a command").isTrue();

        CompletableFuture<Boolean> drained = CompletableFuture.supplyAsync(
                () -> ShellDrain.awaitNoCommand(Duration.ofSeconds(30)));
        assertThat(drained).as("still waiting while the command runs").isNotDone();
        command.release.countDown();
        assertThat(drained.get(30, TimeUnit.SECONDS)).isTrue();
        console.join(10_000);
        assertThat(ShellDrain.commandRunning()).isFalse();
    }

    @Test
    void aCommandThatNeverReturnsDoesNotKeepTheNodeFromStopping() throws Exception {
        CommandSessionImpl command = new CommandSessionImpl();
        Thread console = new Thread(new Console(command), "console");
        console.start();
        try {
            assertThat(command.entered.await(10, TimeUnit.SECONDS)).isTrue();
            assertThat(ShellDrain.awaitNoCommand(Duration.ofMillis(50))).as("patience ran out").isFalse();
        } finally {
            command.release.countDown();
            console.join(10_000);
        }
    }

    @Test
    void otherThreadsAreNoCommand() {
        StackTraceElement loop = new StackTraceElement(ShellDrain.CONSOLE_LOOP, "run", null, 1);
        StackTraceElement execute = new StackTraceElement(ShellDrain.EXECUTE, "execute", null, 1);
        StackTraceElement read = new StackTraceElement("java.io.FileInputStream", "read", null, 1);
        assertThat(ShellDrain.inCommand(new StackTraceElement[] { execute, loop })).isTrue();
        assertThat(ShellDrain.inCommand(new StackTraceElement[] { read, loop })).as("waiting for a line").isFalse();
        assertThat(ShellDrain.inCommand(new StackTraceElement[] { execute })).as("not the console").isFalse();
    }
}
