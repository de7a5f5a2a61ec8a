package eu.brain.iot.edge.impl;

/** A door's answer to {@code GET /{door}/door_controller/state}, checked by {@link AnswerParser}. */
record DoorAnswer(String id, int x, int y, String state, double data, int stepsLeft) {
}
