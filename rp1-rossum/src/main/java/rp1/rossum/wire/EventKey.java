package rp1.rossum.wire;

/**
 * An (event code, index) pair as one {@code long}: the code in the high 32 bits, the index (any
 * {@code int}, taken unsigned) in the low 32. Subscriptions and event handlers are kept by such
 * pairs, the index being the sensor id for sensor events and 0 otherwise (docs/protocol.md section 10).
 */
public final class EventKey {
    private EventKey() {
    }

    /**
     * The key of a pair; distinct pairs give distinct keys.
     *
     * @param code  the event code
     * @param index the sensor id, or 0
     * @return the pair as one value
     */
    public static long of(int code, int index) {
        return ((long) code << 32) | (index & 0xFFFFFFFFL);
    }
}
