package rp1.rossum;

import java.util.Arrays;

/** The bytes a non-blocking reader has handed over that do not yet make a whole message. */
final class FeedBuffer {
    byte[] bytes = new byte[512];
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
        if (count > 0) {
            System.arraycopy(bytes, count, bytes, 0, length - count);
            length -= count;
        }
    }
}
