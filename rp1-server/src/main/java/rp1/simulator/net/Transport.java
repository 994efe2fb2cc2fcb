package rp1.simulator.net;

import java.io.IOException;
import java.io.OutputStream;

import rp1.rossum.RsPipe;

/**
 * The real stream to a client as its {@link OutboundQueue} uses it: a write that takes what fits
 * without blocking (so the simulation's thread can send to a client that keeps up without a thread
 * hop), a write that blocks until everything is out (for the queue's writer thread), and a close that
 * releases a blocked writer.
 */
public interface Transport {
    /**
     * Writes as much of {@code b[off, off + len)} as goes without blocking.
     *
     * @return the number of bytes written, from 0 to {@code len}
     */
    int tryWrite(byte[] b, int off, int len) throws IOException;

    /** Writes all of {@code b[off, off + len)}, waiting as long as it takes. */
    void write(byte[] b, int off, int len) throws IOException;

    /** Closes the stream; a thread blocked in {@link #write} gets an exception. */
    void close();

    /** A stream that cannot tell whether a write would block: every write goes through the writer thread. */
    static Transport of(OutputStream out) {
        return new Transport() {
            @Override
            public int tryWrite(byte[] b, int off, int len) {
                return 0;
            }

            @Override
            public void write(byte[] b, int off, int len) throws IOException {
                out.write(b, off, len);
                out.flush();
            }

            @Override
            public void close() {
                try {
                    out.close();
                } catch (IOException ignored) {
                    // The stream is being abandoned; a failure to close it changes nothing.
                }
            }
        };
    }

    /**
     * An in-process pipe, of which the queue must be the only writer: then the room the pipe reports
     * can only grow until the queue writes, and a write that fits never blocks.
     */
    static Transport of(RsPipe pipe) {
        Transport stream = of(pipe.getOutputStream());
        return new Transport() {
            @Override
            public int tryWrite(byte[] b, int off, int len) throws IOException {
                int n = Math.min(len, pipe.room());
                if (n > 0) {
                    pipe.getOutputStream().write(b, off, n);
                }
                return n;
            }

            @Override
            public void write(byte[] b, int off, int len) throws IOException {
                stream.write(b, off, len);
            }

            @Override
            public void close() {
                stream.close();
            }
        };
    }
}
