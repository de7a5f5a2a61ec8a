package eu.brain.iot.scenario;

import java.util.Locale;

/**
 * One line of live progress, plain text (no terminal escape codes, so it reads the same in a log or a pipe):
 * warehouse time, carts delivered, door openings, robot-in-front detections and how they were resolved, commands.
 * Stateless.
 */
final class ProgressLine {
    private ProgressLine() {
    }

    static String of(WorldSnapshot start, WorldSnapshot now) {
        return String.format(Locale.ROOT,
                "[%12s] carts %d/%d delivered | door openings %d | robot in front %d: %d waits ended, %d waiting, "
                        + "longest %s | commands %d accepted, %d refused",
                WarehouseTime.format(Figures.elapsedMs(start, now)), now.cartsInStorage(), now.cartCount(),
                now.doorOpenings(), now.nearMisses() - start.nearMisses(), now.waitsEnded() - start.waitsEnded(),
                now.waitingNow(), WarehouseTime.format(now.longestWaitMs()), now.commandsAccepted(),
                now.commandsRefused());
    }
}
