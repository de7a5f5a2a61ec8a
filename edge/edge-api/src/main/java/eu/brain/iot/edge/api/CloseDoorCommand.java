package eu.brain.iot.edge.api;

/** Close a door (at once, or as soon as no robot stands in the doorway). */
public class CloseDoorCommand extends EdgeCommand {
}
