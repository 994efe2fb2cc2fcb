package rp1.bench;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.Closeable;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;

/**
 * What the interlocked round trips are measured against: the plain Java ping-pong of one int between
 * two threads, over a loopback socket or through {@code PipedInputStream}s, each int flushed at once.
 */
final class Baselines implements RoundTrips {
    private final DataInputStream in;
    private final DataOutputStream out;
    private final Closeable resource;
    private int value;

    private Baselines(InputStream rawIn, OutputStream rawOut, Closeable resource) {
        this.in = new DataInputStream(new BufferedInputStream(rawIn));
        this.out = new DataOutputStream(new BufferedOutputStream(rawOut));
        this.resource = resource;
    }

    /** A ping-pong over a loopback TCP connection (TCP_NODELAY on both ends). */
    static Baselines socket() throws IOException {
        ServerSocket listener = new ServerSocket();
        listener.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        startEcho(() -> {
            try (Socket s = listener.accept()) {
                s.setTcpNoDelay(true);
                echo(s.getInputStream(), s.getOutputStream());
            }
        });
        Socket s = new Socket();
        s.connect(listener.getLocalSocketAddress());
        s.setTcpNoDelay(true);
        return new Baselines(s.getInputStream(), s.getOutputStream(), () -> {
            s.close();
            listener.close();
        });
    }

    /** A ping-pong through a pair of {@code PipedInputStream}s. */
    static Baselines piped() throws IOException {
        PipedInputStream toEcho = new PipedInputStream();
        PipedOutputStream intoEcho = new PipedOutputStream(toEcho);
        PipedInputStream fromEcho = new PipedInputStream();
        PipedOutputStream outOfEcho = new PipedOutputStream(fromEcho);
        startEcho(() -> echo(toEcho, outOfEcho));
        return new Baselines(fromEcho, intoEcho, intoEcho);
    }

    private interface Echo {
        void run() throws IOException;
    }

    private static void startEcho(Echo echo) {
        Thread t = new Thread(() -> {
            try {
                echo.run();
            } catch (IOException e) {
                // the measuring side closed its end: the ping-pong is over
            }
        }, "echo");
        t.setDaemon(true);
        t.start();
    }

    private static void echo(InputStream rawIn, OutputStream rawOut) throws IOException {
        DataInputStream in = new DataInputStream(new BufferedInputStream(rawIn));
        DataOutputStream out = new DataOutputStream(new BufferedOutputStream(rawOut));
        while (true) {
            out.writeInt(in.readInt() + 1);
            out.flush();
        }
    }

    @Override
    public double measure(double seconds) throws IOException {
        long start = System.nanoTime();
        long end = start + (long) (seconds * 1e9);
        int n = 0;
        while (System.nanoTime() < end) {
            out.writeInt(value);
            out.flush();
            value = in.readInt();
            n++;
        }
        return n / ((System.nanoTime() - start) * 1e-9);
    }

    @Override
    public void close() throws IOException {
        resource.close();
    }
}
