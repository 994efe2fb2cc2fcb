package rp1.rossum;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsEventHandler;
import rp1.rossum.wire.EventKey;

/**
 * The client's event handlers, keyed by (event code, index) where the index is the sensor id for
 * sensor events and 0 otherwise. Handlers for a key are kept in registration order, as an array that
 * is never changed but replaced: dispatch takes the array as it is (a snapshot that costs nothing,
 * once per event), so a handler may add or remove handlers while an event is being delivered. The
 * keys every client uses (the protocol's event codes, sensor ids below {@link #SMALL_INDEXES}) are
 * looked up in arrays: a crowd's clients dispatch hundreds of thousands of events a second, and a
 * hashed key costs a box and several dependent loads each.
 *
 * <p>Handlers are added and removed under the registry's lock, and each change publishes new tables
 * through a volatile field, so that a dispatch, on whichever thread, reads them without a lock: with
 * a thousand robots in one world a lock taken per event was a compare-and-swap on a thousand objects
 * in turn, and a list's iterator two allocations per event.
 */
final class HandlerRegistry {
    /** Indexes below this, for codes of {@link RsEvent}, are kept in arrays; the rest in a map. */
    private static final int SMALL_INDEXES = 64;
    private static final RsEventHandler[] NONE = new RsEventHandler[0];
    /**
     * By code, by index: the handlers, or null where none were ever registered. Never changed once
     * published: a change copies the code's row into a new table.
     */
    private volatile RsEventHandler[][][] small = new RsEventHandler[RsEvent.EVT_ARRAY_SIZE][][];
    /** The other keys' handlers; never changed once published, likewise. */
    private volatile Map<Long, RsEventHandler[]> others = Map.of();

    /** Whether any handler is registered for the key. */
    boolean has(int code, int index) {
        return snapshot(code, index).length > 0;
    }

    synchronized void add(int code, int index, RsEventHandler handler) {
        RsEventHandler[] list = get(code, index);
        RsEventHandler[] grown = list == null ? new RsEventHandler[1] : Arrays.copyOf(list, list.length + 1);
        grown[grown.length - 1] = handler;
        put(code, index, grown);
    }

    /**
     * Removes every registration of {@code handler} for the key, as RP1 0.60 does: a handler added
     * twice is gone after one removal, so the key may be left without handlers and the next add for
     * it subscribes again (protocol.md section 10).
     */
    synchronized void remove(int code, int index, RsEventHandler handler) {
        RsEventHandler[] list = get(code, index);
        if (list != null) {
            put(code, index, Arrays.stream(list).filter(h -> !handler.equals(h)).toArray(RsEventHandler[]::new));
        }
    }

    /** Removes every handler for the key (the no-argument {@code remove…EventHandler()} forms). */
    synchronized void removeAll(int code, int index) {
        put(code, index, null);
    }

    /**
     * The handlers for the key, in registration order, as a snapshot: an array that later
     * registrations leave as it is, and that the caller must not change.
     */
    RsEventHandler[] snapshot(int code, int index) {
        RsEventHandler[] list = get(code, index);
        return list == null ? NONE : list;
    }

    private static boolean isSmall(int code, int index) {
        return code >= 0 && code < RsEvent.EVT_ARRAY_SIZE && index >= 0 && index < SMALL_INDEXES;
    }

    private RsEventHandler[] get(int code, int index) {
        if (!isSmall(code, index)) {
            return others.get(EventKey.of(code, index));
        }
        RsEventHandler[][] byIndex = small[code];
        return byIndex == null || index >= byIndex.length ? null : byIndex[index];
    }

    /** Publishes the key's handlers; null removes the key. Only under the lock. */
    private void put(int code, int index, RsEventHandler[] list) {
        if (!isSmall(code, index)) {
            Map<Long, RsEventHandler[]> changed = new HashMap<>(others);
            if (list == null) {
                changed.remove(EventKey.of(code, index));
            } else {
                changed.put(EventKey.of(code, index), list);
            }
            others = changed;
            return;
        }
        RsEventHandler[][] byIndex = small[code];
        if (byIndex == null || index >= byIndex.length) {
            if (list == null) {
                return;
            }
            byIndex = byIndex == null ? new RsEventHandler[index + 1][] : Arrays.copyOf(byIndex, index + 1);
        } else {
            byIndex = byIndex.clone();
        }
        byIndex[index] = list;
        RsEventHandler[][][] table = small.clone();
        table[code] = byIndex;
        small = table;
    }
}
