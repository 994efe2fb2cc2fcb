package rp1.rossum.event;

/** Marker for the event-handler interfaces, one per event type. */
public interface RsEventHandler {
}
