package org.triad.vda5050.mqtt;

import java.net.URI;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

import com.fasterxml.jackson.databind.JsonNode;

import org.eclipse.paho.client.mqttv3.DisconnectedBufferOptions;
import org.eclipse.paho.client.mqttv3.IMqttDeliveryToken;
import org.eclipse.paho.client.mqttv3.MqttAsyncClient;
import org.eclipse.paho.client.mqttv3.MqttCallbackExtended;
import org.eclipse.paho.client.mqttv3.MqttConnectOptions;
import org.eclipse.paho.client.mqttv3.MqttException;
import org.eclipse.paho.client.mqttv3.MqttMessage;
import org.eclipse.paho.client.mqttv3.persist.MemoryPersistence;
import org.triad.vda5050.protocol.MessageSchemas;
import org.triad.vda5050.protocol.Topic;
import org.triad.vda5050.protocol.VdaJson;
import org.triad.vda5050.protocol.VdaMessageException;
import org.triad.vda5050.security.ClientCredentials;

/**
 * One MQTT connection of a VDA 5050 participant (master control or AGV) through Eclipse Paho: QoS 1,
 * a persistent session (clean session off, so the broker keeps subscriptions and queued messages
 * across reconnects), automatic reconnect with messages published meanwhile buffered, and an optional
 * last will. Every message sent is validated against its topic's official schema first (a violation is
 * a bug and throws); every message received is parsed, validated and version-checked before a handler
 * sees it, and one that fails is reported as one line naming the topic and ignored.
 */
public final class MqttLink implements AutoCloseable {
    /** A last will: published by the broker when this link dies without disconnecting. */
    public record Will(String mqttTopic, Object message) {
    }

    private final MqttAsyncClient client;
    private final String broker;
    private final Consumer<String> problems;
    private final Map<String, Consumer<Received>> handlers = new ConcurrentHashMap<>();
    /** Subscriptions outside VDA 5050 (the building's device protocol): their payloads are handed over unparsed. */
    private final Map<String, List<Consumer<byte[]>>> rawHandlers = new ConcurrentHashMap<>();
    private final List<Runnable> reconnectListeners = new CopyOnWriteArrayList<>();
    private final List<Consumer<String>> sentListeners = new CopyOnWriteArrayList<>();
    private final ExecutorService dispatch;
    /** Delivers the raw subscriptions' messages, apart from VDA 5050's (whose handlers may wait for one of them). */
    private final ExecutorService rawDispatch;
    private final AtomicLong received = new AtomicLong();
    private final AtomicLong rejected = new AtomicLong();
    private volatile boolean connected;

    private MqttLink(String broker, String clientId, Consumer<String> problems) throws MqttException {
        this.broker = broker;
        this.problems = problems;
        this.client = new MqttAsyncClient(broker, clientId, new MemoryPersistence());
        this.dispatch = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "vda5050-" + clientId);
            t.setDaemon(true);
            return t;
        });
        this.rawDispatch = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "devices-" + clientId);
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Connects to the broker ({@code tcp://HOST:PORT}) as {@code clientId}.
     *
     * @param problems where messages that were ignored are reported, one line each
     * @throws BrokerUnreachableException when no broker answers within {@code timeoutSeconds}
     */
    public static MqttLink connect(String broker, String clientId, Will will, Consumer<String> problems, int keepAliveSeconds,
            double timeoutSeconds) {
        return connect(broker, null, clientId, will, problems, keepAliveSeconds, timeoutSeconds);
    }

    /**
     * Connects as {@code identity} (master control's or a robot's serial number): on a secured broker
     * ({@code ssl://HOST:PORT}) with that identity's client certificate and password from the credentials
     * folder ({@link ClientCredentials#configuredFolder()}); on plain TCP the identity is not used.
     *
     * @throws IllegalArgumentException when a secured broker is named and the identity's credentials are missing
     */
    public static MqttLink connect(String broker, String identity, String clientId, Will will, Consumer<String> problems,
            int keepAliveSeconds, double timeoutSeconds) {
        Objects.requireNonNull(problems, "problems");
        URI uri = brokerUri(broker);
        MqttLink link;
        try {
            link = new MqttLink(broker, clientId, problems);
        } catch (MqttException e) {
            throw new IllegalArgumentException("cannot use MQTT client id '" + clientId + "': " + e.getMessage(), e);
        }
        MqttConnectOptions o = new MqttConnectOptions();
        o.setCleanSession(false);
        o.setAutomaticReconnect(true);
        o.setMaxReconnectDelay(1000);
        o.setKeepAliveInterval(keepAliveSeconds);
        o.setConnectionTimeout((int) Math.max(1, Math.ceil(timeoutSeconds)));
        o.setMaxInflight(1000);
        if ("ssl".equals(uri.getScheme())) {
            ClientCredentials c = ClientCredentials.forBroker(broker, identity);
            o.setUserName(c.identity());
            o.setPassword(c.password());
            o.setSocketFactory(new NoDelaySslSocketFactory(c.socketFactory()));
        } else {
            o.setSocketFactory(new NoDelaySocketFactory());
        }
        if (will != null) {
            o.setWill(will.mqttTopic(), validated(will.mqttTopic(), will.message()), 1, true);
        }
        DisconnectedBufferOptions buffer = new DisconnectedBufferOptions();
        buffer.setBufferEnabled(true);
        buffer.setBufferSize(10_000);
        buffer.setPersistBuffer(false);
        buffer.setDeleteOldestMessages(false);
        link.client.setBufferOpts(buffer);
        link.client.setCallback(link.new Callback());
        try {
            link.client.connect(o).waitForCompletion((long) (timeoutSeconds * 1000));
            link.connected = true;
        } catch (MqttException e) {
            link.closeQuietly();
            if (e.getReasonCode() == MqttException.REASON_CODE_FAILED_AUTHENTICATION
                    || e.getReasonCode() == MqttException.REASON_CODE_NOT_AUTHORIZED) {
                throw new BrokerUnreachableException("the MQTT broker at " + uri.getHost() + ":" + uri.getPort() + " (" + broker
                        + ") refused " + (o.getUserName() != null ? "'" + o.getUserName() + "'" : "an anonymous client") + ": " + reason(e), e);
            }
            throw new BrokerUnreachableException("no MQTT broker at " + uri.getHost() + ":" + uri.getPort() + " (" + broker + "): "
                    + reason(e), e);
        }
        return link;
    }

    private static URI brokerUri(String broker) {
        URI uri;
        try {
            uri = URI.create(broker);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("not a broker address: '" + broker + "' (expected ssl://HOST:PORT or tcp://HOST:PORT)");
        }
        if (!("tcp".equals(uri.getScheme()) || "ssl".equals(uri.getScheme())) || uri.getHost() == null || uri.getPort() < 0) {
            throw new IllegalArgumentException("not a broker address: '" + broker + "' (expected ssl://HOST:PORT or tcp://HOST:PORT)");
        }
        return uri;
    }

    private static String reason(MqttException e) {
        Throwable c = e.getCause();
        return c != null && c.getMessage() != null ? c.getMessage() : e.getMessage();
    }

    public String broker() {
        return broker;
    }

    public boolean isConnected() {
        return connected;
    }

    /** Messages received (valid or not) and messages ignored as malformed, since the start. */
    public long receivedCount() {
        return received.get();
    }

    public long rejectedCount() {
        return rejected.get();
    }

    /** Runs after every automatic reconnect (subscriptions are renewed first). */
    public void onReconnect(Runnable r) {
        reconnectListeners.add(r);
    }

    /** Sees the MQTT topic of every message published through this link (for message-rate counts). */
    public void onSent(Consumer<String> listener) {
        sentListeners.add(listener);
    }

    /** Subscribes with QoS 1; the handler runs on this link's one dispatch thread, in arrival order. */
    public void subscribe(String filter, Consumer<Received> handler) {
        handlers.put(filter, handler);
        try {
            client.subscribe(filter, 1).waitForCompletion(5000);
        } catch (MqttException e) {
            throw new IllegalStateException("cannot subscribe to " + filter + " on " + broker + ": " + reason(e), e);
        }
    }

    /**
     * Subscribes with QoS 1 to a topic outside VDA 5050 (e.g. the building's device protocol,
     * {@code triad/devices/v1/...}), sharing this connection and so its identity on a secured broker: messages
     * on it are neither parsed nor validated here but handed over as bytes, in arrival order on a thread apart from the
     * VDA 5050 messages' (whose handlers may wait for a device's answer), to
     * every handler subscribed to a matching filter. The returned action removes this handler (the last one
     * for its filter unsubscribes).
     */
    public Runnable subscribeRaw(String filter, Consumer<byte[]> handler) {
        Objects.requireNonNull(handler, "handler");
        if (Topic.parse(filter.replace("+", "x").replace("#", "x")).isPresent()) {
            throw new IllegalArgumentException("a VDA 5050 topic is subscribed with subscribe(), not as raw bytes: " + filter);
        }
        rawHandlers.computeIfAbsent(filter, f -> new CopyOnWriteArrayList<>()).add(handler);
        try {
            client.subscribe(filter, 1).waitForCompletion(5000);
        } catch (MqttException e) {
            throw new IllegalStateException("cannot subscribe to " + filter + " on " + broker + ": " + reason(e), e);
        }
        return () -> {
            List<Consumer<byte[]>> list = rawHandlers.get(filter);
            if (list != null && list.remove(handler) && list.isEmpty() && rawHandlers.remove(filter, list)) {
                try {
                    client.unsubscribe(filter);
                } catch (MqttException e) {
                    // the connection is gone; so is the subscription's use
                }
            }
        };
    }

    /** Publishes a message (QoS 1) after checking it against its topic's schema; buffered while reconnecting. */
    public void publish(String mqttTopic, Object message, boolean retained) {
        byte[] payload = validated(mqttTopic, message);
        publishRaw(mqttTopic, payload, retained);
    }

    /** Publishes bytes as they are, unchecked: only for tests that feed malformed messages to the other side. */
    public void publishRaw(String mqttTopic, byte[] payload, boolean retained) {
        try {
            client.publish(mqttTopic, payload, 1, retained);
            sentListeners.forEach(l -> l.accept(mqttTopic));
        } catch (MqttException e) {
            throw new IllegalStateException("cannot publish to " + mqttTopic + " on " + broker + ": " + reason(e), e);
        }
    }

    /** Hands a message on a raw subscription to its handlers (on the raw dispatch thread); false when no raw filter matches. */
    private boolean deliverRaw(String mqttTopic, byte[] payload) {
        boolean raw = false;
        for (Map.Entry<String, List<Consumer<byte[]>>> h : rawHandlers.entrySet()) {
            if (matches(h.getKey(), mqttTopic)) {
                raw = true;
                for (Consumer<byte[]> c : h.getValue()) {
                    try {
                        c.accept(payload);
                    } catch (RuntimeException e) {
                        problems.accept("vda5050: handling a message on " + mqttTopic + " failed: " + e);
                    }
                }
            }
        }
        return raw;
    }

    private static byte[] validated(String mqttTopic, Object message) {
        Topic.Address a = Topic.parse(mqttTopic)
                .orElseThrow(() -> new IllegalArgumentException("not a VDA 5050 topic: " + mqttTopic));
        JsonNode tree = VdaJson.tree(message);
        try {
            MessageSchemas.get().check(a.topic(), tree);
        } catch (VdaMessageException e) {
            throw new IllegalStateException("refusing to send a malformed message on " + mqttTopic + ": " + e.getMessage(), e);
        }
        return VdaJson.write(tree);
    }

    private void deliver(String mqttTopic, byte[] payload) {
        received.incrementAndGet();
        if (!mqttTopic.startsWith(Topic.INTERFACE + "/") && handlers.keySet().stream().noneMatch(f -> matches(f, mqttTopic))) {
            return; // a message for a raw subscription that was dropped meanwhile
        }
        try {
            Received r = Inbound.read(mqttTopic, payload);
            for (Map.Entry<String, Consumer<Received>> h : handlers.entrySet()) {
                if (matches(h.getKey(), mqttTopic)) {
                    h.getValue().accept(r);
                }
            }
        } catch (VdaMessageException e) {
            rejected.incrementAndGet();
            problems.accept("vda5050: ignored message on " + mqttTopic + ": " + e.getMessage());
        } catch (RuntimeException e) {
            problems.accept("vda5050: handling a message on " + mqttTopic + " failed: " + e);
        }
    }

    /** Whether an MQTT topic filter ({@code +} one level, {@code #} the rest) matches a topic. */
    public static boolean matches(String filter, String topic) {
        String[] f = filter.split("/", -1);
        String[] t = topic.split("/", -1);
        for (int i = 0; i < f.length; i++) {
            if (f[i].equals("#")) {
                return true;
            }
            if (i >= t.length || !(f[i].equals("+") || f[i].equals(t[i]))) {
                return false;
            }
        }
        return f.length == t.length;
    }

    private final class Callback implements MqttCallbackExtended {
        @Override
        public void connectComplete(boolean reconnect, String serverURI) {
            connected = true;
            if (reconnect) {
                dispatch.execute(() -> {
                    List<String> filters = new java.util.ArrayList<>(handlers.keySet());
                    filters.addAll(rawHandlers.keySet());
                    for (String filter : filters) {
                        try {
                            client.subscribe(filter, 1);
                        } catch (MqttException e) {
                            problems.accept("vda5050: cannot renew the subscription to " + filter + ": " + reason(e));
                        }
                    }
                    reconnectListeners.forEach(Runnable::run);
                });
            }
        }

        @Override
        public void connectionLost(Throwable cause) {
            connected = false;
        }

        @Override
        public void messageArrived(String topic, MqttMessage message) {
            byte[] payload = message.getPayload();
            if (!topic.startsWith(Topic.INTERFACE + "/") && rawHandlers.keySet().stream().anyMatch(f -> matches(f, topic))) {
                // a thread of their own: a VDA 5050 handler may wait (e.g. for a door to open) for a device's message
                received.incrementAndGet();
                rawDispatch.execute(() -> deliverRaw(topic, payload));
                return;
            }
            dispatch.execute(() -> deliver(topic, payload));
        }

        @Override
        public void deliveryComplete(IMqttDeliveryToken token) {
        }
    }

    /** Disconnects cleanly (no last will), after the messages published so far have gone out. */
    @Override
    public void close() {
        try {
            if (client.isConnected()) {
                client.disconnect(2000).waitForCompletion(3000);
            }
        } catch (MqttException e) {
            // closing anyway
        }
        closeQuietly();
    }

    private void closeQuietly() {
        rawDispatch.shutdown();
        dispatch.shutdown();
        try {
            dispatch.awaitTermination(1, TimeUnit.SECONDS);
            client.close(true);
        } catch (MqttException | InterruptedException e) {
            // nothing left to release
        }
    }
}
