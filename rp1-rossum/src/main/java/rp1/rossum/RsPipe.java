package rp1.rossum;

import java.io.IOException;
import java.io.InputStream;
import java.io.InterruptedIOException;
import java.io.OutputStream;

/**
 * A one-way in-memory byte channel between two threads of one process, used to connect an in-process
 * client to the server without a socket. Unlike {@code java.io.PipedInputStream} it does not care
 * which threads read or write (a writer thread that ends does not break it), it wakes the reader as
 * soon as bytes arrive, and closing either end releases a thread blocked on the other: the reader
 * sees end of stream once the buffer is drained, the writer gets an {@link IOException}.
 */
public final class RsPipe {
    /** Default buffer size: room for hundreds of typical messages. */
    public static final int DEFAULT_CAPACITY = 64 * 1024;

    private final byte[] buffer;
    private int head;
    private int count;
    private boolean writerClosed;
    private boolean readerClosed;
    private boolean readerWaiting;
    /** Whether the reader has been answered the end of the stream. */
    private boolean readerAtEnd;
    private final InputStream input = new PipeInput();
    private final OutputStream output = new PipeOutput();

    /** A pipe with the default capacity. */
    public RsPipe() {
        this(DEFAULT_CAPACITY);
    }

    /** A pipe holding up to {@code capacity} bytes before writers block. */
    public RsPipe(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity must be positive, got " + capacity);
        }
        buffer = new byte[capacity];
    }

    /** The reading end. */
    public InputStream getInputStream() {
        return input;
    }

    /** The writing end. */
    public OutputStream getOutputStream() {
        return output;
    }

    private synchronized int read(byte[] b, int off, int len) throws IOException {
        if (len == 0) {
            return 0;
        }
        while (count == 0) {
            if (writerClosed || readerClosed) {
                readerAtEnd = true;
                return -1;
            }
            readerWaiting = true;
            try {
                awaitChange();
            } finally {
                readerWaiting = false;
            }
        }
        int n = Math.min(len, count);
        int first = Math.min(n, buffer.length - head);
        System.arraycopy(buffer, head, b, off, first);
        System.arraycopy(buffer, 0, b, off + first, n - first);
        head = (head + n) % buffer.length;
        count -= n;
        notifyAll();
        return n;
    }

    private synchronized void write(byte[] b, int off, int len) throws IOException {
        while (len > 0) {
            if (readerClosed) {
                throw new IOException("pipe closed by its reader");
            }
            if (writerClosed) {
                throw new IOException("pipe closed");
            }
            if (count == buffer.length) {
                awaitChange();
                continue;
            }
            int tail = (head + count) % buffer.length;
            int n = Math.min(len, Math.min(buffer.length - count, buffer.length - tail));
            System.arraycopy(b, off, buffer, tail, n);
            count += n;
            off += n;
            len -= n;
            notifyAll();
        }
    }

    private void awaitChange() throws InterruptedIOException {
        try {
            wait();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted while waiting on an RsPipe");
        }
    }

    private synchronized int available() {
        return count;
    }

    /**
     * How many bytes can be written now without blocking. With a single writer this stays true until
     * it writes: the reader only ever makes more room. Lets a server write to an in-process client
     * without a thread hop when the client keeps up, and queue the message when it does not.
     */
    public synchronized int room() {
        return buffer.length - count;
    }

    /**
     * Whether everything written so far has been read and the reader is blocked waiting for more, or
     * has been told there is no more (the writer closed): a reader that decodes messages has then
     * dealt with every message it was sent. The simulator uses this to start its clock only once
     * in-process clients have finished their first requests; a client that sent them and ended at
     * once (its run() threw) is drained too, or the clock would wait for it until connectTimeout.
     */
    public synchronized boolean isDrained() {
        return count == 0 && (readerWaiting || readerAtEnd);
    }

    /** Whether the reader has been answered the end of the stream (the writer closed, everything read). */
    public synchronized boolean isAtEnd() {
        return readerAtEnd;
    }

    private synchronized void closeWriter() {
        writerClosed = true;
        notifyAll();
    }

    private synchronized void closeReader() {
        readerClosed = true;
        count = 0;
        notifyAll();
    }

    private final class PipeInput extends InputStream {
        @Override
        public int read() throws IOException {
            byte[] one = new byte[1];
            return RsPipe.this.read(one, 0, 1) < 0 ? -1 : one[0] & 0xFF;
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            return RsPipe.this.read(b, off, len);
        }

        @Override
        public int available() {
            return RsPipe.this.available();
        }

        @Override
        public void close() {
            closeReader();
        }
    }

    private final class PipeOutput extends OutputStream {
        @Override
        public void write(int b) throws IOException {
            RsPipe.this.write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            RsPipe.this.write(b, off, len);
        }

        @Override
        public void close() {
            closeWriter();
        }
    }
}
