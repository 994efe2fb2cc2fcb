package rp1.simulator.session;

import java.util.HashSet;
import java.util.Set;

import rp1.rossum.event.RsEvent;
import rp1.rossum.wire.EventKey;

/**
 * Which simulation-generated events a client wants (docs/protocol.md section 10): (event code, index)
 * pairs, the index being the sensor id for sensor events and 0 otherwise. Subscriptions to timeouts,
 * positions and placements are ignored (those always go out), as are codes outside 0..13 and
 * negative indices. Any sensor id is accepted (RP1 0.60 stopped at 1000; with many robots in one
 * process part ids pass that quickly).
 */
final class Subscriptions {
    private final Set<Long> wanted = new HashSet<>();

    void set(int code, int index, boolean enable) {
        if (code < 0 || code > RsEvent.EVT_MAX_CODE || index < 0 || code == RsEvent.EVT_TIMEOUT
                || code == RsEvent.EVT_POSITION || code == RsEvent.EVT_PLACEMENT) {
            return;
        }
        if (enable) {
            wanted.add(EventKey.of(code, index));
        } else {
            wanted.remove(EventKey.of(code, index));
        }
    }

    /** How many (code, index) pairs are wanted. */
    int size() {
        return wanted.size();
    }

    boolean isSubscribed(int code, int index) {
        return wanted.contains(EventKey.of(code, index));
    }

}
