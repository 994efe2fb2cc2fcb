package rp1.simulator.net;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayDeque;
import java.util.Arrays;

/**
 * The stream a client's connection writes to, standing between the simulation and a client that may
 * stop reading (the user's guide's heartbeat backlog, section 5.4.1.1). {@code RsConnection} writes
 * each complete message and flushes once; here every flush turns the bytes written since the last one
 * into one queued message, and a writer thread of its own moves queued messages to the real stream
 * (a socket or an in-process pipe), several at a time when they pile up.
 *
 * <p>So the thread that sends an event (the scheduler, mostly) never waits for the client. When more
 * than {@code limit} messages are waiting to be written, the client is not keeping up: the queue
 * closes, reports the failure (the connection is then closed and the client's robot leaves the world)
 * and the flush fails. A failure of the real stream is reported the same way.
 */
public final class OutboundQueue extends OutputStream {
    /** Told, once, why the queue gave up. Called without any of the queue's locks held. */
    @FunctionalInterface
    public interface FailureHandler {
        void failed(String reason);
    }

    /** Bytes gathered before a write to the real stream, when messages are waiting. */
    private static final int BATCH_BYTES = 64 * 1024;

    private final OutputStream sink;
    private final int limit;
    private final FailureHandler onFailure;
    private final ArrayDeque<byte[]> queue = new ArrayDeque<>();
    private byte[] message = new byte[256];
    private int messageLength;
    /** Messages flushed but not yet written to the sink, including those the writer is writing. */
    private int waiting;
    private boolean closed;

    private OutboundQueue(OutputStream sink, int limit, FailureHandler onFailure) {
        if (limit < 1) {
            throw new IllegalArgumentException("limit must be positive, got " + limit);
        }
        this.sink = sink;
        this.limit = limit;
        this.onFailure = onFailure;
    }

    /**
     * Creates a queue in front of {@code sink} and starts its writer thread.
     *
     * @param sink       the real stream (a socket's or a pipe's); closed when the queue closes
     * @param limit      messages that may wait before the client counts as not keeping up
     * @param threadName name of the writer thread
     * @param onFailure  told why, if the client falls more than {@code limit} messages behind or the
     *                   sink fails
     */
    public static OutboundQueue start(OutputStream sink, int limit, String threadName, FailureHandler onFailure) {
        OutboundQueue q = new OutboundQueue(sink, limit, onFailure);
        Thread writer = new Thread(q::writeLoop, threadName);
        writer.setDaemon(true);
        writer.start();
        return q;
    }

    @Override
    public void write(int b) throws IOException {
        write(new byte[] {(byte) b}, 0, 1);
    }

    @Override
    public synchronized void write(byte[] b, int off, int len) throws IOException {
        ensureOpen();
        if (messageLength + len > message.length) {
            message = Arrays.copyOf(message, Math.max(message.length * 2, messageLength + len));
        }
        System.arraycopy(b, off, message, messageLength, len);
        messageLength += len;
    }

    /** Ends a message: queues what was written since the last flush. */
    @Override
    public void flush() throws IOException {
        String overflow;
        synchronized (this) {
            ensureOpen();
            if (messageLength == 0) {
                return;
            }
            if (waiting < limit) {
                queue.addLast(Arrays.copyOf(message, messageLength));
                messageLength = 0;
                waiting++;
                notifyAll();
                return;
            }
            overflow = "not reading: " + waiting + " messages waiting, the limit is " + limit + " (clientQueueLimit)";
            closeQueue();
        }
        onFailure.failed(overflow);
        closeSink();
        throw new IOException(overflow);
    }

    private void ensureOpen() throws IOException {
        if (closed) {
            throw new IOException("connection closed");
        }
    }

    /** The number of messages not yet written to the real stream. */
    public synchronized int getWaiting() {
        return waiting;
    }

    /** Drops whatever waits and closes the real stream, releasing a writer blocked on it. */
    @Override
    public void close() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closeQueue();
        }
        closeSink();
    }

    private void closeQueue() {
        closed = true;
        queue.clear();
        messageLength = 0;
        notifyAll();
    }

    private void closeSink() {
        try {
            sink.close();
        } catch (IOException ignored) {
            // The stream is being abandoned; a failure to close it changes nothing.
        }
    }

    private void writeLoop() {
        OutputStream out = new BufferedOutputStream(sink, BATCH_BYTES);
        try {
            while (true) {
                byte[][] batch = takeBatch();
                if (batch == null) {
                    return;
                }
                for (byte[] m : batch) {
                    out.write(m);
                }
                out.flush();
                written(batch.length);
            }
        } catch (IOException e) {
            writeFailed(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Waits for messages and takes all of them; null once the queue is closed. */
    private synchronized byte[][] takeBatch() throws InterruptedException {
        while (queue.isEmpty() && !closed) {
            wait();
        }
        if (closed) {
            return null;
        }
        byte[][] batch = queue.toArray(new byte[0][]);
        queue.clear();
        return batch;
    }

    private synchronized void written(int count) {
        waiting -= count;
    }

    private void writeFailed(IOException e) {
        synchronized (this) {
            if (closed) {
                return;
            }
            closeQueue();
        }
        onFailure.failed("cannot write to the client: " + e.getMessage());
        closeSink();
    }
}
