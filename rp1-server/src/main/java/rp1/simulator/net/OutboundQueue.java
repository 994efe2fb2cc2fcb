package rp1.simulator.net;

import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayDeque;
import java.util.Arrays;

/**
 * The stream a client's connection writes to, standing between the simulation and a client that may
 * stop reading (a client that stops reading its heartbeats would otherwise fill the socket until the
 * simulation's writes block). {@code RsConnection} writes each complete message and flushes once;
 * every flush here ends one message.
 *
 * <p>A message that finds nothing waiting before it is written at once, as far as the
 * {@link Transport} takes it without blocking: a client that keeps up gets its events with no thread
 * hop, which is what makes interlocked exchanges fast. Whatever does not go out at once is queued,
 * and a writer thread of its own (started the first time it is needed) moves queued messages to the
 * transport, several at a time when they pile up.
 *
 * <p>So the thread that sends an event (the scheduler, mostly) never waits for the client. When more
 * than {@code limit} messages, or more than {@code byteBudget} bytes, are waiting (one message may
 * always wait, whatever its size), the client is not keeping up: the queue closes, reports
 * the failure (the connection is then closed and the client's robot leaves the world) and the flush
 * fails. A failing transport is reported the same way.
 */
public final class OutboundQueue extends OutputStream {
    /** Told, once, why the queue gave up. Called without any of the queue's locks held. */
    @FunctionalInterface
    public interface FailureHandler {
        void failed(String reason);
    }

    /** Bytes of waiting messages gathered into one write to the transport. */
    private static final int BATCH_BYTES = 64 * 1024;

    private final Transport transport;
    private final int limit;
    private final int byteBudget;
    private final FailureHandler onFailure;
    private final String threadName;
    private boolean writerStarted;
    private final ArrayDeque<byte[]> queue = new ArrayDeque<>();
    private byte[] message = new byte[256];
    private int messageLength;
    /** Messages not yet wholly handed to the transport, including those the writer is writing. */
    private int waiting;
    /** Bytes of the messages not yet wholly handed to the transport. */
    private long waitingBytes;
    /** What all the server's clients together may have waiting, or null if only this one's budget counts. */
    private final SharedBudget shared;
    private boolean closed;

    private OutboundQueue(Transport transport, int limit, int byteBudget, SharedBudget shared, String threadName,
                          FailureHandler onFailure) {
        if (limit < 1) {
            throw new IllegalArgumentException("limit must be positive, got " + limit);
        }
        if (byteBudget < 1) {
            throw new IllegalArgumentException("byteBudget must be positive, got " + byteBudget);
        }
        this.transport = transport;
        this.limit = limit;
        this.byteBudget = byteBudget;
        this.shared = shared;
        this.onFailure = onFailure;
        this.threadName = threadName;
    }

    /**
     * Creates a queue in front of {@code transport}.
     *
     * @param transport  the real stream; the queue must be its only writer. Closed when the queue closes
     * @param limit      messages that may wait before the client counts as not keeping up
     * @param threadName name of the writer thread
     * @param onFailure  told why, if the client falls more than {@code limit} messages behind or the
     *                   transport fails
     */
    public static OutboundQueue start(Transport transport, int limit, String threadName, FailureHandler onFailure) {
        return start(transport, limit, Integer.MAX_VALUE, threadName, onFailure);
    }

    /**
     * Creates a queue in front of {@code transport} that also gives the client up when more than
     * {@code byteBudget} bytes wait for it ({@code clientOutputBudget}); see
     * {@link #start(Transport, int, String, FailureHandler)}.
     */
    public static OutboundQueue start(Transport transport, int limit, int byteBudget, String threadName,
                                      FailureHandler onFailure) {
        return new OutboundQueue(transport, limit, byteBudget, null, threadName, onFailure);
    }

    /**
     * As {@link #start(Transport, int, int, String, FailureHandler)}, the bytes waiting also counted in
     * {@code shared}: the client is given up when all the clients together would have more waiting.
     */
    static OutboundQueue start(Transport transport, int limit, int byteBudget, SharedBudget shared, String threadName,
                               FailureHandler onFailure) {
        return new OutboundQueue(transport, limit, byteBudget, shared, threadName, onFailure);
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

    /** Ends a message: writes or queues what was written since the last flush. */
    @Override
    public void flush() throws IOException {
        String failure;
        synchronized (this) {
            ensureOpen();
            if (messageLength == 0) {
                return;
            }
            failure = send();
        }
        if (failure != null) {
            onFailure.failed(failure);
            transport.close();
            throw new IOException(failure);
        }
    }

    /** Writes what goes now, queues the rest; returns why the client is given up, or null. */
    private String send() {
        int sent = 0;
        if (waiting == 0) {
            try {
                sent = transport.tryWrite(message, 0, messageLength);
            } catch (IOException e) {
                closeQueue();
                return "cannot write to the client: " + e.getMessage();
            }
        }
        if (sent < messageLength) {
            int rest = messageLength - sent;
            String why = null;
            if (waiting >= limit) {
                why = "not reading: " + waiting + " messages waiting, the limit is " + limit + " (clientQueueLimit)";
            } else if (waiting > 0 && waitingBytes + rest > byteBudget) {
                why = "not reading: " + (waitingBytes + rest) + " bytes of events waiting, the budget is "
                        + byteBudget + " (clientOutputBudget)";
            } else if (shared != null && !shared.take(rest)) {
                why = "not reading: the events waiting for all the clients would hold more than " + shared.limit()
                        + " bytes in all (a quarter of the server's memory), " + (waitingBytes + rest) + " of them for this one";
            }
            if (why != null) {
                closeQueue(); // which forgets what waited: the reason is told first
                return why;
            }
            queue.addLast(Arrays.copyOfRange(message, sent, messageLength));
            waiting++;
            waitingBytes += rest;
            startWriter();
            notifyAll();
        }
        messageLength = 0;
        return null;
    }

    /** Most clients keep up and never need a writer; one that falls behind gets it now. */
    private void startWriter() {
        if (!writerStarted) {
            writerStarted = true;
            Thread writer = new Thread(this::writeLoop, threadName);
            writer.setDaemon(true);
            writer.start();
        }
    }

    private void ensureOpen() throws IOException {
        if (closed) {
            throw new IOException("connection closed");
        }
    }

    /** The number of messages not yet written to the transport. */
    public synchronized int getWaiting() {
        return waiting;
    }

    /** Drops whatever waits and closes the transport, releasing a writer blocked on it. */
    @Override
    public void close() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closeQueue();
        }
        transport.close();
    }

    private void closeQueue() {
        closed = true;
        queue.clear();
        messageLength = 0;
        if (shared != null) {
            shared.give(waitingBytes);
        }
        waiting = 0;
        waitingBytes = 0;
        notifyAll();
    }

    private void writeLoop() {
        byte[] batch = new byte[BATCH_BYTES];
        try {
            while (true) {
                byte[][] messages = takeWaiting();
                if (messages == null) {
                    return;
                }
                int n = 0;
                for (byte[] m : messages) {
                    if (n + m.length > batch.length) {
                        transport.write(batch, 0, n);
                        n = 0;
                    }
                    if (m.length > batch.length) {
                        transport.write(m, 0, m.length);
                    } else {
                        System.arraycopy(m, 0, batch, n, m.length);
                        n += m.length;
                    }
                }
                if (n > 0) {
                    transport.write(batch, 0, n);
                }
                written(messages);
            }
        } catch (IOException e) {
            writeFailed(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Waits for queued messages and takes all of them; null once the queue is closed. */
    private synchronized byte[][] takeWaiting() throws InterruptedException {
        while (queue.isEmpty() && !closed) {
            wait();
        }
        if (closed) {
            return null;
        }
        byte[][] messages = queue.toArray(new byte[0][]);
        queue.clear();
        return messages;
    }

    private synchronized void written(byte[][] messages) {
        if (closed) {
            return; // closing let go of everything, these too
        }
        waiting -= messages.length;
        long bytes = 0;
        for (byte[] m : messages) {
            bytes += m.length;
        }
        waitingBytes -= bytes;
        if (shared != null) {
            shared.give(bytes);
        }
    }

    private void writeFailed(IOException e) {
        synchronized (this) {
            if (closed) {
                return;
            }
            closeQueue();
        }
        onFailure.failed("cannot write to the client: " + e.getMessage());
        transport.close();
    }
}
