package rp1.simulator.session;

import java.util.Arrays;

import rp1.rossum.event.RsEvent;
import rp1.rossum.wire.EventKey;

/**
 * Which simulation-generated events a client wants (docs/protocol.md section 10): (event code, index)
 * pairs, the index being the sensor id for sensor events and 0 otherwise. Subscriptions to timeouts,
 * positions and placements are ignored (those always go out), as are codes outside 0..13 and
 * negative indices. Any sensor id is accepted (RP1 0.60 stopped at 1000; with many robots in one
 * process part ids pass that quickly).
 *
 * <p>The pairs are kept as a sorted array of keys, replaced at each change: a client wants a handful,
 * changes them rarely, and is asked about them at every event its robot makes. Among ten thousand
 * robots, a hash set per client (its table, its entries and their boxed keys, all in different places)
 * cost several waits for memory per question, a fifth of the simulation's time.
 */
final class Subscriptions {
    private long[] wanted = new long[0];

    void set(int code, int index, boolean enable) {
        if (code < 0 || code > RsEvent.EVT_MAX_CODE || index < 0 || code == RsEvent.EVT_TIMEOUT
                || code == RsEvent.EVT_POSITION || code == RsEvent.EVT_PLACEMENT) {
            return;
        }
        long key = EventKey.of(code, index);
        int at = Arrays.binarySearch(wanted, key);
        if (enable && at < 0) {
            int insert = -at - 1;
            long[] grown = new long[wanted.length + 1];
            System.arraycopy(wanted, 0, grown, 0, insert);
            grown[insert] = key;
            System.arraycopy(wanted, insert, grown, insert + 1, wanted.length - insert);
            wanted = grown;
        } else if (!enable && at >= 0) {
            long[] shrunk = new long[wanted.length - 1];
            System.arraycopy(wanted, 0, shrunk, 0, at);
            System.arraycopy(wanted, at + 1, shrunk, at, wanted.length - at - 1);
            wanted = shrunk;
        }
    }

    /** How many (code, index) pairs are wanted. */
    int size() {
        return wanted.length;
    }

    boolean isSubscribed(int code, int index) {
        return Arrays.binarySearch(wanted, EventKey.of(code, index)) >= 0;
    }
}
