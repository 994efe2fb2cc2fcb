package rp1.rossum;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.util.HashSet;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;

import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsActuatorControlRequestHandler;
import rp1.rossum.request.RsEncoderStatusRequest;
import rp1.rossum.request.RsEncoderStatusRequestHandler;
import rp1.rossum.request.RsHaltRequest;
import rp1.rossum.request.RsHaltRequestHandler;
import rp1.rossum.request.RsHeartbeatRequest;
import rp1.rossum.request.RsHeartbeatRequestHandler;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsMotionRequestHandler;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsPainterChangeRequestHandler;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlacementRequestHandler;
import rp1.rossum.request.RsPlanRequest;
import rp1.rossum.request.RsPlanRequestHandler;
import rp1.rossum.request.RsPositionRequestHandler;
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSensorRequestHandler;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.request.RsSubscriptionRequestHandler;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.request.RsTargetSelectionRequestHandler;
import rp1.rossum.request.RsTimeoutRequestHandler;

/**
 * The server's end of one client session. The client's body specification, requests and interlock
 * acknowledgements are handed to the handlers the simulator registered; the {@code send...Event}
 * methods send events to the client. A session runs in one of three modes:
 * <ul>
 * <li>reading a stream: {@link #run()} reads messages until the client leaves, handlers running on
 * that thread (RP1 0.60's only mode);
 * <li>feed mode, beyond RP1 0.60: a non-blocking reader hands over bytes with {@link #receive} and
 * reports their end with {@link #endOfInput()}, handlers running on the thread that hands them over;
 * <li>direct mode, beyond RP1 0.60 ({@link #connectDirect}): a client in the same process without
 * streams, its requests handled on the thread that sends them and events handed to its handlers on
 * the thread that sends them.
 * </ul>
 *
 * <p>It also keeps the client's subscription table: which simulation-generated events (mouse clicks,
 * motion started/halted, per-sensor state changes) the client wants. The {@code send...Event} methods
 * do not consult it; the simulator does, before sending.
 */
public class RsConnection extends RsProtocol implements Runnable {
    private static final byte[] NO_BYTES = new byte[0];
    /** Bodies received in this session (handed over by one thread at a time: the decoder or the direct client). */
    private int bodiesReceived;
    /**
     * Subscriptions as (event code, index) keys. RP1 0.60 kept a fixed table of indices 0..1000, so
     * sensors whose part id exceeded 1000 could never subscribe (its process-wide part counter passed
     * 1000 quickly with many robots in one process); a client may give a part any id, so any index is
     * accepted.
     */
    private final Set<Long> subscriptions = new HashSet<>();
    /** Keeps interlock numbers in increasing order on this connection's stream. */
    private final Object eventLock = new Object();
    private final RequestSink dispatcher = new Dispatcher();
    /** Bytes handed to {@link #receive} that do not yet make a whole message. */
    private final FeedBuffer feed = new FeedBuffer();
    /** How far the message at the start of {@link #feed} has been scanned for its end. */
    private final MessageScanner scanner = new MessageScanner();
    private volatile boolean introduced;
    private volatile DirectLink direct;
    private RsInterlock interlock;
    private volatile int maxInterlockSent;

    private volatile RsTimeoutRequestHandler timeoutHandler;
    private volatile RsSubscriptionRequestHandler subscriptionHandler;
    private volatile RsMotionRequestHandler motionHandler;
    private volatile RsPositionRequestHandler positionHandler;
    private volatile RsPlacementRequestHandler placementHandler;
    private volatile RsHaltRequestHandler haltHandler;
    private volatile RsSensorRequestHandler sensorHandler;
    private volatile RsTargetSelectionRequestHandler targetSelectionHandler;
    private volatile RsPainterChangeRequestHandler painterChangeHandler;
    private volatile RsActuatorControlRequestHandler actuatorControlHandler;
    private volatile RsEncoderStatusRequestHandler encoderStatusHandler;
    private volatile RsConnectionBodyHandler bodyHandler;
    private volatile RsPlanRequestHandler planHandler;
    private volatile RsHeartbeatRequestHandler heartbeatHandler;

    /**
     * A connection not yet attached to streams: give it a socket or streams, or connect a client
     * directly.
     */
    public RsConnection() {
    }

    /** Every event sent from now on opens this interlock; acknowledgements close it. */
    public void addInterlock(RsInterlock interlock) {
        this.interlock = interlock;
    }

    /** The largest interlock number sent to this client (0 if none); released if the client leaves. */
    public int getMaxInterlockSent() {
        return maxInterlockSent;
    }

    /**
     * The server's half of the handshake: reads CONNECT, adopting the client id and key it carries
     * (the server assigns none), and answers ACCEPT echoing them.
     */
    public void exchangeIntroductions() throws IOException {
        readConnect(wire());
    }

    /** Reads CONNECT from {@code in}, adopts its id and key, and answers ACCEPT. */
    private void readConnect(WireIn in) throws IOException {
        int version = in.firstI32("CONNECT version");
        if (version != VERSION) {
            throw new RsProtocolException("CONNECT version", "expected " + VERSION + ", got " + version);
        }
        int id = in.i32("CONNECT client id");
        int key = in.i32("CONNECT client key");
        serverSequence = in.i32("CONNECT sequence");
        int code = in.i32("CONNECT transaction code");
        if (code != CONNECT) {
            throw new RsProtocolException("CONNECT transaction code", "expected CONNECT (1), got " + describeTransaction(code));
        }
        clientID = id;
        clientKey = key;
        send(ACCEPT, null);
        introduced = true;
    }

    /**
     * Reads the client's messages until it disconnects or breaks the protocol, then shuts the
     * session down, which calls the shutdown handler (the simulator removes the robot). A handler's
     * RuntimeException is not caught: it propagates out of this method, the message that caused it
     * having been read whole.
     */
    @Override
    public void run() {
        try {
            while (true) {
                readTransaction(wire());
            }
        } catch (EOFException e) {
            clientLeft();
        } catch (IOException e) {
            inputFailed(e.getMessage());
        }
    }

    /** The CONNECT message until the handshake is done, then any message a client may send. */
    private void readMessage(WireIn in) throws IOException {
        if (introduced) {
            readTransaction(in);
        } else {
            readConnect(in);
        }
    }

    private void readTransaction(WireIn in) throws IOException {
        int code = readHeader(in);
        switch (code) {
            case REQUEST:
                RequestCodec.decode(in, dispatcher);
                break;
            case BODY_SPECIFICATION:
                bodyReceived(BodyCodec.decode(in));
                break;
            case INTERLOCK: {
                int value = in.i32("interlock value");
                RsInterlock il = interlock;
                if (il != null) {
                    il.closeInterlock(value);
                }
                break;
            }
            default:
                throw new RsProtocolException("header transaction code",
                        "a server does not accept " + describeTransaction(code) + " after the handshake");
        }
    }

    /**
     * A body specification for the body handler: decoded here, or a decoded copy from a direct link.
     * It is numbered as the client numbered it: the n-th body of this session.
     */
    void bodyReceived(RsBody body) {
        body.assignID(++bodiesReceived);
        verbose("Received body specification with name " + body.getName());
        RsConnectionBodyHandler h = bodyHandler;
        if (h != null) {
            h.process(body);
        }
    }

    /**
     * Beyond RP1 0.60, for servers that read with non-blocking I/O: hands over bytes read from the
     * client. Every complete message among the bytes received so far is decoded and dispatched as
     * {@link #run()} would dispatch it (the CONNECT/ACCEPT handshake first, unless
     * {@link #exchangeIntroductions()} already did it); an incomplete one waits for the next call.
     * The bytes are parsed where they are; only the start of an incomplete message is kept, so the
     * caller may reuse its array once this returns. Where an incomplete message would end is worked
     * out from the bytes as they arrive, each byte once, and the message is decoded once, whole: a
     * message that comes a few bytes at a time costs what it would cost in one piece.
     *
     * <p>A handler's RuntimeException (or Error) is not caught, as in {@code run()}: the message that
     * caused it counts as consumed, and the messages after it wait for the next call (or for
     * {@link #endOfInput()}).
     *
     * @throws IOException if the bytes break the protocol (the message names the field), or a message
     *                     grows beyond any the protocol allows; the session should then be ended with
     *                     {@link #inputFailed}
     */
    public void receive(byte[] bytes, int offset, int length) throws IOException {
        Objects.checkFromIndexSize(offset, length, bytes.length);
        boolean inPlace = feed.length == 0;
        byte[] buffer;
        int at;
        int end;
        if (inPlace) {
            buffer = bytes;
            at = offset;
            end = offset + length;
        } else {
            feed.append(bytes, offset, length);
            buffer = feed.bytes;
            at = 0;
            end = feed.length;
        }
        int start = at;
        try {
            while (at < end) {
                int size = scanner.scan(buffer, at, end, introduced);
                if (size < 0) {
                    if (end - at > WireLimits.MAX_MESSAGE_BYTES) {
                        throw new RsProtocolException(truncation(buffer, at, end).getField(),
                                "message longer than " + WireLimits.MAX_MESSAGE_BYTES + " bytes");
                    }
                    break;
                }
                int from = at;
                // The message counts as consumed even if its handler throws.
                at += size;
                readMessage(new WireIn(new DataInputStream(new ByteArrayInputStream(buffer, from, size))));
            }
        } finally {
            if (inPlace) {
                feed.append(buffer, at, end - at);
            } else {
                feed.consume(at - start);
            }
        }
    }

    /**
     * Beyond RP1 0.60: the bytes of a message that has begun to arrive but is not yet complete (0
     * between messages), for a server that budgets what each client may make it hold.
     */
    public int getIncompleteMessageBytes() {
        return feed.length;
    }

    /**
     * Where the incomplete message in {@code b[at..end)} breaks off: decoding it as far as it goes
     * names the field. If those bytes already break the protocol, that is thrown instead.
     */
    private TruncatedMessageException truncation(byte[] b, int at, int end) throws IOException {
        try {
            readMessage(new WireIn(new DataInputStream(new ByteArrayInputStream(b, at, end - at))));
        } catch (TruncatedMessageException e) {
            return e;
        }
        throw new IllegalStateException("an incomplete message of " + (end - at) + " bytes decoded whole");
    }

    /**
     * Beyond RP1 0.60: the non-blocking transport found the end of the client's input. Ends the
     * session (calling the shutdown handler), logging whether the client left between messages or in
     * the middle of one. Complete messages still waiting (a handler threw before they were reached)
     * are dispatched first, as a reader of a stream reads them before the end.
     */
    public void endOfInput() {
        String problem;
        try {
            receive(NO_BYTES, 0, 0);
            problem = feed.length > 0 ? truncation(feed.bytes, 0, feed.length).getMessage() : null;
        } catch (IOException e) {
            problem = e.getMessage();
        } catch (RuntimeException | Error e) {
            shutdown();
            throw e;
        }
        if (problem == null) {
            clientLeft();
        } else {
            inputFailed(problem);
        }
    }

    private void clientLeft() {
        log("RsConnection: client " + clientID + " closed the connection");
        shutdown();
    }

    /**
     * Beyond RP1 0.60: the client's input broke the protocol or could not be read. Logs
     * "RsConnection terminating due to exception on input: " and {@code reason} (the field at fault
     * and what was wrong with it), then ends the session, calling the shutdown handler. {@link #run()}
     * and {@link #endOfInput()} end this way; a non-blocking reader calls it when {@link #receive}
     * throws.
     */
    public void inputFailed(String reason) {
        log("RsConnection terminating due to exception on input: " + reason);
        shutdown();
    }

    /** Whether the CONNECT/ACCEPT handshake has been done. */
    public boolean hasIntroduced() {
        return introduced;
    }

    /**
     * Beyond RP1 0.60: connects {@code client}, in the same process, to this connection without
     * streams. The client's requests come to this connection's handlers as objects (equal to what
     * decoding them from the wire would give), on the thread that sends them; its body arrives as a
     * decoded copy, as from the wire; and each event sent here is handed to the client's handlers at
     * once, on the sending thread, as a copy of what the client would decode. There is no handshake and
     * no interlock: the handlers returning is the acknowledgement. If a handler throws an
     * {@code Error}, the session ends and {@code onFailure} is told. Closing either side closes both.
     */
    public void connectDirect(RsClient client, Consumer<Throwable> onFailure) {
        DirectLink link = new DirectLink(this, client, onFailure);
        direct = link;
        client.attach(link);
        setClosingAction(link::shutdownClient);
    }

    /** What the client's requests are handed to: the same dispatch as for decoded requests. */
    RequestSink dispatcher() {
        return dispatcher;
    }

    /**
     * Beyond RP1 0.60: a body specification's payload (what follows the message header on the wire),
     * for storing a body outside a connection (a recording of a run).
     *
     * @throws IllegalArgumentException if the body has no part that can be sent, or a name is too long
     */
    public static byte[] encodeBodySpecification(RsBody body) {
        return BodyCodec.encode(body);
    }

    /**
     * Beyond RP1 0.60: reads back a payload made by {@link #encodeBodySpecification}. Every part gets
     * the id it had in the body that was encoded.
     *
     * @throws IOException naming the field if the bytes are malformed or cut short
     */
    public static RsBody decodeBodySpecification(byte[] payload) throws IOException {
        return BodyCodec.decode(payload);
    }

    /** Writes an event header and the event prefix (code, index, time, interlock), unflushed. */
    protected void writeEventHeader(RsEvent event) throws IOException {
        writeEventHeader(event.eventID, event.getIndex(), event.simTime);
    }

    /** Writes an event header and prefix for the given code, index and time, unflushed. */
    protected void writeEventHeader(int eventID, int eventIndex, double simTime) throws IOException {
        writeHeader(EVENT);
        WireOut prefix = new WireOut().i32(eventID).i32(eventIndex).f64(simTime).i32(openInterlock());
        writeRaw(prefix);
    }

    private void writeRaw(WireOut bytes) throws IOException {
        if (output == null) {
            throw new IOException("connection is closed");
        }
        bytes.writeTo(output);
    }

    private int openInterlock() {
        RsInterlock il = interlock;
        if (il == null) {
            return 0;
        }
        int value = il.openInterlock();
        if (value > maxInterlockSent) {
            maxInterlockSent = value;
        }
        return value;
    }

    /**
     * Sends any event. A write failure is logged and ends the session (the reader then stops too);
     * after that, sends do nothing. To a directly connected client ({@link #connectDirect}) nothing is
     * written: a copy of the event goes to the client's handlers, which have run when this returns.
     */
    public void sendEvent(RsEvent event) {
        DirectLink link = direct;
        if (link != null) {
            if (!isClosed()) {
                link.deliver(event);
            }
            return;
        }
        if (isClosed() || !isOutputSet()) {
            return;
        }
        try {
            synchronized (eventLock) {
                WireOut payload = new WireOut();
                EventCodec.encode(payload, event, openInterlock());
                send(EVENT, payload);
            }
        } catch (IOException e) {
            log("RsConnection: cannot send " + event + " to client " + clientID + ": " + e.getMessage());
            shutdown();
        }
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendTimeoutEvent(RsTimeoutEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendMouseClickEvent(RsMouseClickEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendPositionEvent(RsPositionEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendPlacementEvent(RsPlacementEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendMotionHaltedEvent(RsMotionHaltedEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendMotionStartedEvent(RsMotionStartedEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendTargetSensorEvent(RsTargetSensorEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendContactSensorEvent(RsContactSensorEvent e) {
        sendEvent(e);
    }

    /**
     * Sends a contact-sensor event with these values; as {@link #sendEvent}.
     *
     * @param simTime simulation time of the event, seconds
     * @param sensorID part id of the sensor
     * @param status whether the sensor is in contact
     * @param contactObjectName the name of what it touches, or null
     */
    public void sendContactSensorEvent(double simTime, int sensorID, boolean status, String contactObjectName) {
        sendEvent(new RsContactSensorEvent(simTime, sensorID, status, contactObjectName));
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendRangeSensorEvent(RsRangeSensorEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendTargetSelectionEvent(RsTargetSelectionEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendPlanEvent(RsPlanEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendPaintSensorEvent(RsPaintSensorEvent e) {
        sendEvent(e);
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendHeartbeatEvent(RsHeartbeatEvent e) {
        sendEvent(e);
    }

    /**
     * Sends a heartbeat event with these values; as {@link #sendEvent}.
     *
     * @param simTime simulation time of the beat, seconds
     * @param sequence the beat's number, from 1
     */
    public void sendHeartbeatEvent(double simTime, int sequence) {
        sendEvent(new RsHeartbeatEvent(simTime, sequence));
    }

    /**
     * Sends the event; as {@link #sendEvent}, on the thread running the simulation's tasks.
     *
     * @param e the event
     */
    public void sendEncoderStatusEvent(RsEncoderStatusEvent e) {
        sendEvent(e);
    }

    /**
     * Sets who handles the timeout requests this connection decodes (null: they are dropped). Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setTimeoutRequestHandler(RsTimeoutRequestHandler h) {
        timeoutHandler = h;
    }

    /**
     * Sets who handles the subscription requests this connection decodes (null: they are dropped).
     * Any thread; the handler is called on the thread that decodes the request (see the class
     * comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setSubscriptionRequestHandler(RsSubscriptionRequestHandler h) {
        subscriptionHandler = h;
    }

    /**
     * Sets who handles the motion requests this connection decodes (null: they are dropped). Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setMotionRequestHandler(RsMotionRequestHandler h) {
        motionHandler = h;
    }

    /**
     * Sets who handles the position requests this connection decodes (null: they are dropped). Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setPositionRequestHandler(RsPositionRequestHandler h) {
        positionHandler = h;
    }

    /**
     * Sets who handles the placement requests this connection decodes (null: they are dropped). Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setPlacementRequestHandler(RsPlacementRequestHandler h) {
        placementHandler = h;
    }

    /**
     * Sets who handles the halt requests this connection decodes (null: they are dropped). Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setHaltRequestHandler(RsHaltRequestHandler h) {
        haltHandler = h;
    }

    /**
     * Sets who handles the sensor-status requests this connection decodes (null: they are dropped).
     * Any thread; the handler is called on the thread that decodes the request (see the class
     * comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setSensorRequestHandler(RsSensorRequestHandler h) {
        sensorHandler = h;
    }

    /**
     * Sets who handles the target-selection requests this connection decodes (null: they are
     * dropped). Any thread; the handler is called on the thread that decodes the request (see the
     * class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setTargetSelectionRequestHandler(RsTargetSelectionRequestHandler h) {
        targetSelectionHandler = h;
    }

    /**
     * Sets who handles the painter-change requests this connection decodes (null: they are
     * dropped). Any thread; the handler is called on the thread that decodes the request (see the
     * class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setPainterChangeRequestHandler(RsPainterChangeRequestHandler h) {
        painterChangeHandler = h;
    }

    /**
     * Sets who handles the actuator-control requests this connection decodes (null: they are
     * dropped). Any thread; the handler is called on the thread that decodes the request (see the
     * class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setActuatorControlRequestHandler(RsActuatorControlRequestHandler h) {
        actuatorControlHandler = h;
    }

    /**
     * Sets who handles the encoder-status requests this connection decodes (null: they are
     * dropped). Any thread; the handler is called on the thread that decodes the request (see the
     * class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setEncoderStatusRequestHandler(RsEncoderStatusRequestHandler h) {
        encoderStatusHandler = h;
    }

    /**
     * Sets who receives the body specification the client sends (null: it is dropped). Any thread.
     *
     * @param h the handler, or null
     */
    public synchronized void setBodyHandler(RsConnectionBodyHandler h) {
        bodyHandler = h;
    }

    /**
     * Sets who handles the plan requests this connection decodes (null: they are dropped). Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setPlanRequestHandler(RsPlanRequestHandler h) {
        planHandler = h;
    }

    /**
     * Sets who handles the heartbeat requests this connection decodes (null: they are dropped). Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setHeartbeatRequestHandler(RsHeartbeatRequestHandler h) {
        heartbeatHandler = h;
    }

    /** Records a subscription; event codes outside 0..13 and negative indices are ignored. */
    public void setSubscriptionTableEntry(int row, int column, boolean value) {
        if (row < 0 || row > RsEvent.EVT_MAX_CODE || column < 0) {
            return;
        }
        synchronized (subscriptions) {
            if (value) {
                subscriptions.add(key(row, column));
            } else {
                subscriptions.remove(key(row, column));
            }
        }
    }

    /** Whether the client subscribed to event code {@code row} for index {@code column}. */
    public boolean isClientSubscribedToEvent(int row, int column) {
        synchronized (subscriptions) {
            return subscriptions.contains(key(row, column));
        }
    }

    private static long key(int row, int column) {
        return ((long) row << 32) | (column & 0xFFFFFFFFL);
    }

    /** Hands decoded requests to the registered handlers; requests without a handler are dropped. */
    private final class Dispatcher implements RequestSink {
        @Override
        public void timeout(double duration, int timeoutIndex) {
            RsTimeoutRequestHandler h = timeoutHandler;
            if (h != null) {
                h.process(duration, timeoutIndex);
            }
        }

        /** Timeout, position and placement events are always delivered, so their subscriptions are ignored. */
        @Override
        public void subscription(RsSubscriptionRequest r) {
            int code = r.eventCode;
            if (code != RsEvent.EVT_TIMEOUT && code != RsEvent.EVT_POSITION && code != RsEvent.EVT_PLACEMENT) {
                setSubscriptionTableEntry(code, r.eventIndex, r.eventEnable);
            }
            RsSubscriptionRequestHandler h = subscriptionHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void sensorStatus(RsSensorRequest r) {
            RsSensorRequestHandler h = sensorHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void motion(RsMotionRequest r) {
            RsMotionRequestHandler h = motionHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void halt(RsHaltRequest r) {
            RsHaltRequestHandler h = haltHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void position() {
            RsPositionRequestHandler h = positionHandler;
            if (h != null) {
                h.process();
            }
        }

        @Override
        public void setPosition() {
            verbose("RsConnection: ignoring reserved SetPosition request");
        }

        @Override
        public void placement(RsPlacementRequest r) {
            RsPlacementRequestHandler h = placementHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void targetSelection(RsTargetSelectionRequest r) {
            RsTargetSelectionRequestHandler h = targetSelectionHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void plan(RsPlanRequest r) {
            RsPlanRequestHandler h = planHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void heartbeat(RsHeartbeatRequest r) {
            RsHeartbeatRequestHandler h = heartbeatHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void painterChange(RsPainterChangeRequest r) {
            RsPainterChangeRequestHandler h = painterChangeHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void actuatorControl(RsActuatorControlRequest r) {
            RsActuatorControlRequestHandler h = actuatorControlHandler;
            if (h != null) {
                h.process(r);
            }
        }

        @Override
        public void encoderStatus(RsEncoderStatusRequest r) {
            RsEncoderStatusRequestHandler h = encoderStatusHandler;
            if (h != null) {
                h.process(r);
            }
        }
    }
}
