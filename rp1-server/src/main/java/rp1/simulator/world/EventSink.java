package rp1.simulator.world;

import rp1.rossum.event.RsEvent;

/**
 * Where a robot's events go: its client's session. Simulation-generated events (motion started and
 * halted, sensor state changes, mouse clicks) go only to subscribed clients; answers to requests go
 * always.
 */
public interface EventSink {
    /** Sends {@code event} to the client, whatever its subscriptions. */
    void send(RsEvent event);

    /** Whether the client subscribed to events with this code and index. */
    boolean isSubscribed(int eventCode, int index);

    /** Sends {@code event} if the client subscribed to its code and index. */
    default void sendIfSubscribed(RsEvent event) {
        if (isSubscribed(event.eventID, event.getIndex())) {
            send(event);
        }
    }
}
