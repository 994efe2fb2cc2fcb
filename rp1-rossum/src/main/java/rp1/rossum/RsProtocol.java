package rp1.rossum;

import static rp1.rossum.wire.Closing.closeQuietly;

import java.awt.Color;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;

import rp1.rossum.wire.WireCodes;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;

/**
 * The RP1 wire protocol shared by both ends of a session: the client ({@link RsClient}) and the
 * server's per-client connection ({@link RsConnection}). It owns the streams, the 20-byte transaction
 * header (version, client id, client key, sequence number, transaction code) and its validation, the
 * sequence numbering, the logger, and the orderly shutdown of a session.
 *
 * <p>Every message is built completely in memory and then written and flushed at once under one
 * lock, so messages from different threads never interleave and a message that fails to encode
 * never reaches the stream.
 */
public class RsProtocol implements RsLogInterface {
    /** The protocol version every header carries (docs/protocol.md section 3). */
    protected static final int VERSION = WireCodes.VERSION;
    /** The highest transaction code. */
    protected static final int MAX_TRANSACTION_CODE = WireCodes.MAX_TRANSACTION_CODE;
    /** The number of transaction codes, for tables indexed by code. */
    protected static final int TRANSACTION_ARRAY_SIZE = WireCodes.MAX_TRANSACTION_CODE + 1;
    /** Transaction code: No transaction; never sent (docs/protocol.md section 3.1). */
    protected static final int NULL_TRANSACTION = WireCodes.NULL_TRANSACTION;
    /** Transaction code: The client's opening message (docs/protocol.md section 3.1). */
    protected static final int CONNECT = WireCodes.CONNECT;
    /** Transaction code: The server's answer to CONNECT (docs/protocol.md section 3.1). */
    protected static final int ACCEPT = WireCodes.ACCEPT;
    /** Transaction code: An event, server to client (docs/protocol.md section 3.1). */
    protected static final int EVENT = WireCodes.EVENT;
    /** Transaction code: A request, client to server (docs/protocol.md section 3.1). */
    protected static final int REQUEST = WireCodes.REQUEST;
    /** Transaction code: The robot's body, client to server (docs/protocol.md section 3.1). */
    protected static final int BODY_SPECIFICATION = WireCodes.BODY_SPECIFICATION;
    /**
     * Transaction code: An event's acknowledgement, client to server (docs/protocol.md section
     * 3.1).
     */
    protected static final int INTERLOCK = WireCodes.INTERLOCK;

    /** Body part type on the wire: a part with no wire encoding (docs/protocol.md section 8.2). */
    protected static final int UNDEFINED_BODY_PART = WireCodes.UNDEFINED_BODY_PART;
    /** Body part type on the wire: a wheel system (docs/protocol.md section 8.2). */
    protected static final int WHEEL_SYSTEM = WireCodes.WHEEL_SYSTEM;
    /** Body part type on the wire: a circle (docs/protocol.md section 8.2). */
    protected static final int BODY_CIRCLE = WireCodes.BODY_CIRCLE;
    /** Body part type on the wire: a polygon shape (docs/protocol.md section 8.2). */
    protected static final int BODY_SHAPE = WireCodes.BODY_SHAPE;
    /** Body part type on the wire: a generic sensor (docs/protocol.md section 8.2). */
    protected static final int BODY_SENSOR = WireCodes.BODY_SENSOR;
    /** Body part type on the wire: a target sensor (docs/protocol.md section 8.2). */
    protected static final int BODY_TARGET_SENSOR = WireCodes.BODY_TARGET_SENSOR;
    /** Body part type on the wire: a contact sensor (docs/protocol.md section 8.2). */
    protected static final int BODY_CONTACT_SENSOR = WireCodes.BODY_CONTACT_SENSOR;
    /** Body part type on the wire: a range sensor (docs/protocol.md section 8.2). */
    protected static final int BODY_RANGE_SENSOR = WireCodes.BODY_RANGE_SENSOR;
    /** Body part type on the wire: a paint sensor (docs/protocol.md section 8.2). */
    protected static final int BODY_PAINT_SENSOR = WireCodes.BODY_PAINT_SENSOR;
    /** Body part type on the wire: a painter (docs/protocol.md section 8.2). */
    protected static final int BODY_PAINTER = WireCodes.BODY_PAINTER;

    /** Plan object type on the wire: none (docs/protocol.md section 9). */
    protected static final int UNDEFINED_PLAN_OBJECT = WireCodes.UNDEFINED_PLAN_OBJECT;
    /** Plan object type on the wire: a wall or obstacle (docs/protocol.md section 9). */
    protected static final int PLAN_WALL = WireCodes.PLAN_WALL;
    /** Plan object type on the wire: a target (docs/protocol.md section 9). */
    protected static final int PLAN_TARGET = WireCodes.PLAN_TARGET;
    /** Plan object type on the wire: a placement (docs/protocol.md section 9). */
    protected static final int PLAN_PLACEMENT = WireCodes.PLAN_PLACEMENT;
    /** Plan object type on the wire: a navigation node (docs/protocol.md section 9). */
    protected static final int PLAN_NAV_NODE = WireCodes.PLAN_NAV_NODE;
    /** Plan object type on the wire: a navigation link (docs/protocol.md section 9). */
    protected static final int PLAN_NAV_LINK = WireCodes.PLAN_NAV_LINK;
    /** Plan object type on the wire: floor paint (docs/protocol.md section 9). */
    protected static final int PLAN_PAINT = WireCodes.PLAN_PAINT;

    /** Diagnostic names of the transaction codes, indexed by code. */
    protected static final String[] transactionName = {
        "NULL", "CONNECT", "ACCEPT", "EVENT", "REQUEST", "BODY_SPECIFICATION", "INTERLOCK"};
    /** Diagnostic names of the request codes, indexed by code. */
    protected static final String[] requestName = {
        "Timeout", "Subscription", "SensorStatus", "Motion", "Halt", "Position", "SetPosition",
        "Placement", "TargetSelection", "Plan", "Heartbeat", "PainterChange", "ActuatorControl",
        "EncoderStatus"};
    /** Diagnostic names of the event codes, indexed by code. */
    protected static final String[] eventName = {
        "ContactSensor", "MouseClick", "Position", "RangeSensor", "TargetSensor", "Timeout",
        "MotionStarted", "MotionHalted", "Placement", "TargetSelection", "Plan", "PaintSensor",
        "Heartbeat", "EncoderStatus"};

    /** The socket, when the session runs over one ({@link #setSocket}); null otherwise. */
    protected Socket socket;
    /** The buffered input stream; null before streams are set and after shutdown. */
    protected DataInputStream input;
    /** The buffered output stream; null before streams are set and after shutdown. */
    protected DataOutputStream output;
    /** The client id every header carries (assigned in the handshake). */
    protected int clientID;
    /** The client key every header carries (assigned in the handshake). */
    protected int clientKey;
    /** The number of the last message this side sent. */
    protected int sequence;
    /** The sequence number of the last message received from the peer (kept, never checked: 0.60 did not either). */
    protected int serverSequence;
    /** Where this session logs; null for no log. */
    protected RsLogInterface logger;
    /** Whether verbose lines are logged; copied from the logger when one is set. */
    protected boolean verbosity;

    /** Serializes whole messages on the output stream. */
    private final Object writeLock = new Object();
    /**
     * Guards the open/closed state. Separate from the write lock (and from this object's monitor) so
     * that a session can be shut down while another thread is blocked writing to a peer that stopped
     * reading: closing the stream is what releases that writer.
     */
    private final Object stateLock = new Object();
    private boolean loggerSet;
    /**
     * Changed under {@link #stateLock}, read without it: every event sent and every request asks, and
     * a directly connected client's event loop waits on that lock ({@link #awaitClosed}), which makes
     * the JVM inflate its monitor: each ask was then a heavyweight lock, hundreds of thousands a second
     * in a crowd.
     */
    private volatile boolean closed;
    private RsProtocolShutdownHandler shutdownHandler;
    /** Run by {@link #shutdown()} before the handler: closes the other end of a direct link. */
    private volatile Runnable closingAction = () -> { };
    private WireIn wireIn;
    /** The streams as given, closed directly on shutdown: closing the buffered wrappers would flush. */
    private InputStream rawInput;
    private OutputStream rawOutput;

    /** A session without streams yet. */
    public RsProtocol() {
    }

    /**
     * Talks over {@code socket}. Nagle's algorithm is switched off: RP1 messages are small and
     * answered one by one, and delaying them would cap interlocked exchanges at a few dozen per second.
     */
    public void setSocket(Socket socket) throws IOException {
        this.socket = socket;
        socket.setTcpNoDelay(true);
        setInputOutputStreams(socket.getInputStream(), socket.getOutputStream());
    }

    /** Talks over these streams (buffered here); either may be null. */
    public void setInputOutputStreams(InputStream in, OutputStream out) {
        synchronized (stateLock) {
            rawInput = in;
            rawOutput = out;
            input = in == null ? null : new DataInputStream(new BufferedInputStream(in));
            output = out == null ? null : new DataOutputStream(new BufferedOutputStream(out));
            wireIn = input == null ? null : new WireIn(input);
            closed = false;
        }
    }

    /**
     * Whether an input stream is set (and the session not shut down).
     *
     * @return whether messages can be read
     */
    public boolean isInputSet() {
        return input != null;
    }

    /**
     * Whether an output stream is set (and the session not shut down).
     *
     * @return whether messages can be written
     */
    public boolean isOutputSet() {
        return output != null;
    }

    /** Whether {@link #setLogger} has been called (even with null). */
    public boolean isLoggerSet() {
        return loggerSet;
    }

    /** Called once when this session shuts down. */
    public void setProtocolShutdownHandler(RsProtocolShutdownHandler handler) {
        shutdownHandler = handler;
    }

    /** Logs through {@code logger}; null disables logging. Either way the logger counts as set. */
    public void setLogger(RsLogInterface logger) {
        this.logger = logger;
        loggerSet = true;
        if (logger != null) {
            verbosity = logger.getVerbosity();
        }
    }

    @Override
    public void log(String message) {
        LogLevels.standard(this, message);
    }

    @Override
    public void verbose(String message) {
        LogLevels.verbose(this, verbosity, message);
    }

    @Override
    public boolean getVerbosity() {
        return verbosity;
    }

    @Override
    public void setVerbosity(boolean value) {
        verbosity = value;
        if (logger != null) {
            logger.setVerbosity(value);
        }
    }

    @Override
    public void logIt(String level, String message) {
        RsLogInterface l = logger;
        if (l != null) {
            l.logIt(level, message);
        }
    }

    /**
     * Reads and validates a transaction header (protocol.md section 3.2): version 0, this session's
     * client id and key, a transaction code in 1..6.
     *
     * @return the transaction code
     * @throws java.io.EOFException if the stream ended cleanly before the header
     * @throws RsProtocolException if the header is invalid or the stream ends inside it
     */
    protected int readHeader() throws IOException {
        return readHeader(wire());
    }

    /** {@link #readHeader()} from {@code in}. */
    int readHeader(WireIn in) throws IOException {
        int version = in.firstI32("header version");
        if (version != VERSION) {
            throw new RsProtocolException("header version", "expected " + VERSION + ", got " + version);
        }
        int id = in.i32("header client id");
        if (id != clientID) {
            throw new RsProtocolException("header client id", "expected " + clientID + ", got " + id);
        }
        int key = in.i32("header client key");
        if (key != clientKey) {
            throw new RsProtocolException("header client key", "expected " + clientKey + ", got " + key);
        }
        serverSequence = in.i32("header sequence");
        int code = in.i32("header transaction code");
        if (code < CONNECT || code > MAX_TRANSACTION_CODE) {
            throw new RsProtocolException("header transaction code", "unknown code " + code);
        }
        return code;
    }

    /** Reads a header and checks that it carries {@code expected}. */
    protected int readHeader(int expected) throws IOException {
        int code = readHeader();
        if (code != expected) {
            throw new RsProtocolException("header transaction code",
                    "expected " + transactionName[expected] + " (" + expected + "), got " + describeTransaction(code));
        }
        return code;
    }

    static String describeTransaction(int code) {
        return code >= 0 && code < transactionName.length ? transactionName[code] + " (" + code + ")" : String.valueOf(code);
    }

    /** The field-naming reader over the input stream. */
    WireIn wire() throws IOException {
        WireIn in = wireIn;
        if (in == null) {
            throw new IOException("connection is closed");
        }
        return in;
    }

    /**
     * Writes a header for {@code transactionCode} with the next sequence number straight to the output
     * stream, unflushed. Kept for subclasses written against the original API; the library itself
     * sends whole messages through {@link #send}.
     */
    protected void writeHeader(int transactionCode) throws IOException {
        synchronized (writeLock) {
            DataOutputStream out = openOutput();
            out.writeInt(VERSION);
            out.writeInt(clientID);
            out.writeInt(clientKey);
            out.writeInt(++sequence);
            out.writeInt(transactionCode);
        }
    }

    /** Writes a STR (null as the empty string) to the output stream, unflushed. */
    protected void writeString(String s) throws IOException {
        synchronized (writeLock) {
            openOutput().writeUTF(s == null ? "" : s);
        }
    }

    /** Reads a STR (never null). */
    protected String readString() throws IOException {
        return wire().str("string");
    }

    /** Writes a COLOR to the output stream, unflushed. */
    protected void writeColor(Color c) throws IOException {
        write(new WireOut().color(c));
    }

    /** Writes a COLOR_ARRAY to the output stream, unflushed. */
    protected void writeColorArray(Color[] colors) throws IOException {
        write(new WireOut().colorArray(colors));
    }

    /**
     * Reads a COLOR (docs/protocol.md section 2).
     *
     * @return the colour
     * @throws IOException if the stream fails or ends
     */
    protected Color readColor() throws IOException {
        return wire().color("color");
    }

    /**
     * Reads a COLOR_ARRAY (docs/protocol.md section 2).
     *
     * @return the colours
     * @throws IOException if the stream fails or ends
     */
    protected Color[] readColorArray() throws IOException {
        return wire().colorArray("color array");
    }

    private void write(WireOut bytes) throws IOException {
        synchronized (writeLock) {
            bytes.writeTo(openOutput());
        }
    }

    private DataOutputStream openOutput() throws IOException {
        DataOutputStream out = output;
        if (out == null) {
            throw new IOException("connection is closed");
        }
        return out;
    }

    /**
     * Sends one complete message: a header for {@code transactionCode} carrying the next sequence
     * number, then {@code payload}, flushed once.
     */
    void send(int transactionCode, WireOut payload) throws IOException {
        synchronized (writeLock) {
            DataOutputStream out = openOutput();
            WireOut header = new WireOut().header(clientID, clientKey, ++sequence, transactionCode);
            header.writeTo(out);
            if (payload != null) {
                payload.writeTo(out);
            }
            out.flush();
        }
    }

    /**
     * Sends a header carrying the current sequence number and only then counts it: the original
     * client's CONNECT goes out this way with sequence 0, so its first message afterwards carries 2.
     */
    void sendWithCurrentSequence(int transactionCode) throws IOException {
        synchronized (writeLock) {
            DataOutputStream out = openOutput();
            new WireOut().header(clientID, clientKey, sequence, transactionCode).writeTo(out);
            sequence++;
            out.flush();
        }
    }

    /** Sets what {@link #shutdown()} does besides closing the streams (a direct link closes its other end). */
    void setClosingAction(Runnable action) {
        closingAction = action;
    }

    /** Waits until this session has been shut down. */
    void awaitClosed() {
        synchronized (stateLock) {
            while (!closed) {
                try {
                    stateLock.wait();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
        }
    }

    /** Whether this session has been shut down. */
    boolean isClosed() {
        return closed;
    }

    /**
     * Ends the session: closes the streams and the socket and calls the shutdown handler, once.
     * Further calls do nothing. Takes no lock another thread could be holding while blocked on I/O.
     */
    protected void shutdown() {
        InputStream in;
        OutputStream out;
        Socket s;
        synchronized (stateLock) {
            if (closed) {
                return;
            }
            closed = true;
            stateLock.notifyAll();
            in = rawInput;
            out = rawOutput;
            s = socket;
            rawInput = null;
            rawOutput = null;
            input = null;
            output = null;
            socket = null;
            wireIn = null;
        }
        closeQuietly(s);
        closeQuietly(in);
        closeQuietly(out);
        closingAction.run();
        RsProtocolShutdownHandler handler = shutdownHandler;
        if (handler != null) {
            handler.process();
        }
    }

    /** @deprecated the client id is taken from the handshake. */
    @Deprecated
    protected void setClientID(int id) {
        clientID = id;
    }

    /** @deprecated the client key is taken from the handshake. */
    @Deprecated
    protected void setClientKey(int key) {
        clientKey = key;
    }

    /** @deprecated for diagnostics only. */
    @Deprecated
    protected int getClientID() {
        return clientID;
    }

    /** @deprecated for diagnostics only. */
    @Deprecated
    protected int getClientKey() {
        return clientKey;
    }
}
