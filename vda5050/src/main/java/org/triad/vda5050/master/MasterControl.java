package org.triad.vda5050.master;

import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

import com.fasterxml.jackson.databind.JsonNode;

import org.triad.vda5050.mqtt.MqttLink;
import org.triad.vda5050.mqtt.Received;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Topic;

/**
 * VDA 5050 master control on one broker: one MQTT connection serving any number of AGVs, each a
 * {@link RemoteAgv} with its own topics. The factory for services and applications:
 *
 * <pre>{@code
 * try (MasterControl master = MasterControl.connect("tcp://127.0.0.1:1883", VdaTimeouts.defaults(), System.err::println)) {
 *     RemoteAgv courier = master.agv("courier-1");          // manufacturer "triad"
 *     courier.drive("lobby", "c4");                           // an order of two nodes and an edge; blocks until done
 * }
 * }</pre>
 *
 * Messages from AGVs nobody asked for (an unknown serial number) are reported once per AGV and ignored.
 */
public final class MasterControl implements AutoCloseable {
    /** The manufacturer the simulated hospital robots report. */
    public static final String TRIAD = "triad";

    private final MqttLink link;
    private final VdaTimeouts timeouts;
    private final Consumer<String> log;
    private final Map<String, RemoteAgv> agvs = new ConcurrentHashMap<>();
    private final Set<String> unknownReported = ConcurrentHashMap.newKeySet();
    /** Every AGV heard on the connection topic (known or not), with the last connection state it reported: discovery. */
    private final Map<String, ConnectionState> announced = new ConcurrentHashMap<>();
    /** The last factsheet of every AGV heard on the factsheet topic (it is retained, so it comes before anyone asks for the AGV). */
    private final Map<String, JsonNode> factsheets = new ConcurrentHashMap<>();
    /** Whether an {@link AgvDiscovery} reports the AGVs this master was not asked for (then they are not "unknown"). */
    private volatile boolean discovering;

    private MasterControl(MqttLink link, VdaTimeouts timeouts, Consumer<String> log) {
        this.link = link;
        this.timeouts = timeouts;
        this.log = log;
    }

    /**
     * Connects to the broker at {@code tcp://HOST:PORT}.
     *
     * @param log where one-line reports go (ignored messages, unknown AGVs)
     * @throws org.triad.vda5050.mqtt.BrokerUnreachableException when no broker answers (the message names host and port)
     */
    public static MasterControl connect(String broker, VdaTimeouts timeouts, Consumer<String> log) {
        Objects.requireNonNull(timeouts, "timeouts");
        Objects.requireNonNull(log, "log");
        String clientId = "triad-master-" + ProcessHandle.current().pid() + "-" + Long.toHexString(System.nanoTime() & 0xffffff);
        MqttLink link = MqttLink.connect(broker, org.triad.vda5050.security.BrokerCredentials.MASTER, clientId, null, log, 10, 5);
        MasterControl m = new MasterControl(link, timeouts, log);
        link.onReconnect(() -> m.agvs.values().forEach(RemoteAgv::masterReconnected));
        link.subscribe(Topic.STATE.ofAll(), m::route);
        link.subscribe(Topic.CONNECTION.ofAll(), m::route);
        link.subscribe(Topic.FACTSHEET.ofAll(), m::route);
        return m;
    }

    /** The AGV of manufacturer {@value #TRIAD} with this serial number. */
    public RemoteAgv agv(String serialNumber) {
        return agv(TRIAD, serialNumber);
    }

    /** The AGV with this manufacturer and serial number; the same object for the same AGV. */
    public RemoteAgv agv(String manufacturer, String serialNumber) {
        Topic.ORDER.of(manufacturer, serialNumber); // rejects names unusable in topics
        return agvs.computeIfAbsent(manufacturer + "/" + serialNumber, k -> new RemoteAgv(link, manufacturer, serialNumber, timeouts, log));
    }

    public String broker() {
        return link.broker();
    }

    /** The MQTT link (message counts, for benchmarks). */
    public MqttLink link() {
        return link;
    }

    /**
     * The AGVs that announced themselves on this broker's {@code connection} topic (the retained message
     * of every AGV that ever connected, then each change), as {@code manufacturer/serialNumber} with the
     * last state each reported: discovery for services that drive whatever AGVs are there.
     */
    public Map<String, ConnectionState> announced() {
        return Map.copyOf(announced);
    }

    /** The last factsheet the AGV of this manufacturer and serial number published on this broker, if any. */
    public Optional<JsonNode> factsheet(String manufacturer, String serialNumber) {
        return Optional.ofNullable(factsheets.get(manufacturer + "/" + serialNumber));
    }

    /** Called by {@link AgvDiscovery}: AGVs nobody asked for are its business, not worth a line each. */
    void discovering() {
        discovering = true;
    }

    private void route(Received r) {
        if (r.address().topic() == Topic.CONNECTION) {
            announced.put(r.address().manufacturer() + "/" + r.address().serialNumber(), r.as(Connection.class).connectionState());
        } else if (r.address().topic() == Topic.FACTSHEET) {
            factsheets.put(r.address().manufacturer() + "/" + r.address().serialNumber(), r.json());
        }
        RemoteAgv agv = agvs.get(r.address().manufacturer() + "/" + r.address().serialNumber());
        if (agv == null) {
            if (!discovering && unknownReported.add(r.address().manufacturer() + "/" + r.address().serialNumber())) {
                log.accept("vda5050: ignored " + r.address().topic().leaf() + " from unknown AGV " + r.address().manufacturer() + "/"
                        + r.address().serialNumber() + " on " + r.mqttTopic() + " (no robot of this master has that serial number)");
            }
            return;
        }
        agv.receive(r);
    }

    @Override
    public void close() {
        link.close();
    }
}
