package rp1.simulator.net;

import java.util.concurrent.atomic.AtomicLong;

/**
 * Bytes that all the network clients of one server together may make it hold for one purpose (events
 * waiting for clients that do not read them). Each client's own budget ({@code clientOutputBudget})
 * bounds one client; this bounds them all, so that a few hundred connections, each within its own
 * budget, cannot take the memory every client needs. Any thread.
 */
final class SharedBudget {
    private final AtomicLong held = new AtomicLong();
    private final long limit;

    SharedBudget(long limit) {
        if (limit <= 0) {
            throw new IllegalArgumentException("limit must be positive, got " + limit);
        }
        this.limit = limit;
    }

    /** Holds {@code bytes} more if that stays within the limit; returns whether it did. */
    boolean take(long bytes) {
        while (true) {
            long now = held.get();
            if (now + bytes > limit) {
                return false;
            }
            if (held.compareAndSet(now, now + bytes)) {
                return true;
            }
        }
    }

    /** Lets go of {@code bytes} taken before. */
    void give(long bytes) {
        held.addAndGet(-bytes);
    }

    /** The bytes held now. */
    long held() {
        return held.get();
    }

    /** The most that may be held. */
    long limit() {
        return limit;
    }
}
