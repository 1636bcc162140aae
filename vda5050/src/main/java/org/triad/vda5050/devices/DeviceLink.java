package org.triad.vda5050.devices;

import java.net.URI;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

import org.eclipse.paho.client.mqttv3.IMqttDeliveryToken;
import org.eclipse.paho.client.mqttv3.MqttCallbackExtended;
import org.eclipse.paho.client.mqttv3.MqttClient;
import org.eclipse.paho.client.mqttv3.MqttConnectOptions;
import org.eclipse.paho.client.mqttv3.MqttException;
import org.eclipse.paho.client.mqttv3.MqttMessage;
import org.eclipse.paho.client.mqttv3.persist.MemoryPersistence;
import org.triad.vda5050.mqtt.BrokerUnreachableException;
import org.triad.vda5050.mqtt.MqttLink;
import org.triad.vda5050.protocol.VdaJson;
import org.triad.vda5050.security.ClientCredentials;

/**
 * A connection for the device protocol ({@link DeviceMessages}): JSON messages on {@code triad/devices/v1/...},
 * QoS 1. A message that is not JSON of the expected shape is reported as one line and ignored. Either an MQTT
 * connection of its own ({@link #connect}), which on a secured broker ({@code ssl://}) logs in as an identity from the
 * credentials folder (the building's, {@link org.triad.vda5050.security.BrokerCredentials#BUILDING}, to serve devices),
 * or a share of master control's VDA 5050 connection ({@link #over}): the broker lets one connection in per identity,
 * and its ACL already grants master control the asking side of the protocol (publish requests, read states), so
 * whatever a master process asks of doors and lifts goes over the connection it already has, with no identity or
 * secret more to deploy.
 */
public final class DeviceLink implements AutoCloseable {
    /** What carries the messages: an MQTT client of the link's own, or a shared VDA 5050 connection. */
    private interface Transport {
        void subscribe(String topic, Consumer<byte[]> handler) throws MqttException;

        void publish(String topic, byte[] payload, boolean retained) throws MqttException;

        void close() throws MqttException;
    }

    private final Consumer<String> problems;
    private final Map<String, Consumer<byte[]>> handlers = new ConcurrentHashMap<>();
    private Transport transport;

    private DeviceLink(Consumer<String> problems) {
        this.problems = problems;
    }

    /**
     * The device protocol over master control's connection ({@code link}, e.g. {@code MasterControl.link()}): on a
     * secured broker as master control's identity. Closing this link drops its subscriptions, not the connection.
     */
    public static DeviceLink over(MqttLink link, Consumer<String> problems) {
        Objects.requireNonNull(link, "link");
        Objects.requireNonNull(problems, "problems");
        DeviceLink d = new DeviceLink(problems);
        java.util.List<Runnable> unsubscribe = new java.util.concurrent.CopyOnWriteArrayList<>();
        d.transport = new Transport() {
            @Override
            public void subscribe(String topic, Consumer<byte[]> handler) {
                unsubscribe.add(link.subscribeRaw(topic, handler));
            }

            @Override
            public void publish(String topic, byte[] payload, boolean retained) {
                link.publishRaw(topic, payload, retained);
            }

            @Override
            public void close() {
                unsubscribe.forEach(Runnable::run);
                unsubscribe.clear();
            }
        };
        return d;
    }

    /**
     * Connects to a plain broker ({@code tcp://HOST:PORT}).
     *
     * @throws BrokerUnreachableException when no broker answers within 5 s
     * @throws IllegalArgumentException for an address that is not {@code tcp://HOST:PORT}
     */
    public static DeviceLink connect(String broker, String clientId, Consumer<String> problems) {
        return connect(broker, null, clientId, problems);
    }

    /**
     * Connects as {@code identity}: on a secured broker ({@code ssl://HOST:PORT}) with that identity's certificate and
     * password from the credentials folder ({@link ClientCredentials#configuredFolder()}; the broker then uses the identity
     * as the client id); on plain TCP the identity is not used.
     *
     * @throws BrokerUnreachableException when no broker answers within 5 s or the broker refuses the identity
     * @throws IllegalArgumentException for an address that is not {@code tcp://} or {@code ssl://HOST:PORT}, or missing credentials
     */
    public static DeviceLink connect(String broker, String identity, String clientId, Consumer<String> problems) {
        Objects.requireNonNull(problems, "problems");
        URI uri;
        try {
            uri = URI.create(broker);
        } catch (IllegalArgumentException e) {
            uri = null;
        }
        if (uri == null || !("tcp".equals(uri.getScheme()) || "ssl".equals(uri.getScheme())) || uri.getHost() == null || uri.getPort() < 0) {
            throw new IllegalArgumentException("the device protocol needs a broker address tcp://HOST:PORT or ssl://HOST:PORT, not '" + broker + "'");
        }
        MqttConnectOptions o = new MqttConnectOptions();
        if ("ssl".equals(uri.getScheme())) {
            ClientCredentials credentials = ClientCredentials.forBroker(broker, identity);
            o.setUserName(credentials.identity());
            o.setPassword(credentials.password());
            o.setSocketFactory(credentials.socketFactory());
        }
        try {
            MqttClient c = new MqttClient(broker, clientId, new MemoryPersistence());
            c.setTimeToWait(2000);
            DeviceLink link = new DeviceLink(problems);
            link.transport = link.new OwnClient(c);
            c.setCallback(link.new Callback(c));
            o.setCleanSession(true);
            o.setAutomaticReconnect(true);
            o.setMaxReconnectDelay(1000);
            o.setConnectionTimeout(5);
            c.connect(o);
            return link;
        } catch (MqttException e) {
            throw new BrokerUnreachableException("no MQTT broker at " + broker + " for the devices: " + e.getMessage(), e);
        }
    }

    /** Receives messages of type {@code type} on {@code topic} (a topic or a filter with {@code +}). */
    public <T> void subscribe(String topic, Class<T> type, Consumer<T> handler) {
        Consumer<byte[]> parsing = payload -> {
            T message;
            try {
                message = VdaJson.bind(VdaJson.parse(payload), type);
            } catch (RuntimeException e) {
                problems.accept("devices: ignored message on " + topic + ": " + e.getMessage());
                return;
            }
            handler.accept(message);
        };
        handlers.put(topic, parsing);
        try {
            transport.subscribe(topic, payload -> {
                if (handlers.get(topic) == parsing) { // a later subscription to the topic replaces this one
                    parsing.accept(payload);
                }
            });
        } catch (MqttException | RuntimeException e) {
            throw new IllegalStateException("cannot subscribe to " + topic + ": " + e.getMessage(), e);
        }
    }

    /**
     * Publishes a message as JSON (QoS 1), waiting at most 2 s for the broker. A message that cannot be sent (no
     * broker) is reported as one line, not thrown: a device's state is published again at its next change, and a
     * client whose request got lost says so after its timeout.
     */
    public void publish(String topic, Object message, boolean retained) {
        try {
            transport.publish(topic, VdaJson.write(message), retained);
        } catch (MqttException | RuntimeException e) {
            problems.accept("devices: could not publish to " + topic + ": " + e.getMessage());
        }
    }

    @Override
    public void close() {
        try {
            transport.close();
        } catch (MqttException e) {
            problems.accept("devices: closing the connection: " + e.getMessage());
        }
    }

    /** A connection of this link's own; messages arrive through {@link Callback}. */
    private final class OwnClient implements Transport {
        private final MqttClient client;

        OwnClient(MqttClient client) {
            this.client = client;
        }

        @Override
        public void subscribe(String topic, Consumer<byte[]> handler) throws MqttException {
            client.subscribe(topic, 1);
        }

        @Override
        public void publish(String topic, byte[] payload, boolean retained) throws MqttException {
            client.publish(topic, payload, 1, retained);
        }

        @Override
        public void close() throws MqttException {
            if (client.isConnected()) {
                client.disconnect(2000);
            }
            client.close();
        }
    }

    private final class Callback implements MqttCallbackExtended {
        private final MqttClient client;

        Callback(MqttClient client) {
            this.client = client;
        }

        @Override
        public void connectComplete(boolean reconnect, String serverURI) {
            if (reconnect) {
                for (String t : handlers.keySet()) {
                    try {
                        client.subscribe(t, 1);
                    } catch (MqttException e) {
                        problems.accept("devices: re-subscribing to " + t + ": " + e.getMessage());
                    }
                }
            }
        }

        @Override
        public void connectionLost(Throwable cause) {
            problems.accept("devices: connection lost: " + cause);
        }

        @Override
        public void messageArrived(String topic, MqttMessage message) {
            for (Map.Entry<String, Consumer<byte[]>> h : handlers.entrySet()) {
                if (MqttLink.matches(h.getKey(), topic)) {
                    h.getValue().accept(message.getPayload());
                }
            }
        }

        @Override
        public void deliveryComplete(IMqttDeliveryToken token) {
        }
    }
}
