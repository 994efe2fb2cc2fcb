package rp1.simulator.net;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;

/**
 * A network client's socket as a {@link Transport}. The channel is non-blocking: a write takes what
 * the kernel's send buffer has room for at once, and only the queue's writer thread ever waits (on a
 * selector opened the first time the client falls behind).
 */
final class ChannelTransport implements Transport {
    private final SocketChannel channel;
    private Selector writable;

    ChannelTransport(SocketChannel channel) {
        this.channel = channel;
    }

    @Override
    public int tryWrite(byte[] b, int off, int len) throws IOException {
        return channel.write(ByteBuffer.wrap(b, off, len));
    }

    @Override
    public void write(byte[] b, int off, int len) throws IOException {
        ByteBuffer buffer = ByteBuffer.wrap(b, off, len);
        channel.write(buffer);
        while (buffer.hasRemaining()) {
            awaitWritable();
            channel.write(buffer);
        }
    }

    private void awaitWritable() throws IOException {
        try {
            Selector s = selector();
            s.select();
            s.selectedKeys().clear();
        } catch (ClosedSelectorException e) {
            throw new IOException("connection closed", e);
        }
    }

    private synchronized Selector selector() throws IOException {
        if (writable == null) {
            writable = Selector.open();
            channel.register(writable, SelectionKey.OP_WRITE);
        }
        return writable;
    }

    @Override
    public void close() {
        Selector s;
        synchronized (this) {
            s = writable;
        }
        try {
            channel.close();
            if (s != null) {
                s.close();
            }
        } catch (IOException ignored) {
            // The connection is being abandoned; a failure to close it changes nothing.
        }
    }
}
