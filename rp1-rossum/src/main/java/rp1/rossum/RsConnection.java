package rp1.rossum;

import java.io.EOFException;
import java.io.IOException;
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
import rp1.rossum.request.RsActuatorControlRequestHandler;
import rp1.rossum.request.RsEncoderStatusRequestHandler;
import rp1.rossum.request.RsHaltRequestHandler;
import rp1.rossum.request.RsHeartbeatRequestHandler;
import rp1.rossum.request.RsMotionRequestHandler;
import rp1.rossum.request.RsPainterChangeRequestHandler;
import rp1.rossum.request.RsPlacementRequestHandler;
import rp1.rossum.request.RsPlanRequestHandler;
import rp1.rossum.request.RsPositionRequestHandler;
import rp1.rossum.request.RsSensorRequestHandler;
import rp1.rossum.request.RsSubscriptionRequestHandler;
import rp1.rossum.request.RsTargetSelectionRequestHandler;
import rp1.rossum.request.RsTimeoutRequestHandler;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.RequestListener;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;

/**
 * The server's end of one client session. The client's body specification and requests go to one
 * {@link RequestListener} ({@link #setRequestListener}, beyond RP1 0.60), or, while none is set, to
 * RP1 0.60's per-type handlers ({@code set...Handler}); interlock acknowledgements close the
 * interlock; the {@code send...Event} methods send events to the client. A session runs in one of
 * three modes:
 * <ul>
 * <li>reading a stream: {@link #run()} reads messages until the client leaves, handlers running on
 * that thread (RP1 0.60's only mode);
 * <li>feed mode, beyond RP1 0.60: a non-blocking reader hands over bytes with {@link #receive} and
 * reports their end with {@link #endOfInput()}, handlers running on the thread that hands them over
 * (the framing is {@code FeedDecoder}'s);
 * <li>direct mode, beyond RP1 0.60 ({@link #connectDirect}): a client in the same process without
 * streams, its requests handled on the thread that sends them and events handed to its handlers on
 * the thread that sends them.
 * </ul>
 *
 * <p>RP1 0.60's subscription table ({@link #isClientSubscribedToEvent}) is kept for 0.60 servers: it
 * is filled from subscription requests only while no listener is set. The {@code send...Event} methods
 * do not consult it, and this simulator does not use it (it keeps its own subscriptions).
 */
public class RsConnection extends RsProtocol implements Runnable {
    /** Bodies received in this session (handed over by one thread at a time: the decoder or the direct client). */
    private int bodiesReceived;
    /** Keeps interlock numbers in increasing order on this connection's stream. */
    private final Object eventLock = new Object();
    /** RP1 0.60's per-type handlers and subscription table, used while no listener is set. */
    private final ConnectionHandlers handlers = new ConnectionHandlers(this);
    private final FeedDecoder feed = new FeedDecoder(new FeedDecoder.Messages() {
        @Override
        public void read(WireIn in) throws IOException {
            readMessage(in);
        }

        @Override
        public boolean introduced() {
            return introduced;
        }
    });
    private volatile RequestListener listener;
    private volatile boolean introduced;
    private volatile DirectLink direct;
    private RsInterlock interlock;
    private volatile int maxInterlockSent;

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
                RequestCodec.decode(in, requests());
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
     * A body specification for the listener (or the body handler): decoded here, or a decoded copy
     * from a direct link. It is numbered as the client numbered it: the n-th body of this session.
     */
    void bodyReceived(RsBody body) {
        body.assignID(++bodiesReceived);
        verbose("Received body specification with name " + body.getName());
        requests().body(body);
    }

    /** Where the client's requests and body go now: the listener, or while there is none the 0.60 handlers. */
    RequestListener requests() {
        RequestListener l = listener;
        return l != null ? l : handlers;
    }

    /**
     * Beyond RP1 0.60: hands every request and the body this connection receives to {@code l}, one
     * typed call each, instead of to the per-type handlers (which, with the subscription table, are
     * then left alone). Any thread; {@code l} is called on the thread that decodes the message (see
     * the class comment). Null goes back to the per-type handlers.
     *
     * @param l the listener, or null
     */
    public void setRequestListener(RequestListener l) {
        listener = l;
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
        feed.receive(bytes, offset, length);
    }

    /**
     * Beyond RP1 0.60: the bytes of a message that has begun to arrive but is not yet complete (0
     * between messages), for a server that budgets what each client may make it hold.
     */
    public int getIncompleteMessageBytes() {
        return feed.incompleteBytes();
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
            problem = feed.end();
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
     * streams. The client's requests come to this connection's request listener (or handlers) as
     * objects (equal to what decoding them from the wire would give), on the thread that sends them;
     * its body arrives as a decoded copy, as from the wire; and each event sent here is handed to the
     * client's handlers at once, on the sending thread, as a copy of what the client would decode.
     * There is no handshake and no interlock: the handlers returning is the acknowledgement. If a
     * handler throws an {@code Error}, the session ends and {@code onFailure} is told. Closing either
     * side closes both.
     */
    public void connectDirect(RsClient client, Consumer<Throwable> onFailure) {
        DirectLink link = new DirectLink(this, client, onFailure);
        direct = link;
        client.attach(link);
        setClosingAction(link::shutdownClient);
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
     * Sets who handles the timeout requests this connection decodes (null: they are dropped) while no {@link #setRequestListener request listener} is set. Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setTimeoutRequestHandler(RsTimeoutRequestHandler h) {
        handlers.timeout = h;
    }

    /**
     * Sets who handles the subscription requests this connection decodes (null: they are dropped) while no {@link #setRequestListener request listener} is set.
     * Any thread; the handler is called on the thread that decodes the request (see the class
     * comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setSubscriptionRequestHandler(RsSubscriptionRequestHandler h) {
        handlers.subscription = h;
    }

    /**
     * Sets who handles the motion requests this connection decodes (null: they are dropped) while no {@link #setRequestListener request listener} is set. Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setMotionRequestHandler(RsMotionRequestHandler h) {
        handlers.motion = h;
    }

    /**
     * Sets who handles the position requests this connection decodes (null: they are dropped) while no {@link #setRequestListener request listener} is set. Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setPositionRequestHandler(RsPositionRequestHandler h) {
        handlers.position = h;
    }

    /**
     * Sets who handles the placement requests this connection decodes (null: they are dropped) while no {@link #setRequestListener request listener} is set. Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setPlacementRequestHandler(RsPlacementRequestHandler h) {
        handlers.placement = h;
    }

    /**
     * Sets who handles the halt requests this connection decodes (null: they are dropped) while no {@link #setRequestListener request listener} is set. Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setHaltRequestHandler(RsHaltRequestHandler h) {
        handlers.halt = h;
    }

    /**
     * Sets who handles the sensor-status requests this connection decodes (null: they are dropped) while no {@link #setRequestListener request listener} is set.
     * Any thread; the handler is called on the thread that decodes the request (see the class
     * comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setSensorRequestHandler(RsSensorRequestHandler h) {
        handlers.sensor = h;
    }

    /**
     * Sets who handles the target-selection requests this connection decodes (null: they are
     * dropped). Any thread; the handler is called on the thread that decodes the request (see the
     * class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setTargetSelectionRequestHandler(RsTargetSelectionRequestHandler h) {
        handlers.targetSelection = h;
    }

    /**
     * Sets who handles the painter-change requests this connection decodes (null: they are
     * dropped). Any thread; the handler is called on the thread that decodes the request (see the
     * class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setPainterChangeRequestHandler(RsPainterChangeRequestHandler h) {
        handlers.painterChange = h;
    }

    /**
     * Sets who handles the actuator-control requests this connection decodes (null: they are
     * dropped). Any thread; the handler is called on the thread that decodes the request (see the
     * class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setActuatorControlRequestHandler(RsActuatorControlRequestHandler h) {
        handlers.actuatorControl = h;
    }

    /**
     * Sets who handles the encoder-status requests this connection decodes (null: they are
     * dropped). Any thread; the handler is called on the thread that decodes the request (see the
     * class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setEncoderStatusRequestHandler(RsEncoderStatusRequestHandler h) {
        handlers.encoderStatus = h;
    }

    /**
     * Sets who receives the body specification the client sends (null: it is dropped). Any thread.
     *
     * @param h the handler, or null
     */
    public synchronized void setBodyHandler(RsConnectionBodyHandler h) {
        handlers.body = h;
    }

    /**
     * Sets who handles the plan requests this connection decodes (null: they are dropped) while no {@link #setRequestListener request listener} is set. Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setPlanRequestHandler(RsPlanRequestHandler h) {
        handlers.plan = h;
    }

    /**
     * Sets who handles the heartbeat requests this connection decodes (null: they are dropped) while no {@link #setRequestListener request listener} is set. Any
     * thread; the handler is called on the thread that decodes the request (see the class comment).
     *
     * @param h the handler, or null
     */
    public synchronized void setHeartbeatRequestHandler(RsHeartbeatRequestHandler h) {
        handlers.heartbeat = h;
    }

    /**
     * RP1 0.60's subscription table: records a subscription; event codes outside 0..13 and negative
     * indices are ignored. A connection fills it from subscription requests only while no request
     * listener is set; nothing in this library reads it.
     */
    public void setSubscriptionTableEntry(int row, int column, boolean value) {
        handlers.setSubscription(row, column, value);
    }

    /**
     * RP1 0.60's subscription table: whether the client subscribed to event code {@code row} for index
     * {@code column} (see {@link #setSubscriptionTableEntry}).
     */
    public boolean isClientSubscribedToEvent(int row, int column) {
        return handlers.isSubscribed(row, column);
    }
}
