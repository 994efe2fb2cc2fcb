package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsTimeoutEvent;

/**
 * Messages have no length prefix, and a reader must not assume they arrive in one read: a stream split
 * at any byte boundary, or trickling in a byte at a time, decodes to the same events.
 */
@Timeout(60)
class SplitFrameTest {

    private static byte[] threeEvents() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        RsConnection server = new RsConnection();
        server.setInputOutputStreams(null, bytes);
        server.sendPlacementEvent(new RsPlacementEvent(0.5, true, "home", 2.5, 2.5, 3.9));
        server.sendTimeoutEvent(new RsTimeoutEvent(1.0, 4));
        server.sendMotionHaltedEvent(new RsMotionHaltedEvent(2.0, 2, 1.0, 2.0, 0.5, 1.999));
        return bytes.toByteArray();
    }

    private static List<String> decode(InputStream in) {
        List<String> seen = new ArrayList<>();
        RsClient client = new RsClient();
        client.setLogger(QuietLog.INSTANCE);
        client.addPlacementEventHandler(e -> seen.add(describe(e) + e.name + e.x + e.orientation));
        client.addTimeoutEventHandler(e -> seen.add(describe(e) + e.timeoutIndex));
        client.setInputOutputStreams(in, new ByteArrayOutputStream());
        client.addMotionHaltedEventHandler(e -> seen.add(describe(e) + e.causeOfHalt + e.duration));
        client.run();
        return seen;
    }

    private static String describe(RsEvent e) {
        return e.getClass().getSimpleName() + "@" + e.simTime + ":";
    }

    @Test
    void everySplitPointDecodesTheSameEvents() {
        byte[] stream = threeEvents();
        List<String> whole = decode(new ChunkedInputStream(stream, stream.length));
        assertEquals(3, whole.size());
        for (int split = 1; split < stream.length; split++) {
            assertEquals(whole, decode(new ChunkedInputStream(stream, split)), "split at byte " + split);
        }
    }

    @Test
    void oneByteAtATimeDecodesTheSameEvents() {
        byte[] stream = threeEvents();
        assertEquals(decode(new ChunkedInputStream(stream, stream.length)), decode(new ChunkedInputStream(stream, 1, true)));
    }

    /** Returns the first {@code split} bytes in one read and the rest in another (or one byte per read). */
    private static final class ChunkedInputStream extends InputStream {
        private final byte[] data;
        private final int split;
        private final boolean trickle;
        private int pos;

        ChunkedInputStream(byte[] data, int split) {
            this(data, split, false);
        }

        ChunkedInputStream(byte[] data, int split, boolean trickle) {
            this.data = data;
            this.split = split;
            this.trickle = trickle;
        }

        @Override
        public int read() {
            return pos < data.length ? data[pos++] & 0xFF : -1;
        }

        @Override
        public int read(byte[] b, int off, int len) {
            if (pos >= data.length) {
                return -1;
            }
            int limit = trickle ? pos + 1 : (pos < split ? split : data.length);
            int n = Math.min(len, limit - pos);
            System.arraycopy(data, pos, b, off, n);
            pos += n;
            return n;
        }

        @Override
        public int available() {
            return 0;
        }
    }
}
