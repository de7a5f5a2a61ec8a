package eu.brain.iot.bms.impl;

import java.util.List;
import java.util.Set;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.LongAdder;

import org.osgi.service.log.Logger;

import eu.brain.iot.bms.api.BehaviourInstallFailed;
import eu.brain.iot.bms.api.BehaviourInstalled;
import eu.brain.iot.bms.api.BehaviourNotFound;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;

/**
 * Makes the BMS's alert events and publishes them on the bus from a thread of their own ({@code executor}), so
 * that a slow consumer of alerts (the bus's overflow wait) never delays an install. The BMS never searches for
 * these types: {@link #TYPES}.
 */
final class Alerts {

    /** The alert types; an unhandled alert goes to the consumers of last resort, never to a search. */
    static final Set<String> TYPES = Set.of(BehaviourNotFound.class.getName(),
            BehaviourInstallFailed.class.getName(), BehaviourInstalled.class.getName());

    private final EventBus bus;
    private final Executor executor;
    private final Logger log;
    private final LongAdder published;
    private final AtomicBoolean failureLogged = new AtomicBoolean();

    Alerts(EventBus bus, Executor executor, Logger log, LongAdder published) {
        this.bus = bus;
        this.executor = executor;
        this.log = log;
        this.published = published;
    }

    void notFound(String eventType, List<String> searched, int held, long retryAfter) {
        BehaviourNotFound alert = new BehaviourNotFound();
        alert.eventType = eventType;
        alert.searched = List.copyOf(searched);
        alert.heldEvents = held;
        alert.retryAfter = retryAfter;
        publish(alert);
    }

    void installFailed(String eventType, String behaviour, String problem, String reason, int attempt, long nextRetry,
            int held) {
        BehaviourInstallFailed alert = new BehaviourInstallFailed();
        alert.eventType = eventType;
        alert.behaviour = behaviour;
        alert.problem = problem;
        alert.reason = reason;
        alert.attempt = attempt;
        alert.nextRetry = nextRetry;
        alert.finalFailure = nextRetry == 0;
        alert.heldEvents = held;
        publish(alert);
    }

    void installed(List<String> eventTypes, String symbolicName, String version, String repository, long durationMs,
            int attempt) {
        BehaviourInstalled alert = new BehaviourInstalled();
        alert.eventTypes = List.copyOf(eventTypes);
        alert.behaviour = symbolicName;
        alert.version = version;
        alert.repository = repository;
        alert.durationMs = durationMs;
        alert.attempt = attempt;
        publish(alert);
    }

    private void publish(BrainIoTEvent alert) {
        executor.execute(() -> {
            try {
                bus.deliver(alert);
                published.increment();
            } catch (RuntimeException e) {
                if (failureLogged.compareAndSet(false, true)) {
                    log.warn("Behaviour Management Service: could not publish the alert {} ({}); later failures to "
                            + "publish alerts are not logged", alert.getClass().getSimpleName(), e.getMessage());
                }
            }
        });
    }
}
