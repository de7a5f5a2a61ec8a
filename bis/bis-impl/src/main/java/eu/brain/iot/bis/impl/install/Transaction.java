package eu.brain.iot.bis.impl.install;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.stream.Collectors;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleException;
import org.osgi.framework.FrameworkListener;
import org.osgi.framework.startlevel.BundleStartLevel;
import org.osgi.framework.wiring.BundleRevision;
import org.osgi.framework.wiring.BundleWire;
import org.osgi.framework.wiring.BundleWiring;
import org.osgi.framework.wiring.FrameworkWiring;
import org.osgi.resource.Requirement;
import org.osgi.resource.Resource;
import org.osgi.resource.Wire;
import org.osgi.service.resolver.ResolutionException;
import org.osgi.service.resolver.Resolver;

import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.impl.repo.BehaviourResource;
import eu.brain.iot.bis.impl.repo.Repositories;

/**
 * One install, all or nothing, in two steps: {@link #plan} resolves the behaviour with the OSGi Resolver against the
 * framework and the repositories and lists the bundles the framework lacks, which the installer then downloads and
 * verifies ({@link Downloads}, off the installer's thread); {@link #apply} installs them from the verified files,
 * starts them, dependencies first, and waits until the behaviour's smart behaviours are registered with the bus. Any
 * failure uninstalls what this transaction installed and refreshes the framework, so that it is as before. Runs on
 * the installer's thread only.
 */
final class Transaction {

    /** What an install put into the framework, and which bundles already there it uses. */
    record Result(Bundle own, List<Installed> installed, List<Bundle> reused) {
    }

    /** A bundle installed now, with its index facts. */
    record Installed(Bundle bundle, BehaviourResource facts) {
    }

    /** A resolution and the bundles to download and install for it, dependencies first. */
    record Plan(BehaviourResource behaviour, Map<Resource, List<Wire>> resolution, List<BehaviourResource> order) {
    }

    private final BundleContext context;
    private final Resolver resolver;
    private final Repositories repositories;
    private final Activation activation;
    private final long activationTimeoutMillis;
    private final Consumer<String> warn;

    Transaction(BundleContext context, Resolver resolver, Repositories repositories, Activation activation,
            long activationTimeoutMillis, Consumer<String> warn) {
        this.context = context;
        this.resolver = resolver;
        this.repositories = repositories;
        this.activation = activation;
        this.activationTimeoutMillis = activationTimeoutMillis;
        this.warn = warn;
    }

    Plan plan(BehaviourResource behaviour) throws InstallException {
        Map<Resource, List<Wire>> resolution = resolve(behaviour);
        return new Plan(behaviour, resolution, installOrder(behaviour, resolution));
    }

    /** @param files the verified file of every bundle of the plan, by {@link Downloads#key} */
    Result apply(Plan plan, Map<String, java.nio.file.Path> files) throws InstallException, InterruptedException {
        BehaviourResource behaviour = plan.behaviour();
        Map<Resource, List<Wire>> resolution = plan.resolution();
        List<Installed> installed = new ArrayList<>();
        try {
            for (BehaviourResource r : plan.order()) {
                installed.add(new Installed(install(r, files.get(Downloads.key(r))), r));
            }
            for (Installed i : installed) {
                start(i);
            }
            Bundle own = installed.stream().filter(i -> i.facts() == behaviour).findFirst().orElseThrow().bundle();
            if (activation.await(own, activationTimeoutMillis) == null) {
                throw new InstallException(Problem.ACTIVATION_TIMEOUT, behaviour + " started, but no smart behaviour"
                        + " of it was registered with the event bus within " + activationTimeoutMillis + " ms ("
                        + activation.missing(own) + "; " + ComponentStates.of(context, own) + "; 'scr:info' in"
                        + " the shell says more); raise activation.timeout.ms of eu.brain.iot.bis if the node is"
                        + " merely slow");
            }
            return new Result(own, installed, reused(resolution));
        } catch (InstallException | InterruptedException | RuntimeException e) {
            rollBack(installed.stream().map(Installed::bundle).toList());
            throw e;
        }
    }

    /** Uninstalls the bundles (last installed first) and refreshes the framework; waits for the refresh. */
    void rollBack(List<Bundle> bundles) throws InterruptedException {
        List<Bundle> reversed = new ArrayList<>(bundles);
        java.util.Collections.reverse(reversed);
        for (Bundle b : reversed) {
            try {
                if (b.getState() != Bundle.UNINSTALLED) {
                    b.uninstall();
                }
            } catch (BundleException | IllegalStateException e) {
                warn.accept("could not uninstall " + b.getSymbolicName() + " (bundle " + b.getBundleId() + "): " + e);
            }
        }
        refresh(reversed);
    }

    private void refresh(Collection<Bundle> bundles) throws InterruptedException {
        if (bundles.isEmpty()) {
            return;
        }
        CountDownLatch done = new CountDownLatch(1);
        FrameworkListener listener = event -> done.countDown();
        context.getBundle(0).adapt(FrameworkWiring.class).refreshBundles(bundles, listener);
        if (!done.await(30, TimeUnit.SECONDS)) {
            warn.accept("the framework did not finish refreshing after an uninstall within 30 s");
        }
    }

    private Map<Resource, List<Wire>> resolve(BehaviourResource behaviour) throws InstallException {
        try {
            return resolver.resolve(new NodeResolveContext(context, behaviour.resource(), repositories));
        } catch (ResolutionException e) {
            String missing = e.getUnresolvedRequirements().stream().map(Transaction::describe)
                    .collect(Collectors.joining("; "));
            throw new InstallException(Problem.UNRESOLVED, behaviour + " cannot be resolved: "
                    + (missing.isEmpty() ? firstLine(e.getMessage()) : "missing " + missing)
                    + ". No bundle in the framework or in the repositories provides it: add a bundle that does to an"
                    + " index (and re-sign it), or install it into the node. Resolver: " + firstLine(e.getMessage()));
        }
    }

    /** The repository resources of a resolution, each after the resources it is wired to. */
    private List<BehaviourResource> installOrder(BehaviourResource behaviour, Map<Resource, List<Wire>> resolution)
            throws InstallException {
        Set<Resource> ordered = new LinkedHashSet<>();
        for (Resource r : resolution.keySet()) {
            visit(r, resolution, ordered, new LinkedHashSet<>());
        }
        List<BehaviourResource> order = new ArrayList<>();
        for (Resource r : ordered) {
            if (r instanceof BundleRevision) {
                continue; // in the framework already
            }
            BehaviourResource facts = r == behaviour.resource() ? behaviour : repositories.facts(r).orElse(null);
            if (facts == null) {
                throw new InstallException(Problem.UNRESOLVED, behaviour + " needs " + r + ", which has no"
                        + " osgi.content (URL, SHA-256) in its index: regenerate the index with bnd's indexer");
            }
            order.add(facts);
        }
        return order;
    }

    private static void visit(Resource r, Map<Resource, List<Wire>> resolution, Set<Resource> done,
            Set<Resource> path) {
        if (done.contains(r) || !path.add(r)) {
            return; // done, or a cycle: any order among its members will do, the framework resolves them together
        }
        for (Wire wire : resolution.getOrDefault(r, List.of())) {
            if (resolution.containsKey(wire.getProvider())) {
                visit(wire.getProvider(), resolution, done, path);
            }
        }
        done.add(r);
    }

    /** The framework's bundles (not the system bundle) that the new resources use, directly or through others. */
    private List<Bundle> reused(Map<Resource, List<Wire>> resolution) {
        Set<Bundle> reused = new LinkedHashSet<>();
        List<BundleRevision> todo = new ArrayList<>();
        resolution.values().forEach(wires -> wires.forEach(w -> {
            if (w.getProvider() instanceof BundleRevision rev) {
                todo.add(rev);
            }
        }));
        while (!todo.isEmpty()) {
            BundleRevision rev = todo.remove(todo.size() - 1);
            if (rev.getBundle().getBundleId() == 0 || !reused.add(rev.getBundle())) {
                continue;
            }
            BundleWiring wiring = rev.getWiring();
            if (wiring != null) {
                for (BundleWire w : wiring.getRequiredWires(null)) {
                    todo.add(w.getProvider());
                }
            }
        }
        return new ArrayList<>(reused);
    }

    private Bundle install(BehaviourResource r, java.nio.file.Path file) throws InstallException {
        String location = r.url().toString();
        if (context.getBundle(location) != null) {
            throw new InstallException(Problem.START_FAILED, r + ": a bundle is already installed from " + location
                    + " (bundle " + context.getBundle(location).getBundleId() + ") with another identity: uninstall"
                    + " it first");
        }
        try (java.io.InputStream in = java.nio.file.Files.newInputStream(file)) {
            Bundle installed = context.installBundle(location, in);
            // A launcher may give bundles installed at run time a start level above the one the framework is at
            // (bnd's launcher: above every run bundle), and start() would then only mark them for later: a
            // behaviour would not run until the framework climbed there. The installer's own level is reached.
            // Set only when it differs: Felix applies the change later on its start-level thread, which logs an
            // ERROR ("Bundle in unexpected state") if the bundle is uninstalled (a rollback) before it gets there.
            BundleStartLevel level = installed.adapt(BundleStartLevel.class);
            int own = context.getBundle().adapt(BundleStartLevel.class).getStartLevel();
            if (level.getStartLevel() != own) {
                level.setStartLevel(own);
            }
            return installed;
        } catch (BundleException | IOException e) {
            throw new InstallException(Problem.START_FAILED, r + " from " + r.url() + " could not be installed: "
                    + e.getMessage(), e);
        }
    }

    private void start(Installed i) throws InstallException {
        Bundle b = i.bundle();
        if (b.getHeaders().get(org.osgi.framework.Constants.FRAGMENT_HOST) != null) {
            return; // fragments are not started; they attach to their host
        }
        try {
            b.start();
        } catch (BundleException | IllegalStateException e) {
            throw new InstallException(Problem.START_FAILED, i.facts() + " (bundle " + b.getBundleId() + ") failed to"
                    + " start: " + firstLine(e.getMessage()) + (e.getCause() == null ? ""
                            : " (" + firstLine(String.valueOf(e.getCause())) + ")")
                    + ". Everything this install put into the node was uninstalled; fix the bundle and re-index", e);
        }
    }

    private static String describe(Requirement requirement) {
        String filter = requirement.getDirectives().get("filter");
        return requirement.getNamespace() + (filter == null ? "" : " " + filter) + " (required by "
                + requirement.getResource() + ")";
    }

    private static String firstLine(String message) {
        if (message == null) {
            return "";
        }
        int newline = message.indexOf('\n');
        return newline < 0 ? message : message.substring(0, newline);
    }
}
