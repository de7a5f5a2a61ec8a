package eu.brain.iot.robotsim.world;

/**
 * What a robot checks when it starts a mission, and how a mission ends. A mission whose precondition does not hold
 * when its turn comes fails with a reason (it could have held when it was queued). Owned by the world's owner thread.
 */
final class MissionRules {
    private MissionRules() {
    }

    static void begin(World w, Robot r, Mission m) {
        int here = w.cell(r.x, r.y);
        switch (m.type()) {
            case GOTO -> {
                if (plan(w, r, m) && !r.hasPathLeft()) {
                    m.finish();
                    end(r);
                }
            }
            case PICK -> {
                if (r.carried >= 0) {
                    failCurrent(r, "already carrying " + w.carts[r.carried].id());
                } else if (w.cartAt[here] < 0) {
                    failCurrent(r, "no cart at (" + r.x + "," + r.y + ")");
                } else {
                    r.actionLeft = w.rules.pickSteps();
                }
            }
            case PLACE -> {
                if (r.carried < 0) {
                    failCurrent(r, "not carrying a cart");
                } else if (w.cartAt[here] >= 0) {
                    failCurrent(r, "(" + r.x + "," + r.y + ") already holds " + w.carts[w.cartAt[here]].id());
                } else if (w.doorAt[here] >= 0) {
                    failCurrent(r, "a cart may not be put down in a doorway");
                } else {
                    r.actionLeft = w.rules.placeSteps();
                }
            }
            default -> throw new IllegalStateException("unknown mission type " + m.type());
        }
    }

    /** Plans the current GOTO from where the robot stands; fails the mission when no path exists. */
    static boolean plan(World w, Robot r, Mission m) {
        int[] path = w.planner.plan(w.cell(r.x, r.y), w.cell(m.goalX(), m.goalY()), w.cartAt, r.carried >= 0);
        if (path == null) {
            failCurrent(r, "no path from (" + r.x + "," + r.y + ") to (" + m.goalX() + "," + m.goalY() + ")"
                    + (r.carried >= 0 ? " for a robot carrying a cart" : ""));
            return false;
        }
        r.setPath(path);
        return true;
    }

    static void failCurrent(Robot r, String reason) {
        r.current.fail(reason);
        end(r);
    }

    static void end(Robot r) {
        r.remember(r.current);
        r.endCurrent();
    }
}
