package rp1.rossum;

import java.io.EOFException;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsContactSensorEventHandler;
import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.event.RsEncoderStatusEventHandler;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsEventHandler;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsHeartbeatEventHandler;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionHaltedEventHandler;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsMotionStartedEventHandler;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsMouseClickEventHandler;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1.rossum.event.RsPaintSensorEventHandler;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlacementEventHandler;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsPlanEventHandler;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsPositionEventHandler;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsRangeSensorEventHandler;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.event.RsTargetSelectionEventHandler;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.event.RsTargetSensorEventHandler;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.event.RsTimeoutEventHandler;
import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsEncoderStatusRequest;
import rp1.rossum.request.RsHaltRequest;
import rp1.rossum.request.RsHeartbeatRequest;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlanRequest;
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.RequestListener;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;

/**
 * A robot client's session with the simulator: the "brain" side of RP1. Extend it (or hold one),
 * call {@link #initialize()} to connect, send the robot's body with {@link #sendBodySpecification},
 * register event handlers, send requests, and call {@link #run()} to enter the event loop, which
 * returns when the session ends.
 *
 * <p>Handlers run in registration order per event, until one calls {@code event.consume()}. Over a
 * connection they run on the thread executing {@code run()}; when the server runs with the
 * interlock enabled, the acknowledgement of an event is sent after its last handler has returned,
 * so the simulation clock stands still while the handlers work. A client connected directly to a
 * server in the same process ({@link RsConnection#connectDirect}) has no event loop: its handlers run
 * on the server's thread that sends each event, which waits for them.
 *
 * <p>Handlers are added and removed from any thread, a running handler included (dispatch works on
 * a copy, so the change applies from the next event). Seven kinds of event are sent only to a client
 * that subscribed to them: mouse clicks, motion started, motion halted and each sensor's state
 * changes. The first {@code add...} handler of such a kind (for a sensor: of that sensor) subscribes,
 * every {@code remove...} unsubscribes; a handler added before the client is connected (for a client
 * that connects itself: before {@link #initialize()}) never subscribes (docs/protocol.md section 10).
 * Handlers of the other kinds receive the answers to this client's requests and need no subscription.
 *
 * <p>The {@code send...} methods may be called from any thread, handlers included; each sends one
 * whole message. Before the client is connected they throw {@link IllegalStateException}; after the
 * session has ended they do nothing but write a verbose log line. They hold this object's monitor
 * while writing, so while a server is not reading, a sender waits and so do the other senders.
 */
public class RsClient extends RsProtocol implements RsRunnable, RsLogInterface {
    /** The configuration {@link #initialize()} uses; created there if still null. */
    public RsProperties rsProperties;

    private final HandlerRegistry registry = new HandlerRegistry();
    private final RequestListener wire = new WireRequests();
    private volatile DirectLink link;
    /** Written by the event loop without taking this object's monitor, which senders may hold. */
    private volatile double simTime;
    private int timeoutIndex;
    /** Bodies sent so far; guarded by this client's monitor, as {@link #sendBodySpecification} is. */
    private int bodiesSent;
    private int encoderRequestIndex;
    /** The run this client is part of: set by a server that loads it, else read from the environment. */
    private volatile RsRunContext runContext;

    /**
     * A client not yet connected: {@link #initialize()} connects it, unless a server that loads it
     * in-process gives it its streams or a direct link first.
     */
    public RsClient() {
    }

    /**
     * Prepares the session: loads properties if none were given (the library defaults, then
     * {@code rossum.ini} from the working directory or else from next to this object's class), creates
     * a logger unless one was set, and connects to the server unless streams were supplied or the
     * client is connected directly (in-process clients get their streams, or their direct link, from
     * the server).
     *
     * @throws IOException if the server cannot be reached or the handshake fails
     */
    @Override
    public void initialize() throws IOException {
        List<String> notices = new ArrayList<>();
        if (rsProperties == null) {
            rsProperties = loadClientProperties(notices);
        }
        if (!isLoggerSet()) {
            initiateLogger(rsProperties);
        }
        notices.forEach(this::report);
        if (!isInputSet() && link == null) {
            initiateConnection(rsProperties);
        }
    }

    /** Uses {@code properties} instead of reading {@code rossum.ini}, then {@link #initialize()}. */
    public void initialize(RsProperties properties) throws IOException {
        rsProperties = properties;
        initialize();
    }

    /**
     * The library defaults, then {@code rossum.ini} from the working directory or, if there is none,
     * from next to this object's class. Having neither is normal (the defaults serve); a file that
     * exists but is invalid leaves the defaults. What happened is added to {@code notices}, for the
     * log that the properties are about to configure.
     */
    private RsProperties loadClientProperties(List<String> notices) {
        RsProperties p = new RsProperties();
        try {
            if (Files.isRegularFile(Paths.get(RsProperties.FILE_NAME))) {
                p.loadFromFile(RsProperties.FILE_NAME);
                notices.add("RsClient properties loaded from local file " + RsProperties.FILE_NAME);
            } else if (getClass().getResource(RsProperties.FILE_NAME) != null) {
                p.loadFromResource(this, RsProperties.FILE_NAME);
            }
        } catch (RsPropertiesException e) {
            notices.add("RsClient: " + e.getMessage() + "; using defaults");
        }
        return p;
    }

    /** Creates the logger the properties ask for (none if neither file nor standard output is wanted). */
    public synchronized void initiateLogger(RsProperties p) throws IOException {
        if (!p.logToFile && !p.logToSystemOut) {
            setLogger(null);
            return;
        }
        if (p.logToFile) {
            RsLogger.open(p.logFileName).close();
        }
        RsLogger l = new RsLogger(p.logToFile ? p.logFileName : null, p.logToSystemOut);
        l.setVerbosity(p.logVerbose);
        setLogger(l);
    }

    /** Opens a socket to {@code p.hostName:p.port} and performs the CONNECT/ACCEPT handshake. */
    public synchronized void initiateConnection(RsProperties p) throws IOException {
        Socket s = new Socket();
        try {
            s.connect(new InetSocketAddress(p.hostName, p.port));
            setSocket(s);
            exchangeIntroductions();
        } catch (IOException e) {
            s.close();
            String why = e instanceof ConnectException ? "is it running? start one with rp1" : e.getMessage();
            throw new IOException("cannot connect to the RP1 server at " + p.hostName + ":" + p.port + ": " + why, e);
        }
        log("Connected to RP1 server at " + p.hostName + ":" + p.port);
    }

    /**
     * The properties {@link #initialize()} uses ({@link #rsProperties}): null before it unless they
     * were set.
     *
     * @return the properties, or null
     */
    public RsProperties getProperties() {
        return rsProperties;
    }

    /**
     * Tells this client about the run it is part of. A server that loads the client calls this before
     * {@code initialize()}; a client of one's own need not.
     *
     * @param context the run's parameters, seed and results
     */
    public void setRunContext(RsRunContext context) {
        runContext = Objects.requireNonNull(context, "context");
    }

    /**
     * The value of the run's parameter {@code name}: {@code param.NAME} in the properties of the
     * server that loaded this client, or, for a client a sweep started with {@code --client}, the
     * environment variable {@code RP1_PARAM_NAME} (docs/guide.md, "Experiments"). Any time, even
     * before {@code initialize()}.
     *
     * @param name the parameter's name, without {@code param.}
     * @return its value as written (its first word), or null if there is none, as for a client that
     *         connected over the network by itself
     */
    public String getRunParameter(String name) {
        Objects.requireNonNull(name, "name");
        return runContext().getParameter(name);
    }

    /**
     * The run's seed, so that a robot's own randomness is reproducible: the seed of the server that
     * loaded this client ({@code randomSeed}, or the one it chose), or {@code RP1_SEED} for a client a
     * sweep started with {@code --client}.
     *
     * @return the seed, or 0 for a client that connected over the network by itself
     */
    public long getRunSeed() {
        return runContext().getSeed();
    }

    /**
     * Reports a result of this robot's own, such as whether it reached its goal; in a sweep it
     * becomes the column {@code result.NAME} of {@code results.csv}, and the last value reported for
     * a name wins. A client that connected over the network by itself reports to nobody.
     *
     * @param name  letters, digits, {@code _}, {@code .} and {@code -}
     * @param value a finite number
     * @throws IllegalArgumentException naming the argument if the name or the value is not one
     */
    public void reportRunResult(String name, double value) {
        if (name == null || !name.matches("[A-Za-z0-9_.-]+")) {
            throw new IllegalArgumentException("reportRunResult: name must be letters, digits, _, . or -, got "
                    + (name == null ? "null" : "\"" + name + "\""));
        }
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException("reportRunResult: value of " + name + " must be finite, got " + value);
        }
        runContext().reportResult(name, value);
    }

    private RsRunContext runContext() {
        RsRunContext c = runContext;
        if (c == null) {
            c = RsRunContext.fromEnvironment(System.getenv());
            runContext = c;
        }
        return c;
    }

    /**
     * The handshake: CONNECT (client id and key 0, sequence 0), then ACCEPT, whose client id and key
     * this client adopts.
     */
    protected void exchangeIntroductions() throws IOException {
        clientID = 0;
        clientKey = 0;
        sendWithCurrentSequence(CONNECT);
        WireIn in = wire();
        int version = in.firstI32("ACCEPT version");
        if (version != VERSION) {
            throw new RsProtocolException("ACCEPT version", "expected " + VERSION + ", got " + version);
        }
        int id = in.i32("ACCEPT client id");
        int key = in.i32("ACCEPT client key");
        serverSequence = in.i32("ACCEPT sequence");
        int code = in.i32("ACCEPT transaction code");
        if (code != ACCEPT) {
            throw new RsProtocolException("ACCEPT transaction code", "expected ACCEPT (2), got " + describeTransaction(code));
        }
        clientID = id;
        clientKey = key;
    }

    // ----------------------------------------------------------------------------------------------
    // Handler registration. The seven simulation-generated event types are subscribed when their
    // first handler for a key is added and unsubscribed on every removal, as RP1 0.60 does.

    /**
     * Adds {@code h} for mouse-click events (docs/protocol.md section 7.2), called after the
     * handlers added before it. The first handler subscribes to these events (protocol.md section
     * 10). Before the client is connected (for a client that connects itself: before {@link
     * #initialize()}) the subscription is skipped and, the handler being stored, never sent later,
     * so none of these events arrives. Any thread, a handler included (the change applies from the
     * next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addMouseClickEventHandler(RsMouseClickEventHandler h) {
        addSubscribed(RsEvent.EVT_MOUSE_CLICK, 0, h);
    }

    /**
     * Removes every mouse-click handler and unsubscribes (docs/protocol.md section 10); the next
     * add subscribes again. Any thread, a handler included (the change applies from the next
     * event).
     */
    public synchronized void removeMouseClickEventHandler() {
        removeSubscribed(RsEvent.EVT_MOUSE_CLICK, 0, null);
    }

    /**
     * Removes every registration of {@code h} as a mouse-click handler and unsubscribes, as RP1
     * 0.60 did, even if other handlers remain: those receive none of these events until every
     * handler has been removed and one is added again (docs/protocol.md section 10). Any thread, a
     * handler included (the change applies from the next event).
     *
     * @param h the handler to remove
     */
    public synchronized void removeMouseClickEventHandler(RsMouseClickEventHandler h) {
        removeSubscribed(RsEvent.EVT_MOUSE_CLICK, 0, h);
    }

    /**
     * Adds {@code h} for motion-started events (docs/protocol.md section 7.7), called after the
     * handlers added before it. The first handler subscribes to these events (protocol.md section
     * 10). Before the client is connected (for a client that connects itself: before {@link
     * #initialize()}) the subscription is skipped and, the handler being stored, never sent later,
     * so none of these events arrives. Any thread, a handler included (the change applies from the
     * next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addMotionStartedEventHandler(RsMotionStartedEventHandler h) {
        addSubscribed(RsEvent.EVT_MOTION_STARTED, 0, h);
    }

    /**
     * Removes every motion-started handler and unsubscribes (docs/protocol.md section 10); the next
     * add subscribes again. Any thread, a handler included (the change applies from the next
     * event).
     */
    public synchronized void removeMotionStartedEventHandler() {
        removeSubscribed(RsEvent.EVT_MOTION_STARTED, 0, null);
    }

    /**
     * Removes every registration of {@code h} as a motion-started handler and unsubscribes, as RP1
     * 0.60 did, even if other handlers remain: those receive none of these events until every
     * handler has been removed and one is added again (docs/protocol.md section 10). Any thread, a
     * handler included (the change applies from the next event).
     *
     * @param h the handler to remove
     */
    public synchronized void removeMotionStartedEventHandler(RsMotionStartedEventHandler h) {
        removeSubscribed(RsEvent.EVT_MOTION_STARTED, 0, h);
    }

    /**
     * Adds {@code h} for motion-halted events (docs/protocol.md section 7.8), called after the
     * handlers added before it. The first handler subscribes to these events (protocol.md section
     * 10). Before the client is connected (for a client that connects itself: before {@link
     * #initialize()}) the subscription is skipped and, the handler being stored, never sent later,
     * so none of these events arrives. Any thread, a handler included (the change applies from the
     * next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addMotionHaltedEventHandler(RsMotionHaltedEventHandler h) {
        addSubscribed(RsEvent.EVT_MOTION_HALTED, 0, h);
    }

    /**
     * Removes every motion-halted handler and unsubscribes (docs/protocol.md section 10); the next
     * add subscribes again. Any thread, a handler included (the change applies from the next
     * event).
     */
    public synchronized void removeMotionHaltedEventHandler() {
        removeSubscribed(RsEvent.EVT_MOTION_HALTED, 0, null);
    }

    /**
     * Removes {@code h} from the motion-halted handlers. The parameter type is the original API's
     * (a motion-started handler type); it matters only for a class implementing both interfaces.
     */
    public synchronized void removeMotionHaltedEventHandler(RsMotionStartedEventHandler h) {
        removeSubscribed(RsEvent.EVT_MOTION_HALTED, 0, h);
    }

    /**
     * Adds {@code h} for the state changes of sensor {@code s}: target-sensor events
     * (docs/protocol.md section 7.5), called after the handlers added before it. The first handler
     * for this sensor subscribes to its changes (protocol.md section 10). Before the client is
     * connected (for a client that connects itself: before {@link #initialize()}) the subscription
     * is skipped and, the handler being stored, never sent later: then only the answers to {@link
     * #sendSensorStatusRequest} reach it. Any thread, a handler included (the change applies from
     * the next event).
     *
     * @param s the sensor, a part of the body sent
     * @param h the handler
     * @throws NullPointerException if {@code s} or {@code h} is null
     */
    public synchronized void addTargetSensorEventHandler(RsBodyTargetSensor s, RsTargetSensorEventHandler h) {
        addSubscribed(RsEvent.EVT_TARGET_SENSOR, sensorId(s), h);
    }

    /**
     * Removes every target-sensor handler of sensor {@code s} and unsubscribes from its changes
     * (docs/protocol.md section 10); the next add subscribes again. Any thread, a handler included
     * (the change applies from the next event).
     *
     * @param s the sensor
     */
    public synchronized void removeTargetSensorEventHandler(RsBodyTargetSensor s) {
        removeSubscribed(RsEvent.EVT_TARGET_SENSOR, sensorId(s), null);
    }

    /**
     * Removes every registration of {@code h} as a target-sensor handler of sensor {@code s} and
     * unsubscribes, as RP1 0.60 did, even if other handlers remain: those receive none of these
     * events until every handler has been removed and one is added again (docs/protocol.md section
     * 10). Any thread, a handler included (the change applies from the next event).
     *
     * @param s the sensor
     * @param h the handler to remove
     */
    public synchronized void removeTargetSensorEventHandler(RsBodyTargetSensor s, RsTargetSensorEventHandler h) {
        removeSubscribed(RsEvent.EVT_TARGET_SENSOR, sensorId(s), h);
    }

    /**
     * Adds {@code h} for the state changes of sensor {@code s}: contact-sensor events
     * (docs/protocol.md section 7.1), called after the handlers added before it. The first handler
     * for this sensor subscribes to its changes (protocol.md section 10). Before the client is
     * connected (for a client that connects itself: before {@link #initialize()}) the subscription
     * is skipped and, the handler being stored, never sent later: then only the answers to {@link
     * #sendSensorStatusRequest} reach it. Any thread, a handler included (the change applies from
     * the next event).
     *
     * @param s the sensor, a part of the body sent
     * @param h the handler
     * @throws NullPointerException if {@code s} or {@code h} is null
     */
    public synchronized void addContactSensorEventHandler(RsBodyContactSensor s, RsContactSensorEventHandler h) {
        addSubscribed(RsEvent.EVT_CONTACT_SENSOR, sensorId(s), h);
    }

    /**
     * Removes every contact-sensor handler of sensor {@code s} and unsubscribes from its changes
     * (docs/protocol.md section 10); the next add subscribes again. Any thread, a handler included
     * (the change applies from the next event).
     *
     * @param s the sensor
     */
    public synchronized void removeContactSensorEventHandler(RsBodyContactSensor s) {
        removeSubscribed(RsEvent.EVT_CONTACT_SENSOR, sensorId(s), null);
    }

    /**
     * Removes every registration of {@code h} as a contact-sensor handler of sensor {@code s} and
     * unsubscribes, as RP1 0.60 did, even if other handlers remain: those receive none of these
     * events until every handler has been removed and one is added again (docs/protocol.md section
     * 10). Any thread, a handler included (the change applies from the next event).
     *
     * @param s the sensor
     * @param h the handler to remove
     */
    public synchronized void removeContactSensorEventHandler(RsBodyContactSensor s, RsContactSensorEventHandler h) {
        removeSubscribed(RsEvent.EVT_CONTACT_SENSOR, sensorId(s), h);
    }

    /**
     * Adds {@code h} for the state changes of sensor {@code s}: range-sensor events
     * (docs/protocol.md section 7.4), called after the handlers added before it. The first handler
     * for this sensor subscribes to its changes (protocol.md section 10). Before the client is
     * connected (for a client that connects itself: before {@link #initialize()}) the subscription
     * is skipped and, the handler being stored, never sent later: then only the answers to {@link
     * #sendSensorStatusRequest} reach it. Any thread, a handler included (the change applies from
     * the next event).
     *
     * @param s the sensor, a part of the body sent
     * @param h the handler
     * @throws NullPointerException if {@code s} or {@code h} is null
     */
    public synchronized void addRangeSensorEventHandler(RsBodyRangeSensor s, RsRangeSensorEventHandler h) {
        addSubscribed(RsEvent.EVT_RANGE_SENSOR, sensorId(s), h);
    }

    /**
     * Removes every range-sensor handler of sensor {@code s} and unsubscribes from its changes
     * (docs/protocol.md section 10); the next add subscribes again. Any thread, a handler included
     * (the change applies from the next event).
     *
     * @param s the sensor
     */
    public synchronized void removeRangeSensorEventHandler(RsBodyRangeSensor s) {
        removeSubscribed(RsEvent.EVT_RANGE_SENSOR, sensorId(s), null);
    }

    /**
     * Removes every registration of {@code h} as a range-sensor handler of sensor {@code s} and
     * unsubscribes, as RP1 0.60 did, even if other handlers remain: those receive none of these
     * events until every handler has been removed and one is added again (docs/protocol.md section
     * 10). Any thread, a handler included (the change applies from the next event).
     *
     * @param s the sensor
     * @param h the handler to remove
     */
    public synchronized void removeRangeSensorEventHandler(RsBodyRangeSensor s, RsRangeSensorEventHandler h) {
        removeSubscribed(RsEvent.EVT_RANGE_SENSOR, sensorId(s), h);
    }

    /**
     * Adds {@code h} for the state changes of sensor {@code s}: paint-sensor events
     * (docs/protocol.md section 7.12), called after the handlers added before it. The first handler
     * for this sensor subscribes to its changes (protocol.md section 10). Before the client is
     * connected (for a client that connects itself: before {@link #initialize()}) the subscription
     * is skipped and, the handler being stored, never sent later: then only the answers to {@link
     * #sendSensorStatusRequest} reach it. Any thread, a handler included (the change applies from
     * the next event).
     *
     * @param s the sensor, a part of the body sent
     * @param h the handler
     * @throws NullPointerException if {@code s} or {@code h} is null
     */
    public synchronized void addPaintSensorEventHandler(RsBodyPaintSensor s, RsPaintSensorEventHandler h) {
        addSubscribed(RsEvent.EVT_PAINT_SENSOR, sensorId(s), h);
    }

    /**
     * Removes every paint-sensor handler of sensor {@code s} and unsubscribes from its changes
     * (docs/protocol.md section 10); the next add subscribes again. Any thread, a handler included
     * (the change applies from the next event).
     *
     * @param s the sensor
     */
    public synchronized void removePaintSensorEventHandler(RsBodyPaintSensor s) {
        removeSubscribed(RsEvent.EVT_PAINT_SENSOR, sensorId(s), null);
    }

    /**
     * Removes every registration of {@code h} as a paint-sensor handler of sensor {@code s} and
     * unsubscribes, as RP1 0.60 did, even if other handlers remain: those receive none of these
     * events until every handler has been removed and one is added again (docs/protocol.md section
     * 10). Any thread, a handler included (the change applies from the next event).
     *
     * @param s the sensor
     * @param h the handler to remove
     */
    public synchronized void removePaintSensorEventHandler(RsBodyPaintSensor s, RsPaintSensorEventHandler h) {
        removeSubscribed(RsEvent.EVT_PAINT_SENSOR, sensorId(s), h);
    }

    /**
     * Adds {@code h} for timeout events (the answers to {@link #sendTimeoutRequest};
     * docs/protocol.md section 7.6), called after the handlers added before it. These events answer
     * requests and need no subscription: adding or removing handlers sends nothing. Any thread, a
     * handler included (the change applies from the next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addTimeoutEventHandler(RsTimeoutEventHandler h) {
        addLocal(RsEvent.EVT_TIMEOUT, h);
    }

    /**
     * Removes every timeout handler. Sends nothing. Any thread, a handler included.
     */
    public synchronized void removeTimeoutEventHandler() {
        removeLocal(RsEvent.EVT_TIMEOUT, null);
    }

    /**
     * Removes every registration of {@code h} as a timeout handler. Sends nothing. Any thread, a
     * handler included.
     *
     * @param h the handler to remove
     */
    public synchronized void removeTimeoutEventHandler(RsTimeoutEventHandler h) {
        removeLocal(RsEvent.EVT_TIMEOUT, h);
    }

    /**
     * Adds {@code h} for position events (the answers to {@link #sendPositionRequest};
     * docs/protocol.md section 7.3), called after the handlers added before it. These events answer
     * requests and need no subscription: adding or removing handlers sends nothing. Any thread, a
     * handler included (the change applies from the next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addPositionEventHandler(RsPositionEventHandler h) {
        addLocal(RsEvent.EVT_POSITION, h);
    }

    /**
     * Removes every position handler. Sends nothing. Any thread, a handler included.
     */
    public synchronized void removePositionEventHandler() {
        removeLocal(RsEvent.EVT_POSITION, null);
    }

    /**
     * Removes every registration of {@code h} as a position handler. Sends nothing. Any thread, a
     * handler included.
     *
     * @param h the handler to remove
     */
    public synchronized void removePositionEventHandler(RsPositionEventHandler h) {
        removeLocal(RsEvent.EVT_POSITION, h);
    }

    /**
     * Adds {@code h} for placement events (the answers to {@link #sendPlacementRequest};
     * docs/protocol.md section 7.9), called after the handlers added before it. These events answer
     * requests and need no subscription: adding or removing handlers sends nothing. Any thread, a
     * handler included (the change applies from the next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addPlacementEventHandler(RsPlacementEventHandler h) {
        addLocal(RsEvent.EVT_PLACEMENT, h);
    }

    /**
     * Removes every placement handler. Sends nothing. Any thread, a handler included.
     */
    public synchronized void removePlacementEventHandler() {
        removeLocal(RsEvent.EVT_PLACEMENT, null);
    }

    /**
     * Removes every registration of {@code h} as a placement handler. Sends nothing. Any thread, a
     * handler included.
     *
     * @param h the handler to remove
     */
    public synchronized void removePlacementEventHandler(RsPlacementEventHandler h) {
        removeLocal(RsEvent.EVT_PLACEMENT, h);
    }

    /**
     * Adds {@code h} for target-selection events (the answers to the target selection requests;
     * docs/protocol.md section 7.10), called after the handlers added before it. These events
     * answer requests and need no subscription: adding or removing handlers sends nothing. Any
     * thread, a handler included (the change applies from the next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addTargetSelectionEventHandler(RsTargetSelectionEventHandler h) {
        addLocal(RsEvent.EVT_TARGET_SELECTION, h);
    }

    /**
     * Removes every target-selection handler. Sends nothing. Any thread, a handler included.
     */
    public synchronized void removeTargetSelectionEventHandler() {
        removeLocal(RsEvent.EVT_TARGET_SELECTION, null);
    }

    /**
     * Removes every registration of {@code h} as a target-selection handler. Sends nothing. Any
     * thread, a handler included.
     *
     * @param h the handler to remove
     */
    public synchronized void removeTargetSelectionEventHandler(RsTargetSelectionEventHandler h) {
        removeLocal(RsEvent.EVT_TARGET_SELECTION, h);
    }

    /**
     * Adds {@code h} for plan events (the answers to {@link #sendPlanRequest}; docs/protocol.md
     * section 7.11), called after the handlers added before it. These events answer requests and
     * need no subscription: adding or removing handlers sends nothing. Any thread, a handler
     * included (the change applies from the next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addPlanEventHandler(RsPlanEventHandler h) {
        addLocal(RsEvent.EVT_PLAN, h);
    }

    /**
     * Removes every plan handler. Sends nothing. Any thread, a handler included.
     */
    public synchronized void removePlanEventHandler() {
        removeLocal(RsEvent.EVT_PLAN, null);
    }

    /**
     * Removes every registration of {@code h} as a plan handler. Sends nothing. Any thread, a
     * handler included.
     *
     * @param h the handler to remove
     */
    public synchronized void removePlanEventHandler(RsPlanEventHandler h) {
        removeLocal(RsEvent.EVT_PLAN, h);
    }

    /**
     * Adds {@code h} for heartbeat events (the beats {@link #sendHeartbeatRequest} asks for;
     * docs/protocol.md section 7.13), called after the handlers added before it. These events
     * answer requests and need no subscription: adding or removing handlers sends nothing. Any
     * thread, a handler included (the change applies from the next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addHeartbeatEventHandler(RsHeartbeatEventHandler h) {
        addLocal(RsEvent.EVT_HEARTBEAT, h);
    }

    /**
     * Removes every heartbeat handler. Sends nothing. Any thread, a handler included.
     */
    public synchronized void removeHeartbeatEventHandler() {
        removeLocal(RsEvent.EVT_HEARTBEAT, null);
    }

    /**
     * Removes every registration of {@code h} as a heartbeat handler. Sends nothing. Any thread, a
     * handler included.
     *
     * @param h the handler to remove
     */
    public synchronized void removeHeartbeatEventHandler(RsHeartbeatEventHandler h) {
        removeLocal(RsEvent.EVT_HEARTBEAT, h);
    }

    /**
     * Adds {@code h} for encoder-status events (the answers to {@code sendEncoderStatusRequest};
     * docs/protocol.md section 7.14), called after the handlers added before it. These events
     * answer requests and need no subscription: adding or removing handlers sends nothing. Any
     * thread, a handler included (the change applies from the next event).
     *
     * @param h the handler
     * @throws NullPointerException if {@code h} is null
     */
    public synchronized void addEncoderStatusEventHandler(RsEncoderStatusEventHandler h) {
        addLocal(RsEvent.EVT_ENCODER_STATUS, h);
    }

    /**
     * Removes every encoder-status handler. Sends nothing. Any thread, a handler included.
     */
    public synchronized void removeEncoderStatusEventHandler() {
        removeLocal(RsEvent.EVT_ENCODER_STATUS, null);
    }

    /**
     * Removes every registration of {@code h} as a encoder-status handler. Sends nothing. Any
     * thread, a handler included.
     *
     * @param h the handler to remove
     */
    public synchronized void removeEncoderStatusEventHandler(RsEncoderStatusEventHandler h) {
        removeLocal(RsEvent.EVT_ENCODER_STATUS, h);
    }

    private static int sensorId(RsBodySensor sensor) {
        return Objects.requireNonNull(sensor, "sensor").getID();
    }

    /** RP1 0.60 threw {@code Error} here; a null argument is a {@code NullPointerException} naming it (docs/differences.md). */
    private static void requireHandler(RsEventHandler h) {
        Objects.requireNonNull(h, "handler");
    }

    /** Events that need no subscription (answers to requests, always delivered): only the handler is stored. */
    private void addLocal(int code, RsEventHandler h) {
        requireHandler(h);
        registry.add(code, 0, h);
    }

    /** Removes {@code h}, or with {@code h == null} (the no-argument forms) every handler, of a local event. */
    private void removeLocal(int code, RsEventHandler h) {
        unregister(code, 0, h);
    }

    /**
     * The subscription goes out before the handler is stored and only for the first handler of a key;
     * before the connection exists it is skipped (and, a handler now existing, never sent later).
     */
    private void addSubscribed(int code, int index, RsEventHandler h) {
        requireHandler(h);
        if (!registry.has(code, index)) {
            sendSubscription(code, index, true);
        }
        registry.add(code, index, h);
    }

    /**
     * Unsubscribes on every removal, as RP1 0.60 does. {@code h == null} (the no-argument forms) removes
     * every handler of the key; 0.60 removed none, so the server stopped sending while the handlers
     * stayed and a later add never subscribed again (docs/differences.md).
     */
    private void removeSubscribed(int code, int index, RsEventHandler h) {
        sendSubscription(code, index, false);
        unregister(code, index, h);
    }

    /** Removes {@code h}, or with {@code h == null} every handler, of the key. */
    private void unregister(int code, int index, RsEventHandler h) {
        if (h == null) {
            registry.removeAll(code, index);
        } else {
            registry.remove(code, index, h);
        }
    }

    private void sendSubscription(int code, int index, boolean enable) {
        if (isConnected()) {
            requests().subscription(new RsSubscriptionRequest(code, index, enable));
        }
    }

    // ----------------------------------------------------------------------------------------------
    // Requests.

    /**
     * Asks for a timeout event after {@code duration} seconds of simulation time.
     *
     * @return the timeout's index (1, 2, 3, ... per client), echoed in the timeout event
     * @throws IllegalArgumentException if the duration is NaN or infinite (nothing is sent)
     */
    public synchronized int sendTimeoutRequest(double duration) {
        requireFinite("duration", duration);
        int index = ++timeoutIndex;
        requests().timeout(duration, index);
        return index;
    }

    /** Asks for the sensor's current state as a sensor event, whatever the subscriptions. */
    public synchronized void sendSensorStatusRequest(RsBodySensor sensor) {
        requests().sensorStatus(new RsSensorRequest(sensorId(sensor)));
    }

    /**
     * Asks the robot to move at the request's linear and rotational velocity for its duration
     * (docs/protocol.md section 6.4). It replaces any motion in progress, is ignored while the
     * robot is not placed, and is followed by motion-started and motion-halted events for the
     * handlers subscribed to them. Any thread; before the client is connected it throws {@link
     * IllegalStateException}, after the session ended it does nothing (see the class comment).
     *
     * @param r the motion
     * @throws NullPointerException if {@code r} is null
     * @throws IllegalArgumentException if a velocity or the duration is NaN or infinite (nothing is sent)
     */
    public synchronized void sendMotionRequest(RsMotionRequest r) {
        Objects.requireNonNull(r, "motion request");
        requireFinite("linearVelocity", r.linearVelocity);
        requireFinite("rotationalVelocity", r.rotationalVelocity);
        requireFinite("duration", r.duration);
        requests().motion(r);
    }

    /**
     * Asks where the robot is: a position event answers (docs/protocol.md section 6.6). Any thread;
     * before the client is connected it throws {@link IllegalStateException}, after the session
     * ended it does nothing (see the class comment).
     */
    public synchronized void sendPositionRequest() {
        requests().position();
    }

    /**
     * Asks to be placed at the named placement; null or "" for a random one of the plan's placements,
     * "$random" for a random free pose.
     */
    public synchronized void sendPlacementRequest(String name) {
        requests().placement(new RsPlacementRequest(name));
    }

    /**
     * Stops the motion in progress, if any (docs/protocol.md section 6.5, behavior.md section 5.4):
     * a moving robot stops at once and a motion-halted event (cause 1) follows for the handlers
     * subscribed to it; a robot at rest sends nothing. Any thread; before the client is connected it
     * throws {@link IllegalStateException}, after the session ended it does nothing (see the class
     * comment).
     */
    public synchronized void sendHaltRequest() {
        requests().halt(new RsHaltRequest());
    }

    /**
     * Selects ({@code status} true) or deselects the named target; only selected targets are seen
     * by target sensors. One target-selection event answers for each target the request touched
     * (docs/protocol.md section 6.9). Any thread; before the client is connected it throws {@link
     * IllegalStateException}, after the session ended it does nothing (see the class comment).
     *
     * @param targetName the target's name in the floor plan; {@code "*"} for every target
     * @param status whether it is to be selected
     */
    public synchronized void sendTargetSelectionRequest(String targetName, boolean status) {
        sendTargetSelection(false, targetName, status, false);
    }

    /**
     * Deselects every target, then selects the named one (docs/protocol.md section 6.9). Any
     * thread; before the client is connected it throws {@link IllegalStateException}, after the
     * session ended it does nothing (see the class comment).
     *
     * @param targetName the target's name in the floor plan
     */
    public synchronized void sendExclusiveTargetSelectionRequest(String targetName) {
        sendTargetSelection(false, targetName, true, true);
    }

    /**
     * Selects one target chosen at random from the simulation's random source (docs/protocol.md
     * section 6.9). RP1 0.60 selects it whatever {@code status} says, and so does this server. Any
     * thread; before the client is connected it throws {@link IllegalStateException}, after the
     * session ended it does nothing (see the class comment).
     *
     * @param status sent as given; the server selects the target either way
     */
    public synchronized void sendRandomTargetSelectionRequest(boolean status) {
        sendTargetSelection(true, null, status, false);
    }

    /**
     * Deselects every target, then selects one chosen at random (docs/protocol.md section 6.9). Any
     * thread; before the client is connected it throws {@link IllegalStateException}, after the
     * session ended it does nothing (see the class comment).
     */
    public synchronized void sendExclusiveRandomTargetSelectionRequest() {
        sendTargetSelection(true, null, true, true);
    }

    /**
     * Selects ({@code status} true) or deselects every target of the plan (docs/protocol.md section
     * 6.9). Any thread; before the client is connected it throws {@link IllegalStateException},
     * after the session ended it does nothing (see the class comment).
     *
     * @param status whether they are to be selected
     */
    public synchronized void sendAllTargetsSelectionRequest(boolean status) {
        sendTargetSelection(false, "*", status, false);
    }

    /**
     * Asks for the floor plan: a plan event answers (docs/protocol.md section 6.10). Any thread;
     * before the client is connected it throws {@link IllegalStateException}, after the session
     * ended it does nothing (see the class comment).
     */
    public synchronized void sendPlanRequest() {
        requests().plan(new RsPlanRequest());
    }

    /**
     * Asks for a heartbeat event every {@code period} seconds of simulation time (0 cancels; the server
     * raises a period below 1 ms to 1 ms).
     *
     * @throws IllegalArgumentException if the period is NaN or infinite (nothing is sent)
     */
    public synchronized void sendHeartbeatRequest(double period) {
        requireFinite("period", period);
        requests().heartbeat(new RsHeartbeatRequest(period));
    }

    /**
     * Cancels this client's heartbeat, if any (a heartbeat request with interval 0,
     * docs/protocol.md section 6.11). Any thread; before the client is connected it throws {@link
     * IllegalStateException}, after the session ended it does nothing (see the class comment).
     */
    public synchronized void sendHeartbeatCancellationRequest() {
        requests().heartbeat(new RsHeartbeatRequest(0.0));
    }

    /**
     * Starts the painter's trail. A painter without a colour, or whose trailer was never positioned or
     * sized, cannot paint: a deactivation is sent instead (RP1 0.60 sent a truncated message in the
     * second case, corrupting the stream).
     *
     * @throws IllegalArgumentException if the trailer's position or width is NaN or infinite (nothing is sent)
     */
    public synchronized void sendPainterActivationRequest(RsBodyPainter painter) {
        Objects.requireNonNull(painter, "painter");
        if (painter.getPaintColors() == null || !painter.isTrailerDefined()) {
            sendPainterDeactivationRequest(painter);
            return;
        }
        requireFinite("painter trailer x", painter.getTrailerX());
        requireFinite("painter trailer y", painter.getTrailerY());
        requireFinite("painter trailer width", painter.getTrailerWidth());
        painter.setPainterActivationStatus(true);
        requests().painterChange(new RsPainterChangeRequest(painter.getID(), false, true, true, painter.getTrailerX(),
                painter.getTrailerY(), painter.getTrailerWidth(), painter.getPaintColors()));
    }

    /**
     * Stops the painter's trail; the trail painted so far stays (docs/protocol.md section 6.12).
     * Any thread; before the client is connected it throws {@link IllegalStateException}, after the
     * session ended it does nothing (see the class comment).
     *
     * @param painter a painter of the body sent
     * @throws NullPointerException if {@code painter} is null
     */
    public synchronized void sendPainterDeactivationRequest(RsBodyPainter painter) {
        Objects.requireNonNull(painter, "painter").setPainterActivationStatus(false);
        requests().painterChange(new RsPainterChangeRequest(painter.getID(), false, false, false, 0.0, 0.0, 0.0, null));
    }

    /**
     * Erases the trail the painter has left (docs/protocol.md section 6.12). Any thread; before the
     * client is connected it throws {@link IllegalStateException}, after the session ended it does
     * nothing (see the class comment).
     *
     * @param painter a painter of the body sent
     * @throws NullPointerException if {@code painter} is null
     */
    public synchronized void sendPainterErasureRequest(RsBodyPainter painter) {
        requests().painterChange(new RsPainterChangeRequest(Objects.requireNonNull(painter, "painter").getID(), true, false,
                false, 0.0, 0.0, 0.0, null));
    }

    /**
     * Sends an actuator command. A command without parameters has nothing for the simulator to
     * apply: a parameterless HALT (what {@code getControlRequestForWheelRotation(0, 0)} returns) is
     * sent as a halt request, any other parameterless command is dropped with a log line. (RP1 0.60
     * left a partial message in the stream here.)
     *
     * @throws IllegalArgumentException if a parameter value is NaN or infinite (nothing is sent)
     */
    public synchronized void sendActuatorControlRequest(RsActuatorControlRequest r) {
        Objects.requireNonNull(r, "actuator control request");
        String[] names = r.getParameterNames();
        double[] values = r.getParameterValues();
        for (int i = 0; i < values.length; i++) {
            requireFinite("actuator parameter " + names[i], values[i]);
        }
        if (r.getParameterNames().length > 0) {
            requests().actuatorControl(r);
        } else if (r.commandID == RsActuatorControlRequest.HALT) {
            requests().halt(new RsHaltRequest());
        } else {
            log("RsClient: actuator command " + r.commandID + " without parameters not sent");
        }
    }

    /** Asks for the encoder's state; returns the request index, or -1 (nothing sent) if it is null. */
    public synchronized int sendEncoderStatusRequest(RsEncoder encoder, boolean clearOnRequest) {
        return sendEncoderStatusRequest(new RsEncoder[] {encoder}, clearOnRequest);
    }

    /**
     * Asks for the encoders' states, one event each in this order; returns the request index (1, 2,
     * ... per client), or -1 (nothing sent) if the array or any element is null.
     */
    public synchronized int sendEncoderStatusRequest(RsEncoder[] encoders, boolean clearOnRequest) {
        if (encoders == null) {
            return -1;
        }
        int[] ids = new int[encoders.length];
        for (int i = 0; i < encoders.length; i++) {
            if (encoders[i] == null) {
                return -1;
            }
            ids[i] = encoders[i].getID();
        }
        int index = ++encoderRequestIndex;
        requests().encoderStatus(new RsEncoderStatusRequest(index, ids, clearOnRequest));
        return index;
    }

    /**
     * Describes the robot to the simulator; send it once, before any request about the robot.
     *
     * @throws IllegalArgumentException if the body has no part that can be transmitted, or a dimension
     *         is NaN or infinite (the message names the part and field; nothing is sent)
     */
    public synchronized void sendBodySpecification(RsBody body) {
        Objects.requireNonNull(body, "body");
        WireOut payload = new WireOut();
        BodyCodec.encode(payload, body);
        // Decoding checks every number, and gives the copy the server would decode from the wire.
        RsBody decoded = BodyCodec.checked(payload);
        if (body.getID() == 0) {
            body.assignID(++bodiesSent);
        }
        DirectLink l = link;
        // After the session has ended, the wire path drops the body with a log line, as it drops requests.
        if (l != null && !isClosed()) {
            l.body(decoded);
            return;
        }
        sendMessage(BODY_SPECIFICATION, payload);
    }

    /** The server drops a client that sends NaN or an infinity (protocol.md section 14): refuse it here. */
    private static void requireFinite(String argument, double value) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException(argument + " must be a finite number, got " + value);
        }
    }

    private void sendTargetSelection(boolean random, String name, boolean status, boolean exclusive) {
        requests().targetSelection(new RsTargetSelectionRequest(random, name, status, exclusive));
    }

    /**
     * Where requests go: encoded onto the connection, or, for a client connected directly to a server
     * in the same process, to the server's dispatch. The request objects are the caller's or built for
     * the wire (a null name, an empty colour list); the direct link copies them into what the server
     * would decode, so both ends see the same thing either way.
     */
    private RequestListener requests() {
        DirectLink l = link;
        // After the session has ended, the wire path drops requests with a log line, whichever link it had.
        return l == null || isClosed() ? wire : l.requests();
    }

    /** Whether requests can be sent: the streams are set, or a direct link is. */
    private boolean isConnected() {
        return link != null || isOutputSet();
    }

    /** A direct link to a server in the same process ({@link RsConnection#connectDirect}). */
    void attach(DirectLink l) {
        link = l;
        setClosingAction(l::shutdownServer);
    }

    /** An event from a direct link: dispatched on the calling thread, as {@link #run()} would dispatch it. */
    void receiveDirect(RsEvent e) {
        simTime = e.simTime;
        dispatch(e);
    }

    private void sendRequest(WireOut payload) {
        sendMessage(REQUEST, payload);
    }

    /** Requests encoded onto the connection's stream, each by its own encoder. */
    private final class WireRequests implements RequestListener {
        @Override
        public void timeout(double duration, int timeoutIndex) {
            sendRequest(RequestCodec.timeout(duration, timeoutIndex));
        }

        @Override
        public void subscription(RsSubscriptionRequest r) {
            sendRequest(RequestCodec.subscription(r.eventCode, r.eventIndex, r.eventEnable));
        }

        @Override
        public void sensorStatus(RsSensorRequest r) {
            sendRequest(RequestCodec.sensorStatus(r.sensorID));
        }

        @Override
        public void motion(RsMotionRequest r) {
            sendRequest(RequestCodec.motion(r));
        }

        @Override
        public void halt(RsHaltRequest r) {
            sendRequest(RequestCodec.halt());
        }

        @Override
        public void position() {
            sendRequest(RequestCodec.position());
        }

        @Override
        public void setPosition() {
            throw new IllegalStateException("the client library never sends SetPosition");
        }

        @Override
        public void body(RsBody body) {
            throw new IllegalStateException("a body goes by sendBodySpecification, not as a request");
        }

        @Override
        public void placement(RsPlacementRequest r) {
            sendRequest(RequestCodec.placement(r.name));
        }

        @Override
        public void targetSelection(RsTargetSelectionRequest r) {
            sendRequest(RequestCodec.targetSelection(r.random, r.name, r.status, r.exclusive));
        }

        @Override
        public void plan(RsPlanRequest r) {
            sendRequest(RequestCodec.plan());
        }

        @Override
        public void heartbeat(RsHeartbeatRequest r) {
            sendRequest(RequestCodec.heartbeat(r.interval));
        }

        @Override
        public void painterChange(RsPainterChangeRequest r) {
            sendRequest(RequestCodec.painterChange(r));
        }

        @Override
        public void actuatorControl(RsActuatorControlRequest r) {
            sendRequest(RequestCodec.actuatorControl(r));
        }

        @Override
        public void encoderStatus(RsEncoderStatusRequest r) {
            sendRequest(RequestCodec.encoderStatus(r.requestIndex, r.encoderID, r.clearOnReport));
        }
    }

    /**
     * Sends a message; an I/O failure ends the session. After the session has ended requests are
     * dropped (RP1 0.60 threw NullPointerException); before it was ever connected they are a mistake.
     */
    private void sendMessage(int transactionCode, WireOut payload) {
        if (isClosed()) {
            verbose("RsClient: session closed, " + transactionName[transactionCode] + " not sent");
            return;
        }
        if (!isOutputSet()) {
            throw new IllegalStateException("RsClient is not connected: call initialize() before sending");
        }
        try {
            send(transactionCode, payload);
        } catch (IOException e) {
            terminate("RsClient terminating on output failure: " + e.getMessage());
        }
    }

    // ----------------------------------------------------------------------------------------------
    // Event loop.

    /**
     * The event loop: reads events and calls their handlers until the server goes away or breaks the
     * protocol, then shuts the session down (calling the shutdown handler) and returns. A client
     * connected directly ({@link RsConnection#connectDirect}) has no events to read, its handlers
     * running on the server's sending thread: for it this only waits until the session has ended.
     */
    @Override
    public void run() {
        if (link != null) {
            awaitClosed();
            return;
        }
        while (true) {
            EventCodec.Decoded d;
            try {
                d = readEvent();
            } catch (EOFException e) {
                terminate("RsClient terminating: the server closed the connection");
                return;
            } catch (IOException e) {
                terminate("RsClient terminating: " + e.getMessage());
                return;
            }
            dispatch(d.event);
            if (d.interlock > 0) {
                acknowledge(d.interlock);
            }
        }
    }

    private EventCodec.Decoded readEvent() throws IOException {
        int code = readHeader();
        if (code != EVENT) {
            throw new RsProtocolException("header transaction code",
                    "a client accepts only EVENT (3), got " + describeTransaction(code));
        }
        EventCodec.Decoded d = EventCodec.decode(wire());
        simTime = d.event.simTime;
        return d;
    }

    private void acknowledge(int interlock) {
        try {
            send(INTERLOCK, new WireOut().i32(interlock));
        } catch (IOException e) {
            terminate("RsClient terminating on output failure: " + e.getMessage());
        }
    }

    /** Reports why the session ends (in the log, or on standard error without one) and shuts it down. */
    private void terminate(String notice) {
        if (!isClosed()) {
            report(notice);
        }
        shutdown();
    }

    /** In the client's log; on standard error only when the client has no log at all. */
    private void report(String message) {
        if (logger != null) {
            logIt("X", message);
        } else {
            System.err.println(message);
        }
    }

    /** Calls the event's handlers in registration order until one consumes it. */
    private void dispatch(RsEvent e) {
        for (RsEventHandler h : registry.snapshot(e.eventID, e.getIndex())) {
            if (e.isConsumed()) {
                return;
            }
            try {
                deliver(h, e);
            } catch (RuntimeException ex) {
                reportHandlerFailure(h, e, ex);
            }
        }
    }

    /**
     * A handler that throws is reported and the event goes on to the remaining handlers: letting the
     * exception escape would end the event loop without closing the session, and with the interlock
     * on, freeze the simulation.
     */
    private void reportHandlerFailure(RsEventHandler h, RsEvent e, RuntimeException ex) {
        StringWriter trace = new StringWriter();
        ex.printStackTrace(new PrintWriter(trace));
        report("RsClient: handler " + h.getClass().getName() + " failed on " + e + ": " + trace);
    }

    private static void deliver(RsEventHandler h, RsEvent e) {
        switch (e.eventID) {
            case RsEvent.EVT_CONTACT_SENSOR:
                ((RsContactSensorEventHandler) h).process((RsContactSensorEvent) e);
                break;
            case RsEvent.EVT_MOUSE_CLICK:
                ((RsMouseClickEventHandler) h).process((RsMouseClickEvent) e);
                break;
            case RsEvent.EVT_POSITION:
                ((RsPositionEventHandler) h).process((RsPositionEvent) e);
                break;
            case RsEvent.EVT_RANGE_SENSOR:
                ((RsRangeSensorEventHandler) h).process((RsRangeSensorEvent) e);
                break;
            case RsEvent.EVT_TARGET_SENSOR:
                ((RsTargetSensorEventHandler) h).process((RsTargetSensorEvent) e);
                break;
            case RsEvent.EVT_TIMEOUT:
                ((RsTimeoutEventHandler) h).process((RsTimeoutEvent) e);
                break;
            case RsEvent.EVT_MOTION_STARTED:
                ((RsMotionStartedEventHandler) h).process((RsMotionStartedEvent) e);
                break;
            case RsEvent.EVT_MOTION_HALTED:
                ((RsMotionHaltedEventHandler) h).process((RsMotionHaltedEvent) e);
                break;
            case RsEvent.EVT_PLACEMENT:
                ((RsPlacementEventHandler) h).process((RsPlacementEvent) e);
                break;
            case RsEvent.EVT_TARGET_SELECTION:
                ((RsTargetSelectionEventHandler) h).process((RsTargetSelectionEvent) e);
                break;
            case RsEvent.EVT_PLAN:
                ((RsPlanEventHandler) h).process((RsPlanEvent) e);
                break;
            case RsEvent.EVT_PAINT_SENSOR:
                ((RsPaintSensorEventHandler) h).process((RsPaintSensorEvent) e);
                break;
            case RsEvent.EVT_HEARTBEAT:
                ((RsHeartbeatEventHandler) h).process((RsHeartbeatEvent) e);
                break;
            default:
                ((RsEncoderStatusEventHandler) h).process((RsEncoderStatusEvent) e);
                break;
        }
    }

    /** The simulation time of the last event received (0 before any; a plan event resets it to 0). */
    public synchronized double getSimTime() {
        return simTime;
    }
}
