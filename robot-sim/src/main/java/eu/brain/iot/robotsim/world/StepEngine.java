package eu.brain.iot.robotsim.world;

import java.util.function.IntPredicate;

/**
 * Advances the world by one step (0.5 s of warehouse time by default). Every robot decides on the state at the
 * start of the step (a synchronous update), so the outcome does not depend on the order robots are looked at:
 * <ol>
 *   <li>doors progress (opening counts down, closing waits for a clear doorway);</li>
 *   <li>each robot starts its next mission if idle, works on a pick or place, or picks the next cell of its path;
 *       its front sensor stops it ({@code detect} 2) before a door that is not open, or ({@code detect} 1) before a
 *       cell that holds a robot;</li>
 *   <li>when several robots want the same free cell, the one with the lowest seeded priority for this step wins,
 *       the others stop with {@code detect} 1;</li>
 *   <li>winners move one cell (a carried cart moves along);</li>
 *   <li>near misses (a robot newly stopped by another robot), waits behind another robot (steps, longest, ended)
 *       and deadlocks are counted.</li>
 * </ol>
 * So two robots never share a cell: a robot only enters a cell that was empty at the start of the step and that no
 * other robot entered. Owned by the world's owner thread.
 */
public final class StepEngine {
    private final World world;
    private final IntPredicate offline;
    private final DeadlockDetector deadlocks;
    private final int[] intent;
    private final int[] claimant;

    /**
     * @param offline tells whether a robot (by index) is offline this step: it then stands still, a plain obstacle
     */
    public StepEngine(World world, IntPredicate offline) {
        this.world = world;
        this.offline = offline;
        this.deadlocks = new DeadlockDetector(world.robots.length);
        this.intent = new int[world.robots.length];
        this.claimant = new int[world.robotAt.length];
        java.util.Arrays.fill(claimant, -1);
    }

    public void step() {
        World w = world;
        w.step++;
        for (Door d : w.doors) {
            d.tick(w.robotAt[w.cell(d.x(), d.y())] >= 0);
        }
        for (Robot r : w.robots) {
            decide(r);
        }
        for (Robot r : w.robots) {
            int target = intent[r.index()];
            if (target >= 0) {
                claimant[target] = -1;
                move(r, target);
            }
        }
        for (Robot r : w.robots) {
            boolean blocked = r.blockedBy >= 0;
            if (blocked && !r.wasBlockedByRobot) {
                r.nearMisses++;
                w.nearMisses++;
            }
            r.wasBlockedByRobot = blocked;
            countWait(r, blocked);
            // between two queued missions a robot is still at work: "running" unless its sensor holds it
            r.running = (r.current != null || !r.queue.isEmpty()) && r.detect == 0 && !r.offline;
        }
        deadlocks.afterStep(w);
    }

    /** A wait behind another robot lasts as long as the robot's front sensor sees one (detect 1) step after step. */
    private void countWait(Robot r, boolean blocked) {
        if (blocked) {
            r.waitSteps++;
            r.waitingSteps++;
            r.longestWaitSteps = Math.max(r.longestWaitSteps, r.waitingSteps);
        } else if (r.waitingSteps > 0) {
            world.endedWaits.merge(r.waitingSteps, 1L, Long::sum);
            r.waitsEnded++;
            r.waitingSteps = 0;
        }
    }

    private void decide(Robot r) {
        int i = r.index();
        intent[i] = -1;
        r.blockedBy = -1;
        r.detect = 0;
        r.offline = offline.test(i);
        if (r.offline) {
            return;
        }
        startNextMission(r);
        Mission m = r.current;
        if (m == null) {
            return;
        }
        if (m.type() == MissionType.GOTO) {
            chooseCell(r);
        } else if (--r.actionLeft <= 0) {
            complete(r, m);
        }
    }

    private void startNextMission(Robot r) {
        while (r.current == null && !r.queue.isEmpty()) {
            Mission m = r.queue.pollFirst();
            m.start();
            r.current = m;
            MissionRules.begin(world, r, m);
        }
    }

    private void complete(Robot r, Mission m) {
        int here = world.cell(r.x, r.y);
        if (m.type() == MissionType.PICK) {
            int cart = world.cartAt[here];
            world.cartAt[here] = -1;
            r.carried = cart;
            world.carts[cart].carriedBy = r.index();
        } else {
            Cart cart = world.carts[r.carried];
            cart.carriedBy = -1;
            cart.x = r.x;
            cart.y = r.y;
            world.cartAt[here] = cart.index();
            r.carried = -1;
        }
        m.finish();
        MissionRules.end(r);
    }

    private void chooseCell(Robot r) {
        World w = world;
        if (!r.hasPathLeft()) {
            r.current.finish();
            MissionRules.end(r);
            return;
        }
        int next = r.nextCell();
        if (r.carried >= 0 && w.cartAt[next] >= 0) {
            // a cart was put down on the planned path: plan again around it
            if (!MissionRules.plan(w, r, r.current)) {
                return;
            }
            next = r.nextCell();
        }
        int width = w.map.width();
        r.heading = Heading.between(r.x, r.y, next % width, next / width);
        int door = w.doorAt[next];
        if (door >= 0 && !w.doors[door].passable()) {
            r.detect = 2;
            return;
        }
        int other = w.robotAt[next];
        if (other >= 0) {
            r.detect = 1;
            r.blockedBy = other;
            return;
        }
        int rival = claimant[next];
        if (rival < 0) {
            claimant[next] = r.index();
            intent[r.index()] = next;
        } else if (priority(r.index()) < priority(rival)) {
            yieldTo(w.robots[rival], r.index());
            claimant[next] = r.index();
            intent[r.index()] = next;
        } else {
            yieldTo(r, rival);
        }
    }

    private void yieldTo(Robot loser, int winner) {
        intent[loser.index()] = -1;
        loser.detect = 1;
        loser.blockedBy = winner;
    }

    private long priority(int robot) {
        long z = world.rules.seed() * 0x9E3779B97F4A7C15L + world.step * 0xBF58476D1CE4E5B9L + robot;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    private void move(Robot r, int target) {
        World w = world;
        int width = w.map.width();
        w.robotAt[w.cell(r.x, r.y)] = -1;
        w.robotAt[target] = r.index();
        r.x = target % width;
        r.y = target / width;
        if (r.carried >= 0) {
            Cart cart = w.carts[r.carried];
            cart.x = r.x;
            cart.y = r.y;
        }
        r.pathPos++;
        if (!r.hasPathLeft()) {
            r.current.finish();
            MissionRules.end(r);
        }
    }
}
