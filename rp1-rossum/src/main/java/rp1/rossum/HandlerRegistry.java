package rp1.rossum;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsEventHandler;
import rp1.rossum.wire.EventKey;

/**
 * The client's event handlers, keyed by (event code, index) where the index is the sensor id for
 * sensor events and 0 otherwise. Handlers for a key are kept in registration order, as a list that is
 * never changed but replaced: dispatch takes the list as it is (a snapshot that costs nothing, once per
 * event), so a handler may add or remove handlers while an event is being delivered. The keys every
 * client uses (the protocol's event codes, sensor ids below {@link #SMALL_INDEXES}) are looked up in
 * arrays: a crowd's clients dispatch hundreds of thousands of events a second, and a hashed key costs a
 * box and several dependent loads each.
 */
final class HandlerRegistry {
    /** Indexes below this, for codes of {@link RsEvent}, are kept in arrays; the rest in a map. */
    private static final int SMALL_INDEXES = 64;
    /** By code, by index: the handlers, or null where none were ever registered. */
    private final Object[][] small = new Object[RsEvent.EVT_ARRAY_SIZE][];
    private final Map<Long, List<RsEventHandler>> others = new HashMap<>();

    /** Whether any handler is registered for the key. */
    synchronized boolean has(int code, int index) {
        List<RsEventHandler> list = get(code, index);
        return list != null && !list.isEmpty();
    }

    synchronized void add(int code, int index, RsEventHandler handler) {
        List<RsEventHandler> list = get(code, index);
        List<RsEventHandler> grown = new ArrayList<>(list == null ? List.of() : list);
        grown.add(handler);
        put(code, index, Collections.unmodifiableList(grown));
    }

    /**
     * Removes every registration of {@code handler} for the key, as RP1 0.60 does: a handler added
     * twice is gone after one removal, so the key may be left without handlers and the next add for
     * it subscribes again (protocol.md section 10).
     */
    synchronized void remove(int code, int index, RsEventHandler handler) {
        List<RsEventHandler> list = get(code, index);
        if (list != null) {
            List<RsEventHandler> kept = new ArrayList<>(list);
            kept.removeIf(handler::equals);
            put(code, index, Collections.unmodifiableList(kept));
        }
    }

    /** Removes every handler for the key (the no-argument {@code remove…EventHandler()} forms). */
    synchronized void removeAll(int code, int index) {
        put(code, index, null);
    }

    /** The handlers for the key, in registration order, as a snapshot (an unmodifiable list). */
    synchronized List<RsEventHandler> snapshot(int code, int index) {
        List<RsEventHandler> list = get(code, index);
        return list == null ? List.of() : list;
    }

    private static boolean isSmall(int code, int index) {
        return code >= 0 && code < RsEvent.EVT_ARRAY_SIZE && index >= 0 && index < SMALL_INDEXES;
    }

    @SuppressWarnings("unchecked")
    private List<RsEventHandler> get(int code, int index) {
        if (!isSmall(code, index)) {
            return others.get(EventKey.of(code, index));
        }
        Object[] byIndex = small[code];
        return byIndex == null || index >= byIndex.length ? null : (List<RsEventHandler>) byIndex[index];
    }

    /** Sets the key's handlers; null removes the key. */
    private void put(int code, int index, List<RsEventHandler> list) {
        if (!isSmall(code, index)) {
            if (list == null) {
                others.remove(EventKey.of(code, index));
            } else {
                others.put(EventKey.of(code, index), list);
            }
            return;
        }
        Object[] byIndex = small[code];
        if (byIndex == null || index >= byIndex.length) {
            if (list == null) {
                return;
            }
            byIndex = byIndex == null ? new Object[index + 1] : Arrays.copyOf(byIndex, index + 1);
            small[code] = byIndex;
        }
        byIndex[index] = list;
    }
}
