package eu.brain.iot.edge.api;

/** Open a door (it takes a few steps: {@code opening}, then {@code open}). */
public class OpenDoorCommand extends EdgeCommand {
}
