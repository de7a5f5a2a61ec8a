package eu.brain.iot.edge.model.api;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletionStage;

import org.osgi.annotation.versioning.ProviderType;

import eu.brain.iot.edge.api.CommandOutcome;

/** The edge's device model: read what the fleet looks like now, follow its changes, act on its devices. */
@ProviderType
public interface DeviceModel {

    /** Every provider now known, sorted by id. */
    List<ProviderSnapshot> providers();

    /** One provider, or empty when there is no such provider. */
    Optional<ProviderSnapshot> provider(String providerId);

    /** One resource, or empty when the provider, the service or the resource does not exist. */
    Optional<ResourceValue> resource(String providerId, String service, String resource);

    /**
     * Follow changes. {@code providerId} and {@code service} narrow what is followed; {@code null} means any.
     * The listener first receives nothing of the present state (read it with {@link #provider(String)}); then
     * every change, until the returned handle is closed.
     */
    Subscription subscribe(String providerId, String service, ResourceListener listener);

    /**
     * Run an action resource (sensiNact's ACT): for robots, service {@code control}, actions {@code goTo}
     * ({@code x}, {@code y}), {@code pick}, {@code place}, {@code cancel} ({@code missionType}, {@code missionId}
     * optional); for doors, service {@code control}, actions {@code open} and {@code close}.
     * <p>
     * The returned stage completes with the device's answer, accepted or rejected with the reason. The same
     * {@link CommandOutcome} is published on the event bus.
     *
     * @throws UnknownResourceException when the provider or the action does not exist
     * @throws IllegalArgumentException when a parameter is missing or of the wrong type (the message names it)
     */
    CompletionStage<CommandOutcome> act(String providerId, String service, String action,
            Map<String, Object> parameters);

    /** Stops a subscription. */
    @ProviderType
    interface Subscription extends AutoCloseable {
        @Override
        void close();
    }
}
