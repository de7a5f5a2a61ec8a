package eu.brain.iot.eventing.integration.exported;

/** One kind of {@link Command}: a consumer of {@code Command} takes it. */
public class StopCommand extends Command {
}
