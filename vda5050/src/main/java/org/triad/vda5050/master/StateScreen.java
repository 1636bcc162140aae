package org.triad.vda5050.master;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

import org.triad.vda5050.protocol.AgvState;

/**
 * Screens the states one AGV reports before master control believes them, so that a faulty (or lying)
 * robot with valid credentials cannot blind master control:
 * <ul>
 * <li>a headerId at or just below the last one ({@value #REORDER_WINDOW} or fewer back) is a QoS 1
 * duplicate or a state overtaken by a newer one and is dropped, as before;</li>
 * <li>a headerId far below the last one is taken as a restarted AGV counting afresh (accepted, logged): a
 * single state with headerId 2147483647 used to make every later state look old;</li>
 * <li>a headerId far above the last one is accepted and logged (the AGV skipped many messages);</li>
 * <li>a state naming an order this master control never sent is logged once per order id; it never counts
 * as progress of an order of ours (the verdicts compare order ids).</li>
 * </ul>
 * A state whose payload names another AGV than its topic never gets here (see {@code MqttLink}).
 */
final class StateScreen {
    /** How far back a headerId may be and still count as a duplicate or a reordering rather than a restart. */
    static final int REORDER_WINDOW = 1000;

    private final String agv;
    private final Consumer<String> log;
    private final Set<String> sentOrders = ConcurrentHashMap.newKeySet();
    private final Set<String> foreignReported = ConcurrentHashMap.newKeySet();
    private int lastHeaderId = -1;

    StateScreen(String agv, Consumer<String> log) {
        this.agv = agv;
        this.log = log;
    }

    /** Remembers an order id this master control sent. */
    void sent(String orderId) {
        sentOrders.add(orderId);
    }

    /** The AGV (re)connected: it may count headerIds afresh. */
    void reset() {
        lastHeaderId = -1;
    }

    /** Whether to take this state as the AGV's current state. */
    boolean accept(AgvState s) {
        int h = s.headerId();
        if (lastHeaderId >= 0 && h <= lastHeaderId) {
            if ((long) lastHeaderId - h <= REORDER_WINDOW) {
                return false;
            }
            log.accept("vda5050: AGV " + agv + " went back from state headerId " + lastHeaderId + " to " + h
                    + ": taken as a restarted AGV counting afresh");
        } else if (lastHeaderId >= 0 && (long) h - lastHeaderId > REORDER_WINDOW) {
            log.accept("vda5050: AGV " + agv + " jumped from state headerId " + lastHeaderId + " to " + h);
        }
        lastHeaderId = h;
        String order = s.orderId();
        if (order != null && !order.isEmpty() && !sentOrders.contains(order) && foreignReported.add(order)) {
            log.accept("vda5050: AGV " + agv + " reports order '" + order + "', which this master control never sent"
                    + " (not taken as progress of any order of ours)");
        }
        return true;
    }
}
