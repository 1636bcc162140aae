package org.triad.vda5050.protocol;

import java.util.List;

import com.fasterxml.jackson.annotation.JsonInclude;

import org.triad.vda5050.protocol.Messages.Edge;
import org.triad.vda5050.protocol.Messages.Node;

/** An order from master control to an AGV: a graph of nodes and edges to traverse, with actions on them. */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record Order(int headerId, String timestamp, String version, String manufacturer, String serialNumber, String orderId,
        int orderUpdateId, String zoneSetId, List<Node> nodes, List<Edge> edges) implements Header {
    public Order {
        nodes = List.copyOf(nodes);
        edges = List.copyOf(edges);
    }
}
