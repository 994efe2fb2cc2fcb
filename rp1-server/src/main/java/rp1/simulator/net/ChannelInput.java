package rp1.simulator.net;

import java.io.IOException;
import java.io.InputStream;
import java.net.SocketTimeoutException;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;

/**
 * The reading side of a network client's non-blocking socket channel as a blocking
 * {@code InputStream} (what {@code RsConnection} reads from), with an optional time limit for the
 * handshake. Closing it closes the channel and wakes a reader blocked on it.
 */
final class ChannelInput extends InputStream {
    private final SocketChannel channel;
    private final Selector readable;
    private volatile long timeoutMillis;
    /**
     * Whether the last read found the socket empty (returned less than asked): then the next read
     * waits for data first instead of trying a read that would only say "nothing yet".
     */
    private boolean drained;

    ChannelInput(SocketChannel channel) throws IOException {
        this.channel = channel;
        this.readable = Selector.open();
        try {
            channel.register(readable, SelectionKey.OP_READ);
        } catch (IOException e) {
            readable.close();
            throw e;
        }
    }

    /** Reads fail with {@link SocketTimeoutException} after waiting this long; 0 waits for ever. */
    void setTimeout(long millis) {
        timeoutMillis = millis;
    }

    @Override
    public int read() throws IOException {
        byte[] one = new byte[1];
        return read(one, 0, 1) < 0 ? -1 : one[0] & 0xFF;
    }

    @Override
    public int read(byte[] b, int off, int len) throws IOException {
        if (len == 0) {
            return 0;
        }
        ByteBuffer buffer = ByteBuffer.wrap(b, off, len);
        long limit = timeoutMillis;
        long deadline = System.nanoTime() + limit * 1_000_000L;
        while (true) {
            if (drained) {
                awaitReadable(limit, deadline);
            }
            int n = channel.read(buffer);
            drained = n < len;
            if (n != 0) {
                return n;
            }
        }
    }

    private void awaitReadable(long limit, long deadline) throws IOException {
        long wait = 0;
        if (limit > 0) {
            wait = (deadline - System.nanoTime()) / 1_000_000L;
            if (wait <= 0) {
                throw new SocketTimeoutException("no data within " + limit + " ms");
            }
        }
        awaitReadable(wait);
    }

    private void awaitReadable(long millis) throws IOException {
        try {
            readable.select(millis);
            readable.selectedKeys().clear();
        } catch (ClosedSelectorException e) {
            throw new IOException("connection closed", e);
        }
    }

    @Override
    public void close() throws IOException {
        try {
            channel.close();
        } finally {
            readable.close();
        }
    }
}
