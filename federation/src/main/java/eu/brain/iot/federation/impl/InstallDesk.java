package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.ScheduledExecutorService;
import java.util.function.Consumer;
import java.util.function.Supplier;

import org.osgi.util.promise.Promise;
import org.osgi.util.promise.Promises;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.federation.impl.InstallChoice.Offer;

/**
 * The answering side of {@link FabricInstaller}: this node's offer to a {@code bid} (its local installer's
 * {@code find}, from memory, its load: the behaviours that installer installed, and which of the devices the event
 * names it owns, from its edge's memory), and an {@code order} from
 * another node carried out by the local installer, its {@code result} sent back. A node without an installer offers
 * nothing and refuses orders ({@code CLOSED}), so that the asking node need not wait for its deadline.
 * <p>
 * Threads: the fabric's inbound thread calls it and sends; the local installer's answers are queued back there.
 * Stateless beyond its collaborators.
 */
final class InstallDesk {

    private final Settings settings;
    private final ScheduledExecutorService in;
    private final FabricInstaller.Sending sending;
    private final Supplier<BundleInstaller> local;
    private final Supplier<OwnedDevices> owned;
    private final Host host;

    InstallDesk(Settings settings, ScheduledExecutorService in, FabricInstaller.Sending sending,
            Supplier<BundleInstaller> local, Supplier<OwnedDevices> owned, Host host) {
        this.settings = settings;
        this.in = in;
        this.sending = sending;
        this.local = local;
        this.owned = owned;
        this.host = host;
    }

    private String self() {
        return settings.node();
    }

    /** The devices among {@code devices} this node owns, from its edge's memory; none when it cannot say. */
    private List<String> owns(List<String> devices) {
        OwnedDevices mine = owned.get();
        try {
            return devices.stream().filter(mine::owns).toList();
        } catch (RuntimeException e) {
            return List.of(); // an edge going away: as a node without one
        }
    }

    /** This node's offer for an event of {@code types} naming {@code devices}, from memory; on the inbound thread. */
    void offer(List<String> types, List<String> devices, Consumer<Offer> then) {
        BundleInstaller mine = local.get();
        if (mine == null) {
            then.accept(new Offer(self(), List.of(), 0));
            return;
        }
        Promise<List<BehaviourCandidate>> found;
        try {
            found = mine.find(types);
        } catch (RuntimeException e) {
            found = Promises.failed(e);
        }
        Promise<List<BehaviourCandidate>> f = found;
        Runnable give = () -> {
            List<BehaviourCandidate> candidates = List.of();
            try {
                if (f.getFailure() == null && f.getValue() != null) {
                    candidates = f.getValue();
                }
            } catch (Exception e) {
                // no offer from a failed search
            }
            int load;
            try {
                load = mine.installed().size();
            } catch (RuntimeException e) {
                load = Integer.MAX_VALUE;
            }
            then.accept(new Offer(self(), candidates, load, candidates.isEmpty() ? List.of() : owns(devices)));
        };
        if (f.isDone()) {
            give.run();
        } else {
            f.onResolve(() -> in.execute(give));
        }
    }

    void installHere(Wire.Install m) {
        BundleInstaller mine = local.get();
        if (mine == null) {
            reply(m, Wire.Install.RESULT, r -> {
                r.problem = Problem.CLOSED.name();
                r.message = "it has no Bundle Installer Service";
            });
            return;
        }
        InstallRequest request = m.request();
        request.node = null;
        request.operator = false; // another node's BMS: an automatic request
        host.info("Fabric {}: node {} installs {} as node {} asked", settings.fabric(), self(),
                request.symbolicName, m.from());
        Promise<InstalledBehaviour> done;
        try {
            done = mine.install(request);
        } catch (RuntimeException e) {
            done = Promises.failed(e);
        }
        Promise<InstalledBehaviour> d = done;
        d.onResolve(() -> in.execute(() -> reply(m, Wire.Install.RESULT, r -> {
            try {
                Throwable failure = d.getFailure();
                if (failure == null) {
                    r.ok = true;
                    r.installed = d.getValue();
                } else {
                    r.problem = failure instanceof InstallException ie ? ie.problem().name()
                            : Problem.START_FAILED.name();
                    r.message = failure.getMessage() == null ? failure.toString() : failure.getMessage();
                }
            } catch (Exception e) {
                r.problem = Problem.START_FAILED.name();
                r.message = e.toString();
            }
        })));
    }

    void reply(Wire.Install to, String op, Consumer<Draft> fill) {
        try {
            sending.send(to.from(), message(op, to.from(), to.id(), fill));
        } catch (IOException e) {
            host.warn("Fabric {}: the {} to node {} was not sent ({}); it asks again if it still needs it",
                    settings.fabric(), op, to.from(), e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The fields of a message being written. */
    static final class Draft {
        List<String> types;
        List<BehaviourCandidate> candidates;
        int load;
        List<String> devices;
        List<String> owns;
        InstallRequest request;
        boolean ok;
        String problem;
        String message;
        InstalledBehaviour installed;
    }

    Wire.Install message(String op, String to, String id, Consumer<Draft> fill) {
        Draft d = new Draft();
        fill.accept(d);
        return new Wire.Install(op, self(), to, System.currentTimeMillis(), id, d.types, d.candidates, d.load,
                d.request, d.ok, d.problem, d.message, d.installed, d.devices, d.owns);
    }

}
