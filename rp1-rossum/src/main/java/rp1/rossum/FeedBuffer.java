package rp1.rossum;

import java.util.Arrays;

/**
 * The bytes a non-blocking reader has handed over that do not yet make a whole message. Once empty
 * again it gives back an array grown far beyond its initial size, so one large message does not
 * hold its size in memory for the rest of the session.
 */
final class FeedBuffer {
    static final int INITIAL_CAPACITY = 512;
    /** An empty buffer larger than this shrinks back to {@link #INITIAL_CAPACITY}. */
    static final int RETAINED_CAPACITY = 64 * 1024;

    byte[] bytes = new byte[INITIAL_CAPACITY];
    int length;

    void append(byte[] b, int offset, int count) {
        if (length + count > bytes.length) {
            bytes = Arrays.copyOf(bytes, Math.max(bytes.length * 2, length + count));
        }
        System.arraycopy(b, offset, bytes, length, count);
        length += count;
    }

    /** Drops the first {@code count} bytes (the messages that were dispatched). */
    void consume(int count) {
        if (count <= 0) {
            return;
        }
        length -= count;
        if (length > 0) {
            System.arraycopy(bytes, count, bytes, 0, length);
        } else if (bytes.length > RETAINED_CAPACITY) {
            bytes = new byte[INITIAL_CAPACITY];
        }
    }
}
