package eu.brain.iot.robotsim;

import eu.brain.iot.robotsim.fault.FaultTable;
import eu.brain.iot.robotsim.view.ViewPublisher;
import eu.brain.iot.robotsim.world.Commands;
import eu.brain.iot.robotsim.world.StepEngine;
import eu.brain.iot.robotsim.world.World;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * The single owner of the {@link World}: one thread ("robot-sim-world") runs every step and every command, so the
 * world needs no lock and stays deterministic for a given map, seed and order of commands. After each step or
 * command it publishes views through the {@link ViewPublisher}, which the HTTP threads read.
 */
public final class WorldThread implements AutoCloseable {
    /** Work done on the world thread; may reject a command by throwing. */
    @FunctionalInterface
    public interface Task<T> {
        T run(Access access) throws Exception;
    }

    /** What a task may touch, only while it runs on the world thread. */
    public record Access(World world, Commands commands, ViewPublisher views) {
        public void publishRobot(int robot) {
            views.publishRobot(world, robot);
        }

        public void publishDoor(int door) {
            views.publishDoor(world, door);
        }
    }

    private final ScheduledExecutorService executor;
    private final Access access;
    private final StepEngine engine;

    WorldThread(World world, FaultTable faults, int maxQueuedMissions) {
        this.executor = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "robot-sim-world");
            t.setDaemon(true);
            return t;
        });
        this.engine = new StepEngine(world, faults::offline);
        this.access = new Access(world, new Commands(world, maxQueuedMissions), new ViewPublisher(world));
    }

    ViewPublisher views() {
        return access.views();
    }

    /** Starts automatic steps at a fixed rate. */
    void startClock(long periodNanos) {
        executor.scheduleAtFixedRate(this::stepSafely, periodNanos, periodNanos, TimeUnit.NANOSECONDS);
    }

    private void stepSafely() {
        try {
            stepOnce();
        } catch (RuntimeException e) {
            // a failing step must not silently stop the clock (scheduleAtFixedRate would)
            System.err.println("robot-sim: step " + access.world().step() + " failed: " + e);
            e.printStackTrace();
        }
    }

    private void stepOnce() {
        engine.step();
        access.views().publishAll(access.world());
    }

    /** Runs a task on the world thread. */
    public <T> CompletableFuture<T> call(Task<T> task) {
        CompletableFuture<T> result = new CompletableFuture<>();
        try {
            executor.execute(() -> {
                try {
                    result.complete(task.run(access));
                } catch (Throwable e) {
                    result.completeExceptionally(e);
                }
            });
        } catch (java.util.concurrent.RejectedExecutionException e) {
            result.completeExceptionally(new IllegalStateException("the simulator is closed"));
        }
        return result;
    }

    /** Runs n steps on the world thread; completes with the step count after them. */
    public CompletableFuture<Long> step(int n) {
        return call(a -> {
            for (int i = 0; i < n; i++) {
                stepOnce();
            }
            return a.world().step();
        });
    }

    @Override
    public void close() {
        executor.shutdownNow();
        try {
            executor.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
