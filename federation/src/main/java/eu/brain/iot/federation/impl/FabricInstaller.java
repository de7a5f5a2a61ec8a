package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import java.util.function.Supplier;

import org.osgi.util.promise.Deferred;
import org.osgi.util.promise.Promise;
import org.osgi.util.promise.Promises;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.federation.impl.InstallChoice.Offer;
import eu.brain.iot.federation.impl.RemoteNode.Presence;

/**
 * The fabric's {@link BundleInstaller}: the BMS of a node that is a member of a fabric uses it instead of the node's
 * own installer (it is ranked higher), and it chooses which node of the fabric installs a behaviour.
 * <ul>
 * <li>{@link #find}: with no other node online, the local installer's answer as it is. Otherwise a signed
 * {@code bid} to every online node, naming the devices the event names (given with {@code find(types, event)},
 * {@link DeviceNames}); each answers an {@code offer} from its local installer's {@code find} (from memory), its
 * load (behaviours its installer installed) and which of those devices its edge owns. At the first of all answers
 * or {@code install.bid.ms} (a one-shot timer, no periodic tick) the rule of {@link InstallChoice} picks a node, and
 * the answer is that node's candidates, each naming it ({@link BehaviourCandidate#node}).</li>
 * <li>{@link #install}: for this node, the local installer. For another node, an {@code order}; that node's
 * federation asks its local installer and answers a {@code result}. The promise resolves once the result is a
 * success <em>and</em> that node's interest taking one of the request's types has arrived and its forwarder is
 * registered with the bus (which hands the events it held over in that step). It fails with an
 * {@link InstallException} naming the node and the reason when the result is a failure, the node is not online or
 * goes offline meanwhile, the order cannot be sent, or {@code install.timeout.ms} passes.</li>
 * <li>When no node online offers a behaviour, an offline node whose last interest took the types is the answer
 * ({@link Departed}): its install waits up to {@code install.timeout.ms} for it, the BMS holding the events.</li>
 * <li>The rest ({@code installed}, {@code uninstall}, ...) is the local installer's.</li>
 * </ul>
 * Threads: the methods of {@link BundleInstaller} are called on any thread (the BMS's, publishers'); they read
 * {@link #local} (volatile) and the nodes' presence (volatile) and queue the rest on the fabric's inbound thread,
 * which owns {@link #bids} and {@link #orders}, sends and receives every message and resolves the promises.
 */
final class FabricInstaller implements BundleInstaller {

    /** How the installer sends (on the inbound thread). */
    interface Sending {
        void send(String to, Wire.Install message) throws IOException, InterruptedException;

        boolean joined();
    }

    private final Settings settings;
    private final ScheduledExecutorService in;
    private final Sending sending;
    private final Supplier<Collection<RemoteNode>> nodes;
    private final Function<String, RemoteNode> node;
    private final Host host;
    private volatile BundleInstaller local;
    private volatile OwnedDevices owned = OwnedDevices.NONE;
    private final InstallDesk desk;

    /** Bid deadlines waited at most when no node has offered a candidate yet ({@link #deadline}). */
    static final int NO_OFFER_WAIT = 20;

    private final Map<String, Bid> bids = new HashMap<>();
    private final Map<String, Order> orders = new HashMap<>();

    /** A question to the fabric in flight (inbound thread). */
    private static final class Bid {
        final String id;
        final List<String> types;
        /** The devices the event names ({@link DeviceNames}). */
        final List<String> devices;
        final Set<String> waiting;
        final Map<String, Offer> offers = new HashMap<>();
        final Deferred<List<BehaviourCandidate>> answer;
        ScheduledFuture<?> deadline;
        /** The deadline passed with no candidate offered: the nodes still to answer are waited for longer. */
        boolean extended;

        Bid(String id, List<String> types, List<String> devices, Set<String> waiting,
                Deferred<List<BehaviourCandidate>> answer) {
            this.id = id;
            this.types = types;
            this.devices = devices;
            this.waiting = waiting;
            this.answer = answer;
        }
    }

    /** An install order to another node in flight (inbound thread). */
    private static final class Order {
        final String id;
        final String node;
        final InstallRequest request;
        final Deferred<InstalledBehaviour> answer;
        InstalledBehaviour installed;
        /** Waiting for a departed node to come back ({@link Departed}), no order sent. */
        boolean awaitingReturn;
        ScheduledFuture<?> timeout;

        Order(String id, String node, InstallRequest request, Deferred<InstalledBehaviour> answer) {
            this.id = id;
            this.node = node;
            this.request = request;
            this.answer = answer;
        }

        String what() {
            return request.symbolicName == null ? "a behaviour for " + request.consumedTypes : request.symbolicName
                    + (request.versionRange == null ? "" : " " + request.versionRange);
        }
    }

    FabricInstaller(Settings settings, ScheduledExecutorService in, Sending sending,
            Supplier<Collection<RemoteNode>> nodes, Function<String, RemoteNode> node, Host host) {
        this.settings = settings;
        this.in = in;
        this.sending = sending;
        this.nodes = nodes;
        this.node = node;
        this.host = host;
        this.desk = new InstallDesk(settings, in, sending, this::local, () -> owned, host);
    }

    /** Which devices this node owns (its edge's), as its offers tell; {@code null}: none (no edge). */
    void ownedDevices(OwnedDevices devices) {
        this.owned = devices == null ? OwnedDevices.NONE : devices;
    }

    /** This node's own installer, or {@code null} when it has none (then it offers nothing to the fabric). */
    void local(BundleInstaller installer) {
        this.local = installer;
    }

    BundleInstaller local() {
        return local;
    }

    private String self() {
        return settings.node();
    }

    private List<String> online() {
        List<String> names = new ArrayList<>();
        for (RemoteNode n : nodes.get()) {
            if (n.status == Presence.ONLINE) {
                names.add(n.name);
            }
        }
        return names;
    }

    private static <T> Promise<T> failed(Problem problem, String message) {
        return Promises.failed(new InstallException(problem, message));
    }

    private <T> Promise<T> later(Deferred<T> answer, Runnable work) {
        try {
            in.execute(work);
        } catch (RejectedExecutionException e) {
            answer.fail(new InstallException(Problem.CLOSED, "node " + self() + " has left the fabric"));
        }
        return answer.getPromise();
    }

    // ---- the BMS's side: any thread --------------------------------------------------------------------------

    @Override
    public Promise<List<BehaviourCandidate>> find(List<String> consumedTypes) {
        return find(consumedTypes, null);
    }

    @Override
    public Promise<List<BehaviourCandidate>> find(List<String> consumedTypes, Map<String, ?> event) {
        BundleInstaller mine = local;
        if (mine == null) {
            return failed(Problem.CLOSED, "node " + self() + " has no Bundle Installer Service");
        }
        List<String> online = online();
        if (online.isEmpty() || !sending.joined()) { // alone: the node's own installer, else a departed node
            List<String> types = List.copyOf(consumedTypes);
            Promise<List<BehaviourCandidate>> own = mine.find(types);
            if (!own.isDone()) {
                return own.map(found -> found.isEmpty() ? Departed.candidates(nodes.get(), types) : found);
            }
            try { // answered from memory: answer at once too (the BMS uses an answer that is done on the spot)
                return own.getValue().isEmpty() ? Promises.resolved(Departed.candidates(nodes.get(), types)) : own;
            } catch (InvocationTargetException | InterruptedException e) {
                return own;
            }
        }
        Deferred<List<BehaviourCandidate>> answer = new Deferred<>();
        List<String> devices = DeviceNames.of(event); // read now: the caller keeps its map
        return later(answer, () -> bid(List.copyOf(consumedTypes), devices, online, answer));
    }

    @Override
    public Promise<InstalledBehaviour> install(InstallRequest request) {
        String target = request.node;
        if (target == null || target.equals(self())) {
            BundleInstaller mine = local;
            return mine == null ? failed(Problem.CLOSED, "node " + self() + " has no Bundle Installer Service")
                    : mine.install(request);
        }
        Deferred<InstalledBehaviour> answer = new Deferred<>();
        return later(answer, () -> order(request, answer));
    }

    @Override
    public Promise<InstalledBehaviour> uninstall(String symbolicName, String reason, boolean byOperator) {
        BundleInstaller mine = local;
        return mine == null ? failed(Problem.CLOSED, "node " + self() + " has no Bundle Installer Service")
                : mine.uninstall(symbolicName, reason, byOperator);
    }

    @Override
    public void allow(String symbolicName) {
        BundleInstaller mine = local;
        if (mine != null) {
            mine.allow(symbolicName);
        }
    }

    @Override
    public List<InstalledBehaviour> installed() {
        BundleInstaller mine = local;
        return mine == null ? List.of() : mine.installed();
    }

    @Override
    public List<String> activities() {
        BundleInstaller mine = local;
        return mine == null ? List.of() : mine.activities();
    }

    // ---- the asking node: inbound thread ---------------------------------------------------------------------

    private void bid(List<String> types, List<String> devices, List<String> online,
            Deferred<List<BehaviourCandidate>> answer) {
        Set<String> waiting = new HashSet<>(online);
        waiting.add(self());
        Bid bid = new Bid(UUID.randomUUID().toString(), types, devices, waiting, answer);
        bids.put(bid.id, bid);
        desk.offer(types, devices, offer -> offered(bid.id, offer));
        for (String to : online) {
            try {
                sending.send(to, desk.message(Wire.Install.BID, to, bid.id, m -> {
                    m.types = types;
                    m.devices = devices.isEmpty() ? null : devices;
                }));
            } catch (IOException e) {
                bid.waiting.remove(to);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
        bid.deadline = in.schedule(() -> deadline(bid), settings.bidMillis(), TimeUnit.MILLISECONDS);
        if (bid.waiting.isEmpty()) {
            decide(bid);
        }
    }

    private void offered(String id, Offer offer) {
        Bid bid = bids.get(id);
        if (bid == null) {
            return; // decided already: a late answer
        }
        // only the devices asked about count, whatever a node claims
        bid.offers.put(offer.node(), new Offer(offer.node(), offer.candidates(), offer.load(),
                offer.owns().stream().filter(bid.devices::contains).toList()));
        bid.waiting.remove(offer.node());
        if (bid.waiting.isEmpty()) {
            decide(bid);
        }
    }

    /**
     * The bid's deadline: decided among the answers in, when one offers a candidate and, for an event that names
     * devices, the offers in own every one of them, and when the only offer in is this node's own, it owns them all;
     * else, while nodes are still to answer (a node slower than {@code install.bid.ms}, e.g. under load), they are
     * waited for until {@link #NO_OFFER_WAIT} deadlines have passed: deciding without them would give the event up for
     * nothing, put its behaviour away from its devices, or put it beside the node that asked though another offers it
     * ({@link InstallChoice}).
     */
    private void deadline(Bid bid) {
        Set<String> owned = new HashSet<>();
        bid.offers.values().stream().filter(Offer::offers).forEach(o -> owned.addAll(o.owns()));
        boolean others = bid.offers.values().stream().anyMatch(o -> o.offers() && !o.node().equals(self()));
        Offer own = bid.offers.get(self());
        boolean ownWins = own != null && own.offers() && !bid.devices.isEmpty()
                && own.owns().containsAll(bid.devices);
        boolean offered = bid.offers.values().stream().anyMatch(Offer::offers) && owned.containsAll(bid.devices)
                && (others || ownWins);
        if (offered || bid.waiting.isEmpty() || bid.extended) {
            decide(bid);
            return;
        }
        bid.extended = true;
        bid.deadline = in.schedule(() -> decide(bid), settings.bidMillis() * (NO_OFFER_WAIT - 1),
                TimeUnit.MILLISECONDS);
    }

    private void decide(Bid bid) {
        if (bids.remove(bid.id) != bid) {
            return;
        }
        if (bid.deadline != null) {
            bid.deadline.cancel(false);
        }
        Offer chosen = InstallChoice.choose(bid.offers.values(), self());
        if (chosen == null) {
            bid.answer.resolve(Departed.candidates(nodes.get(), bid.types));
            return;
        }
        List<BehaviourCandidate> candidates = new ArrayList<>();
        for (BehaviourCandidate c : chosen.candidates()) {
            candidates.add(onNode(c, chosen.node()));
        }
        if (!chosen.node().equals(self())) {
            host.info("Fabric {}: node {} installs {} for events of {} naming {} (owns {}, load {}; offers, best "
                    + "first: {}; {} answered of {})", settings.fabric(), chosen.node(), candidates.get(0).symbolicName,
                    bid.types.get(0), bid.devices, chosen.owns(), chosen.load(), offersOf(bid), bid.offers.size(),
                    bid.offers.size() + bid.waiting.size());
        }
        bid.answer.resolve(candidates);
    }

    private List<String> offersOf(Bid bid) {
        return bid.offers.values().stream().filter(Offer::offers).sorted(InstallChoice.order(self()))
                .map(o -> o.node() + " owns " + o.owns() + " load " + o.load()).toList();
    }

    private void order(InstallRequest request, Deferred<InstalledBehaviour> answer) {
        RemoteNode target = node.apply(request.node);
        Order order = new Order(UUID.randomUUID().toString(), request.node, request, answer);
        if (Departed.behaviourOf(order.node).equals(request.symbolicName)) {
            awaitReturn(order);
            interestArrived(order); // back already
            return;
        }
        if (target.status != Presence.ONLINE) {
            answer.fail(new InstallException(Problem.START_FAILED, "node " + order.node + " is "
                    + target.status.name().toLowerCase() + ": it cannot install " + order.what()));
            return;
        }
        orders.put(order.id, order);
        try {
            sending.send(order.node, desk.message(Wire.Install.ORDER, order.node, order.id, m -> m.request = request));
        } catch (IOException e) {
            fail(order, Problem.START_FAILED, "the install order for " + order.what() + " to node " + order.node
                    + " was not sent: " + e.getMessage());
            return;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        }
        order.timeout = in.schedule(() -> fail(order, Problem.ACTIVATION_TIMEOUT, "node " + order.node + " did not"
                + " install " + order.what() + " within " + settings.installTimeoutMillis() + " ms (install.timeout.ms)"
                + (order.installed == null ? ": no answer" : ": installed, but its interest did not arrive")),
                settings.installTimeoutMillis(), TimeUnit.MILLISECONDS);
    }

    /** An order to a departed node: nothing to send, it resolves when the node is back with the interest. */
    private void awaitReturn(Order order) {
        order.awaitingReturn = true;
        order.installed = new InstalledBehaviour();
        order.installed.symbolicName = order.request.symbolicName;
        order.installed.version = Departed.BACK;
        orders.put(order.id, order);
        host.info("Fabric {}: events of {} wait for node {}, offline, whose behaviours took them (at most {} ms, "
                + "install.timeout.ms)", settings.fabric(), order.request.consumedTypes, order.node,
                settings.installTimeoutMillis());
        order.timeout = in.schedule(() -> fail(order, Problem.ACTIVATION_TIMEOUT, "node " + order.node + " did not "
                + "come back within " + settings.installTimeoutMillis() + " ms (install.timeout.ms) to take events of "
                + order.request.consumedTypes), settings.installTimeoutMillis(), TimeUnit.MILLISECONDS);
    }

    private void fail(Order order, Problem problem, String message) {
        if (orders.remove(order.id, order)) {
            if (order.timeout != null) {
                order.timeout.cancel(false);
            }
            order.answer.fail(new InstallException(problem, message));
        }
    }

    private void result(Wire.Install m) {
        Order order = orders.get(m.id());
        if (order == null || !order.node.equals(m.from())) {
            return;
        }
        if (!m.ok()) {
            Problem problem;
            try {
                problem = Problem.valueOf(m.problem());
            } catch (RuntimeException e) {
                problem = Problem.START_FAILED;
            }
            fail(order, problem, "node " + order.node + " could not install " + order.what() + ": " + m.message());
            return;
        }
        order.installed = m.installed() == null ? new InstalledBehaviour() : m.installed();
        interestArrived(order);
    }

    /** Resolves an order whose behaviour is installed once its node's interest takes one of its types. */
    private void interestArrived(Order order) {
        RemoteNode n = node.apply(order.node);
        List<String> types = order.request.consumedTypes;
        boolean takes = types == null || types.isEmpty()
                || n.interest.stream().anyMatch(e -> e.types().stream().anyMatch(types::contains));
        if (n.status == Presence.ONLINE && takes && orders.remove(order.id, order)) {
            order.timeout.cancel(false);
            order.answer.resolve(order.installed);
        }
    }

    /** A node's presence or interest changed, and the forwarders follow it already (inbound thread). */
    void membershipChanged(String name) {
        RemoteNode n = node.apply(name);
        for (Bid bid : List.copyOf(bids.values())) {
            if (n.status != Presence.ONLINE && bid.waiting.remove(name) && bid.waiting.isEmpty()) {
                decide(bid);
            }
        }
        for (Order order : List.copyOf(orders.values())) {
            if (!order.node.equals(name)) {
                continue;
            }
            if (n.status != Presence.ONLINE && order.awaitingReturn) {
                continue; // still away
            }
            if (n.status != Presence.ONLINE) {
                fail(order, Problem.START_FAILED, "node " + name + " went offline while installing " + order.what());
            } else if (order.installed != null) {
                interestArrived(order);
            }
        }
    }

    /** A signed, fresh message for this node from {@code m.from()} (inbound thread). */
    void received(Wire.Install m) {
        switch (m.op()) {
        case Wire.Install.BID -> desk.offer(m.types() == null ? List.of() : m.types(),
                m.devices() == null ? List.of() : m.devices(), offer -> desk.reply(m, Wire.Install.OFFER, r -> {
                    r.candidates = offer.candidates();
                    r.load = offer.load();
                    r.owns = offer.owns().isEmpty() ? null : offer.owns();
                }));
        case Wire.Install.OFFER -> offered(m.id(), new Offer(m.from(), m.candidates(), m.load(), m.owns()));
        case Wire.Install.ORDER -> desk.installHere(m);
        case Wire.Install.RESULT -> result(m);
        default -> {
            // Wire refuses other operations
        }
        }
    }

    private static BehaviourCandidate onNode(BehaviourCandidate c, String node) {
        BehaviourCandidate copy = new BehaviourCandidate();
        copy.symbolicName = c.symbolicName;
        copy.version = c.version;
        copy.consumed = c.consumed;
        copy.repository = c.repository;
        copy.url = c.url;
        copy.sha256 = c.sha256;
        copy.size = c.size;
        copy.node = node;
        return copy;
    }

    /** This node leaves the fabric: what waits for other nodes fails, so that the BMS chooses again (inbound). */
    void close() {
        for (Bid bid : List.copyOf(bids.values())) {
            bids.remove(bid.id);
            bid.answer.fail(new InstallException(Problem.CLOSED, "node " + self() + " left the fabric while it "
                    + "asked which node installs a behaviour for " + bid.types));
        }
        for (Order order : List.copyOf(orders.values())) {
            fail(order, Problem.CLOSED, "node " + self() + " left the fabric while node " + order.node
                    + " installed " + order.what());
        }
    }
}
