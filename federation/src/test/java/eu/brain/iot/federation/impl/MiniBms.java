package eu.brain.iot.federation.impl;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy;

/**
 * The part of the BMS that the fabric's installer serves, as the multi-node tests need it: every unhandled event of
 * a watched type is held; the first asks the installer's {@code find} for the type hierarchy and installs the first
 * candidate on the node it names, as the BMS does ({@code InstallRequest.node}), passing the installer the fields of
 * that first event as the bus gives them ({@code find(types, event)}). Thread-safe (concurrent map, futures).
 */
final class MiniBms implements UnhandledEventPolicy {

    private final BundleInstaller installer;
    private final String watched;
    final CompletableFuture<List<BehaviourCandidate>> found = new CompletableFuture<>();
    final CompletableFuture<InstalledBehaviour> outcome = new CompletableFuture<>();
    private final ConcurrentHashMap<String, Boolean> asked = new ConcurrentHashMap<>();

    MiniBms(BundleInstaller installer, String watched) {
        this.installer = installer;
        this.watched = watched;
    }

    @Override
    public Disposition unhandled(String eventType, List<String> typeHierarchy) {
        return unhandled(eventType, typeHierarchy, Map::of);
    }

    @Override
    public Disposition unhandled(String eventType, List<String> typeHierarchy,
            Supplier<Map<String, Object>> fields) {
        if (!eventType.equals(watched)) {
            return Disposition.LAST_RESORT;
        }
        if (asked.putIfAbsent(eventType, Boolean.TRUE) == null) {
            installer.find(typeHierarchy, fields.get()).onFailure(found::completeExceptionally).onSuccess(candidates -> {
                found.complete(candidates);
                if (candidates.isEmpty()) {
                    outcome.completeExceptionally(new IllegalStateException("no candidate"));
                    return;
                }
                BehaviourCandidate best = candidates.get(0);
                InstallRequest request = new InstallRequest();
                request.symbolicName = best.symbolicName;
                request.versionRange = "[" + best.version + "," + best.version + "]";
                request.consumedTypes = typeHierarchy;
                request.reason = "an event of type " + eventType + " had no consumer (test)";
                request.node = best.node;
                installer.install(request).onSuccess(outcome::complete).onFailure(outcome::completeExceptionally);
            });
        }
        return Disposition.HOLD;
    }

    @Override
    public int maxHeldEvents() {
        return 100_000;
    }
}
