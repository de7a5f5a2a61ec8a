package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.util.List;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;
import java.util.function.Supplier;

import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;

import org.eclipse.paho.mqttv5.client.IMqttToken;
import org.eclipse.paho.mqttv5.client.MqttActionListener;
import org.eclipse.paho.mqttv5.client.MqttAsyncClient;
import org.eclipse.paho.mqttv5.client.MqttCallback;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.MqttDisconnectResponse;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttMessage;
import org.eclipse.paho.mqttv5.common.MqttSubscription;
import org.eclipse.paho.mqttv5.common.packet.MqttProperties;
import org.eclipse.paho.mqttv5.common.packet.UserProperty;

/**
 * The node's MQTT 5 connection (Eclipse Paho): a persistent session (clean start off, a session expiry), QoS 1, a
 * retained Last Will; every message it publishes is signed (user property {@value #SIG}).
 * <p>
 * Every connection uses a new Paho client (the broker keeps the session: subscriptions and messages queued for this
 * node). Paho's own reconnection is not used: it sends the publications that were in flight again with the topic
 * aliases of the lost connection, which brokers refuse (Mosquitto and HiveMQ disconnect the client, again and again);
 * the fabric's own end-to-end acknowledgement sends again whatever was lost instead.
 * <p>
 * Threads: Paho's own threads call {@link Listener}; {@link #connect} is called by the fabric's inbound thread;
 * {@link #publish} by the fabric's sender and inbound threads, and waits while {@link #MAX_IN_FLIGHT} publications
 * are unconfirmed by the broker; {@link #publishIfRoom} (the acknowledgements, on the inbound thread) never waits.
 * {@link #client} and {@link #inFlight} are replaced at each connection.
 */
final class MqttLink {

    /** The user property that carries a message's signature. */
    static final String SIG = "sig";
    /** QoS 1 publications not yet confirmed by the broker, at most (brokers allow 10-65535; Mosquitto 20). */
    static final int MAX_IN_FLIGHT = 10;
    static final int QOS = 1;
    /** Largest packet this node accepts from the broker. */
    static final long MAX_PACKET_BYTES = 16L << 20;

    /**
     * What the link tells its node; called on Paho's threads. {@link #message} may take a while (it checks and
     * decodes a batch of events and hands it to the bus, which never waits) but never waits for a publication: the
     * broker's confirmations, which free the slots {@link #publish} waits for, come on the same thread.
     */
    interface Listener {
        void connected();

        void disconnected(String why);

        void message(String topic, byte[] payload, String signature);
    }

    private final Settings settings;
    private final FabricKey key;
    private final Listener listener;
    private final MqttConnectionOptions options;
    private volatile MqttAsyncClient client;
    private volatile Semaphore inFlight = new Semaphore(MAX_IN_FLIGHT);
    private final String willTopic;
    private final LongFunction<byte[]> willPayload;
    /** When the current connection began: its online status and its Last Will name it. */
    private volatile long since;

    MqttLink(Settings settings, FabricKey key, String willTopic, LongFunction<byte[]> willPayload, Listener listener)
            throws IOException {
        this.settings = settings;
        this.key = key;
        this.listener = listener;
        this.client = newClient();
        options = new MqttConnectionOptions();
        options.setCleanStart(false);
        options.setSessionExpiryInterval(settings.sessionExpirySeconds());
        options.setKeepAliveInterval(settings.keepAliveSeconds());
        options.setAutomaticReconnect(false);
        options.setConnectionTimeout(10);
        options.setMaximumPacketSize(MAX_PACKET_BYTES);
        this.willTopic = willTopic;
        this.willPayload = willPayload;
        if (!settings.username().isEmpty()) {
            options.setUserName(settings.username());
            options.setPassword(settings.password().getBytes(StandardCharsets.UTF_8));
        }
        if (settings.tls()) {
            options.setSocketFactory(sslContext(settings).getSocketFactory());
        } else {
            options.setSocketFactory(new NoDelaySockets());
        }
    }

    private MqttAsyncClient newClient() throws IOException {
        MqttAsyncClient c;
        try {
            c = new MqttAsyncClient(settings.brokerUri(), settings.fabric() + "." + settings.node(),
                    new MemoryPersistence());
        } catch (MqttException e) {
            throw new IOException("the broker URI " + settings.brokerUri() + " is not usable: " + e.getMessage(), e);
        }
        c.setCallback(new MqttCallback() {
            @Override
            public void disconnected(MqttDisconnectResponse response) {
                listener.disconnected(String.valueOf(response.getReasonString() != null ? response.getReasonString()
                        : response.getException()));
            }

            @Override
            public void mqttErrorOccurred(MqttException exception) {
                listener.disconnected(exception.getMessage());
            }

            @Override
            public void messageArrived(String topic, MqttMessage message) {
                listener.message(topic, message.getPayload(), signature(message.getProperties()));
            }

            @Override
            public void deliveryComplete(IMqttToken token) {
                // the publication's own listener frees its slot
            }

            @Override
            public void connectComplete(boolean reconnect, String serverURI) {
                inFlight = new Semaphore(MAX_IN_FLIGHT); // publications of a lost connection never complete
                listener.connected();
            }

            @Override
            public void authPacketArrived(int reasonCode, MqttProperties properties) {
                // no enhanced authentication
            }
        });
        return c;
    }

    /**
     * Try to connect once, waiting up to the connection timeout.
     *
     * @param cleanStart whether the broker drops this node's session first (subscriptions, queued messages)
     * @throws IOException saying why the broker could not be reached
     */
    void connect(boolean cleanStart) throws IOException {
        if (client.isConnected()) {
            return;
        }
        options.setCleanStart(cleanStart);
        discard(client);
        client = newClient();
        since = System.currentTimeMillis();
        MqttMessage will = signed(willTopic, willPayload.apply(since), true);
        options.setWill(willTopic, will);
        options.setWillMessageProperties(will.getProperties()); // a will's properties travel apart from it
        try {
            client.connect(options).waitForCompletion(TimeUnit.SECONDS.toMillis(15));
        } catch (MqttException e) {
            throw new IOException("cannot connect to the broker " + settings.brokerUri() + ": " + e.getMessage()
                    + (e.getCause() != null ? " (" + e.getCause().getMessage() + ")" : ""), e);
        }
    }

    /** @return when the current connection began */
    long since() {
        return since;
    }

    boolean isConnected() {
        return client.isConnected();
    }

    void subscribe(String[] topics) throws IOException {
        MqttSubscription[] subs = new MqttSubscription[topics.length];
        for (int i = 0; i < topics.length; i++) {
            subs[i] = new MqttSubscription(topics[i], QOS);
        }
        try {
            client.subscribe(subs).waitForCompletion(TimeUnit.SECONDS.toMillis(15));
        } catch (MqttException e) {
            throw new IOException("cannot subscribe to the fabric's topics: " + e.getMessage(), e);
        }
    }

    /**
     * Publish a signed message with QoS 1, waiting while too many are unconfirmed.
     *
     * @throws IOException when the connection is down (the caller sends again after reconnection)
     */
    void publish(String topic, byte[] payload, boolean retained) throws IOException, InterruptedException {
        Semaphore slots = inFlight;
        if (!slots.tryAcquire(settings.keepAliveSeconds(), TimeUnit.SECONDS)) {
            throw new IOException("the broker confirms no publication");
        }
        send(slots, topic, payload, retained);
    }

    /** Publishes with a slot of {@code slots} held, released when the broker confirms (or the publication fails). */
    private void send(Semaphore slots, String topic, byte[] payload, boolean retained) throws IOException {
        try {
            client.publish(topic, signed(topic, payload, retained), null, new MqttActionListener() {
                @Override
                public void onSuccess(IMqttToken token) {
                    slots.release();
                }

                @Override
                public void onFailure(IMqttToken token, Throwable failure) {
                    slots.release();
                }
            });
        } catch (MqttException e) {
            slots.release();
            throw new IOException("publication on " + topic + " failed: " + e.getMessage(), e);
        }
    }

    /**
     * Publish a signed message with QoS 1 if the broker has confirmed enough earlier ones, without waiting.
     *
     * @param payload made only when there is room; {@code null}: nothing to publish
     * @return false when there was no room (nothing was made nor published)
     * @throws IOException when the connection is down (the caller sends again after reconnection)
     */
    boolean publishIfRoom(String topic, Supplier<byte[]> payload) throws IOException {
        Semaphore slots = inFlight;
        if (!slots.tryAcquire()) {
            return false;
        }
        byte[] bytes;
        try {
            bytes = payload.get();
        } catch (RuntimeException e) {
            slots.release();
            throw e;
        }
        if (bytes == null) {
            slots.release();
            return true;
        }
        send(slots, topic, bytes, false);
        return true;
    }

    private MqttMessage signed(String topic, byte[] payload, boolean retained) {
        MqttProperties props = new MqttProperties();
        props.setUserProperties(List.of(new UserProperty(SIG, key.sign(topic, payload))));
        return new MqttMessage(payload, QOS, retained, props);
    }

    private static String signature(MqttProperties props) {
        if (props == null || props.getUserProperties() == null) {
            return null;
        }
        for (UserProperty p : props.getUserProperties()) {
            if (SIG.equals(p.getKey())) {
                return p.getValue();
            }
        }
        return null;
    }

    /** Leave the broker: a normal disconnection (no Last Will), then close the client. */
    void close() {
        try {
            if (client.isConnected()) {
                client.disconnect().waitForCompletion(TimeUnit.SECONDS.toMillis(5));
            }
        } catch (MqttException e) {
            // the connection is gone anyway
        }
        try {
            client.close(true);
        } catch (MqttException e) {
            // nothing left to release
        }
    }

    /** Leave without a normal disconnection, as a crash would (tests of the Last Will). */
    void abort() {
        discard(client);
    }

    private static void discard(MqttAsyncClient c) {
        try {
            c.disconnectForcibly(0, 1, false);
        } catch (MqttException e) {
            // not connected
        }
        try {
            c.close(true);
        } catch (MqttException e) {
            // nothing left to release
        }
    }

    private static SSLContext sslContext(Settings settings) throws IOException {
        try {
            SSLContext context = SSLContext.getInstance("TLS");
            if (settings.trustStore().isEmpty()) {
                context.init(null, null, null);
                return context;
            }
            KeyStore store = KeyStore.getInstance(KeyStore.getDefaultType());
            try (InputStream in = Files.newInputStream(Path.of(settings.trustStore()))) {
                store.load(in, settings.trustStorePassword().toCharArray());
            }
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(store);
            context.init(null, tmf.getTrustManagers(), null);
            return context;
        } catch (GeneralSecurityException e) {
            throw new IOException("the TLS trust store " + settings.trustStore() + " is not usable: " + e.getMessage(),
                    e);
        }
    }
}
