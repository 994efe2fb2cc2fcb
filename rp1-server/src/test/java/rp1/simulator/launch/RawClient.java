package rp1.simulator.launch;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;

/**
 * A test client that speaks the wire protocol byte by byte (protocol.md), with no help from the client
 * library: it can follow the protocol, break it, or stop reading.
 */
final class RawClient implements AutoCloseable {
    static final int CONNECT = 1;
    static final int ACCEPT = 2;
    static final int EVENT = 3;
    static final int REQUEST = 4;
    static final int BODY = 5;
    static final int INTERLOCK = 6;
    static final int EVT_TIMEOUT = 5;
    static final int EVT_PLACEMENT = 8;
    static final int EVT_HEARTBEAT = 12;

    final Socket socket;
    final DataOutputStream out;
    final DataInputStream in;
    private int id;
    private int key;
    private int sequence;

    private RawClient(Socket socket) throws IOException {
        this.socket = socket;
        socket.setTcpNoDelay(true);
        socket.setSoTimeout(10_000);
        out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
        in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
    }

    /** Opens a TCP connection to the server on {@code port}, nothing sent yet. */
    static RawClient open(int port) throws IOException {
        return new RawClient(new Socket("127.0.0.1", port));
    }

    /** Opens a connection whose receive buffer is small, so that a backlog reaches the server soon. */
    static RawClient openWithSmallBuffer(int port) throws IOException {
        Socket s = new Socket();
        s.setReceiveBufferSize(4096);
        s.connect(new InetSocketAddress("127.0.0.1", port));
        return new RawClient(s);
    }

    /** Opens a connection and completes the handshake with client id and key 0. */
    static RawClient connected(int port) throws IOException {
        RawClient c = open(port);
        c.handshake(0, 0);
        return c;
    }

    /** Sends CONNECT with this id and key, reads ACCEPT and adopts its id and key. */
    void handshake(int clientId, int clientKey) throws IOException {
        out.writeInt(0);
        out.writeInt(clientId);
        out.writeInt(clientKey);
        out.writeInt(0);
        out.writeInt(CONNECT);
        out.flush();
        sequence = 1;
        int[] accept = readHeader();
        if (accept[4] != ACCEPT) {
            throw new IOException("expected ACCEPT, got transaction " + accept[4]);
        }
        id = accept[1];
        key = accept[2];
    }

    /** Reads a 20-byte header: version, id, key, sequence, transaction code. */
    int[] readHeader() throws IOException {
        return new int[] {in.readInt(), in.readInt(), in.readInt(), in.readInt(), in.readInt()};
    }

    void header(int code) throws IOException {
        out.writeInt(0);
        out.writeInt(id);
        out.writeInt(key);
        out.writeInt(++sequence);
        out.writeInt(code);
    }

    /** A body "B" with one circle of radius 0.15 m (protocol.md section 8.7). */
    void sendBody() throws IOException {
        header(BODY);
        out.writeUTF("B");
        out.writeInt(1);
        out.writeInt(1);
        out.writeInt(2);
        out.writeDouble(0.0);
        out.writeDouble(0.0);
        out.writeDouble(0.15);
        out.writeUTF("c");
        color(255, 255, 255);
        out.writeInt(0);
        color(255, 200, 0);
        color(255, 200, 0);
        out.flush();
    }

    private void color(int r, int g, int b) throws IOException {
        out.writeInt(1);
        out.writeInt(r);
        out.writeInt(g);
        out.writeInt(b);
    }

    void request(int code) throws IOException {
        header(REQUEST);
        out.writeInt(code);
        out.writeInt(0);
    }

    void sendTimeout(double duration, int index) throws IOException {
        request(0);
        out.writeDouble(duration);
        out.writeInt(index);
        out.flush();
    }

    void sendMotion(double linearVelocity, double rotationalVelocity, double duration) throws IOException {
        request(3);
        out.writeDouble(linearVelocity);
        out.writeDouble(rotationalVelocity);
        out.writeDouble(duration);
        out.flush();
    }

    void sendHeartbeat(double interval) throws IOException {
        request(10);
        out.writeDouble(interval);
        out.flush();
    }

    void sendPlacement(String name) throws IOException {
        request(7);
        out.writeInt(name.length());
        out.writeUTF(name);
        out.flush();
    }

    void sendInterlock(int value) throws IOException {
        header(INTERLOCK);
        out.writeInt(value);
        out.flush();
    }

    /** An event as far as these tests need it. */
    static final class Event {
        final int code;
        final double simTime;
        final int interlock;
        /** Timeout index, heartbeat sequence, or 1/0 for a valid/invalid placement. */
        final int value;

        Event(int code, double simTime, int interlock, int value) {
            this.code = code;
            this.simTime = simTime;
            this.interlock = interlock;
            this.value = value;
        }
    }

    /** Reads one timeout, heartbeat or placement event. */
    Event readEvent() throws IOException {
        int[] h = readHeader();
        if (h[4] != EVENT) {
            throw new IOException("expected EVENT, got transaction " + h[4]);
        }
        int code = in.readInt();
        in.readInt();
        double time = in.readDouble();
        int interlock = in.readInt();
        switch (code) {
            case EVT_TIMEOUT:
            case EVT_HEARTBEAT:
                return new Event(code, time, interlock, in.readInt());
            case EVT_PLACEMENT: {
                boolean valid = in.readBoolean();
                in.readUTF();
                in.readDouble();
                in.readDouble();
                in.readDouble();
                return new Event(code, time, interlock, valid ? 1 : 0);
            }
            default:
                throw new IOException("this test client cannot decode event " + code);
        }
    }

    /** Reads events until one with {@code code}, acknowledging interlocked ones on the way. */
    Event awaitEvent(int code) throws IOException {
        while (true) {
            Event e = readEvent();
            if (e.interlock > 0 && e.code != code) {
                sendInterlock(e.interlock);
            }
            if (e.code == code) {
                return e;
            }
        }
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
