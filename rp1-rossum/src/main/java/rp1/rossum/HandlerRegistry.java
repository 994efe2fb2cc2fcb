package rp1.rossum;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import rp1.rossum.event.RsEventHandler;
import rp1.rossum.wire.EventKey;

/**
 * The client's event handlers, keyed by (event code, index) where the index is the sensor id for
 * sensor events and 0 otherwise. Handlers for a key are kept in registration order, as a list that is
 * never changed but replaced: dispatch takes the list as it is (a snapshot that costs nothing, once per
 * event), so a handler may add or remove handlers while an event is being delivered.
 */
final class HandlerRegistry {
    private final Map<Long, List<RsEventHandler>> handlers = new HashMap<>();


    /** Whether any handler is registered for the key. */
    synchronized boolean has(int code, int index) {
        List<RsEventHandler> list = handlers.get(EventKey.of(code, index));
        return list != null && !list.isEmpty();
    }

    synchronized void add(int code, int index, RsEventHandler handler) {
        long key = EventKey.of(code, index);
        List<RsEventHandler> grown = new ArrayList<>(handlers.getOrDefault(key, List.of()));
        grown.add(handler);
        handlers.put(key, Collections.unmodifiableList(grown));
    }

    /**
     * Removes every registration of {@code handler} for the key, as RP1 0.60 does: a handler added
     * twice is gone after one removal, so the key may be left without handlers and the next add for
     * it subscribes again (protocol.md section 10).
     */
    synchronized void remove(int code, int index, RsEventHandler handler) {
        long key = EventKey.of(code, index);
        List<RsEventHandler> list = handlers.get(key);
        if (list != null) {
            List<RsEventHandler> kept = new ArrayList<>(list);
            kept.removeIf(handler::equals);
            handlers.put(key, Collections.unmodifiableList(kept));
        }
    }

    /** Removes every handler for the key (the no-argument {@code remove…EventHandler()} forms). */
    synchronized void removeAll(int code, int index) {
        handlers.remove(EventKey.of(code, index));
    }

    /** The handlers for the key, in registration order, as a snapshot (an unmodifiable list). */
    synchronized List<RsEventHandler> snapshot(int code, int index) {
        return handlers.getOrDefault(EventKey.of(code, index), List.of());
    }
}
