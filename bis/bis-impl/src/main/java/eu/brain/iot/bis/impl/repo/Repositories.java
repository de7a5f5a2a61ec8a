package eu.brain.iot.bis.impl.repo;

import java.io.IOException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import org.osgi.resource.Capability;
import org.osgi.resource.Requirement;

import eu.brain.iot.bis.sign.IndexSigning;

/**
 * The configured indexes, each read at start and re-read on change (conditional reads every {@code refreshMillis}),
 * with retries and exponential backoff while one is unreachable. Each index's content in use is an immutable
 * {@link IndexSnapshot}, replaced only by a newer index that parsed and (when keys are configured) carries a valid
 * signature: a refused index leaves the previous one in use.
 * <p>
 * Every index is read on its own: the scheduler has a thread per index, and each read is bounded in size
 * ({@code maxIndexBytes}) and time (the reader's deadline), so a repository that never answers, or trickles, holds up
 * no other; the indexes that answered are in use meanwhile.
 * <p>
 * Threads: every read runs on the given scheduler, one read per index at a time (its {@link Holder#reading} flag);
 * each {@link Holder}'s mutable fields are written only by the read that holds that flag, and published to other
 * threads through its {@code volatile} snapshot and status; {@link Holder#next} is guarded by the holder.
 */
public final class Repositories {

    private final List<Holder> holders = new ArrayList<>();
    private final TrustedKeys keys;
    private final UrlReader reader;
    private final ScheduledExecutorService scheduler;
    private final long refreshMillis;
    private final long retryInitialMillis;
    private final long retryMaxMillis;
    private final Consumer<String> warn;
    private final Consumer<String> info;
    private final long maxIndexBytes;
    private final CountDownLatch firstAttempts;
    private volatile boolean closed;
    private volatile Runnable onChange = () -> { };

    /** The most a signature file may hold: an Ed25519 signature in base64 is under 100 bytes. */
    private static final long SIGNATURE_MAX_BYTES = 64 * 1024;

    /** @param scheduler runs the reads: give it a thread per index, so that no index waits for another's read */
    public Repositories(List<URI> urls, TrustedKeys keys, UrlReader reader, ScheduledExecutorService scheduler,
            long refreshMillis, long retryInitialMillis, long retryMaxMillis, long maxIndexBytes,
            Consumer<String> warn, Consumer<String> info) {
        this.maxIndexBytes = Math.max(1, maxIndexBytes);
        this.keys = keys;
        this.reader = reader;
        this.scheduler = scheduler;
        this.refreshMillis = Math.max(10, refreshMillis);
        this.retryInitialMillis = Math.max(1, retryInitialMillis);
        this.retryMaxMillis = Math.max(this.retryInitialMillis, retryMaxMillis);
        this.warn = warn;
        this.info = info;
        urls.forEach(u -> holders.add(new Holder(u)));
        this.firstAttempts = new CountDownLatch(holders.size());
    }

    /** @param listener called on the reader's thread after an index's content in use was replaced */
    public void onChange(Runnable listener) {
        this.onChange = listener;
    }

    public void start() {
        holders.forEach(h -> schedule(h, 0));
    }

    public void close() {
        closed = true;
    }

    /** Waits until every index was tried once (read or failed), at most {@code millis}. */
    public boolean awaitFirstAttempts(long millis) throws InterruptedException {
        return firstAttempts.await(millis, TimeUnit.MILLISECONDS);
    }

    /** @return the behaviour and library resources of every index in use, in configuration order */
    public List<BehaviourResource> resources() {
        List<BehaviourResource> all = new ArrayList<>();
        for (Holder h : holders) {
            IndexSnapshot snapshot = h.snapshot;
            if (snapshot != null) {
                all.addAll(snapshot.resources());
            }
        }
        return all;
    }

    /** @return the capabilities of every index's resources that satisfy the requirement, configuration order */
    public List<Capability> providers(Requirement requirement) {
        List<Capability> all = new ArrayList<>();
        for (Holder h : holders) {
            IndexSnapshot snapshot = h.snapshot;
            if (snapshot != null) {
                all.addAll(snapshot.providers(requirement));
            }
        }
        return all;
    }

    /**
     * @return the facts of a resource of one of the indexes, if it is one: the same resource object, or, when its
     *         index was read anew since the resource was found (a resolution in progress), the resource of the same
     *         identity and version in the index now in use
     */
    public Optional<BehaviourResource> facts(org.osgi.resource.Resource resource) {
        for (Holder h : holders) {
            IndexSnapshot snapshot = h.snapshot;
            BehaviourResource facts = snapshot == null ? null : snapshot.facts(resource);
            if (facts != null) {
                return Optional.of(facts);
            }
        }
        Optional<BehaviourResource> identity = BehaviourResource.of(resource, java.net.URI.create("unknown:"));
        return identity.flatMap(wanted -> resources().stream().filter(r -> r.symbolicName().equals(wanted
                .symbolicName()) && r.version().equals(wanted.version())).findFirst());
    }

    public List<IndexStatus> status() {
        return holders.stream().map(h -> h.status).toList();
    }

    /** Re-reads every index now (e.g. {@code bis:repos refresh}); an index being read now is left to that read. */
    public void refreshNow() {
        holders.forEach(h -> schedule(h, 0));
    }

    /** Replaces the index's next read by one in {@code delayMillis}. */
    private void schedule(Holder h, long delayMillis) {
        synchronized (h) {
            if (closed) {
                return;
            }
            if (h.next != null) {
                h.next.cancel(false);
            }
            try {
                h.next = scheduler.schedule(() -> read(h), delayMillis, TimeUnit.MILLISECONDS);
            } catch (java.util.concurrent.RejectedExecutionException e) {
                // closing
            }
        }
    }

    private void read(Holder h) {
        if (closed || !h.reading.compareAndSet(false, true)) {
            return; // this index is being read now: that read schedules the next
        }
        try {
            readNow(h);
        } finally {
            h.reading.set(false);
        }
    }

    private void readNow(Holder h) {
        long now = System.currentTimeMillis();
        long next = refreshMillis;
        try {
            Fetch fetch = reader.fetch(h.url, h.validators, maxIndexBytes);
            if (fetch instanceof Fetch.Content content) {
                accept(h, content, now);
            } else {
                h.publish(h.signature, 0, null, now);
            }
        } catch (IOException e) {
            int failures = h.status.failures() + 1;
            next = Math.min(retryMaxMillis, retryInitialMillis << Math.min(20, failures - 1));
            String problem = Errors.describe(e);
            String prefix = h.url + ": ";
            String message = (problem.startsWith(prefix) ? h.url + " cannot be read (" + problem.substring(
                    prefix.length()) + ")" : problem.contains(h.url.toString()) ? problem : h.url + " cannot be read ("
                            + problem + ")") + "; retry " + failures + " in " + next
                    + " ms" + (h.snapshot == null ? "" : ", the index read before stays in use");
            if (failures == 1 || Long.bitCount(failures) == 1) {
                warn.accept(message); // 1st, 2nd, 4th, 8th... failure: visible without flooding the log
            }
            h.publish(h.signature, failures, message, now);
        } catch (IndexException e) {
            h.publish(h.signature, 0, e.getMessage(), now);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        } catch (RuntimeException e) {
            String message = h.url + ": unexpected failure while reading the index: " + Errors.describe(e);
            warn.accept(message);
            h.publish(h.signature, h.status.failures() + 1, message, now);
        } finally {
            if (!h.attempted) {
                h.attempted = true;
                firstAttempts.countDown();
            }
        }
        schedule(h, next);
    }

    /** Checks the signature and parses; only then replaces the snapshot. */
    private void accept(Holder h, Fetch.Content content, long now) throws IOException, InterruptedException,
            IndexException {
        String digest = sha256(content.bytes());
        String signature = "not checked (no trusted.keys configured)";
        if (keys.enabled()) {
            URI sigUrl = URI.create(h.url + IndexSigning.SUFFIX);
            Optional<byte[]> sig = reader.readIfPresent(sigUrl, SIGNATURE_MAX_BYTES);
            int key = sig.isEmpty() ? -1 : keys.verify(content.bytes(), new String(sig.get(), StandardCharsets.US_ASCII));
            if (key < 0) {
                String problem = sig.isEmpty() ? "has no signature file " + sigUrl
                        : "has a signature " + sigUrl + " that no trusted key verifies";
                String message = "index " + h.url + " REFUSED: it " + problem + " (trusted keys: " + keys.describe()
                        + "). " + (h.snapshot == null ? "No index from this URL is in use"
                                : "The index read before stays in use")
                        + ". Sign the index with the private key of a trusted key (sign-index, see repository/README.md)"
                        + " or add its public key to trusted.keys of eu.brain.iot.bis.";
                if (!digest.equals(h.refusedDigest)) {
                    warn.accept(message); // once per refused content, not at every refresh
                    h.refusedDigest = digest;
                }
                h.publish("REFUSED: " + problem, 0, message, now);
                return;
            }
            signature = "valid (key " + keys.describe(key) + ")";
        }
        if (h.snapshot != null && digest.equals(h.digest)) {
            // the same bytes again (a touched file, a server that ignores conditional requests): the snapshot in use
            // stays, so that a resolution in progress keeps finding its resources; the journal's entries not back
            // are tried again all the same (their bundles may have been repaired)
            h.validators = content.validators();
            h.readAt = now;
            h.publish(signature, 0, null, now);
            onChange.run();
            return;
        }
        IndexSnapshot snapshot;
        try {
            snapshot = new IndexSnapshot(h.url, IndexParser.parse(content.bytes(), h.url, maxIndexBytes));
        } catch (IndexException e) {
            if (!digest.equals(h.refusedDigest)) {
                warn.accept(e.getMessage() + (h.snapshot == null ? "" : "; the index read before stays in use"));
                h.refusedDigest = digest;
            }
            throw e;
        }
        h.validators = content.validators();
        h.refusedDigest = null;
        h.digest = digest;
        h.snapshot = snapshot;
        h.readAt = now;
        info.accept("index " + h.url + " read: " + snapshot.resources().size() + " resources, signature " + signature);
        h.publish(signature, 0, null, now);
        onChange.run();
    }

    private static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** One index. Mutable fields: written only by the read holding {@link #reading}; {@link #next} under the holder. */
    private static final class Holder {
        final URI url;
        final java.util.concurrent.atomic.AtomicBoolean reading = new java.util.concurrent.atomic.AtomicBoolean();
        java.util.concurrent.ScheduledFuture<?> next;
        volatile IndexSnapshot snapshot;
        volatile IndexStatus status;
        Fetch.Validators validators = Fetch.Validators.NONE;
        String refusedDigest;
        /** The SHA-256 of the index's bytes in use. */
        String digest;
        String signature = "-";
        long readAt;
        boolean attempted;

        Holder(URI url) {
            this.url = url;
            this.status = new IndexStatus(url.toString(), 0, 0, 0, 0, "-", 0, null);
        }

        void publish(String signatureState, int failures, String error, long checkedAt) {
            if (!signatureState.startsWith("REFUSED")) {
                signature = signatureState;
            }
            IndexSnapshot s = snapshot;
            int behaviours = s == null ? 0 : (int) s.resources().stream().filter(BehaviourResource::isBehaviour).count();
            status = new IndexStatus(url.toString(), s == null ? 0 : s.resources().size(), behaviours, readAt,
                    checkedAt, signatureState, failures, error);
        }
    }
}
