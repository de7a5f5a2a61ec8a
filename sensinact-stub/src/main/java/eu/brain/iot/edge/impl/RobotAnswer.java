package eu.brain.iot.edge.impl;

/**
 * A robot's answer to {@code GET /{robot}/robot_local_control/state}, checked by {@link AnswerParser}.
 *
 * @param mission the running mission, else the next queued, else the last ended; {@code null} before any
 */
record RobotAnswer(String id, int x, int y, String heading, int area, String state, int detect, String cart,
        Mission mission, int nearMisses, int deadlocks) {

    /** @param goalX the goal of a {@code goto}, else {@code null} */
    record Mission(long id, String type, String state, String reason, Integer goalX, Integer goalY) {

        boolean ended() {
            return "finished".equals(state) || "failed".equals(state);
        }
    }
}
