package rp1.simulator.launch;

import java.awt.Color;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsClient;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsProperties;
import rp1.rossum.event.RsEvent;

/**
 * A well-behaved network client built on the client library: connects to a test server, sends a round
 * body with a differential drive, records the events it receives (acknowledging interlocked ones, as
 * the library does) and runs its event loop on a thread of its own.
 */
final class TcpRobot extends RsClient {
    /** Swallows the library's log, such as the notice that the server closed the connection at the end of a test. */
    private static final RsLogInterface QUIET = new RsLogAdapter() {
        @Override
        public void logIt(String level, String message) {
        }
    };

    private final List<RsEvent> events = new ArrayList<>();
    private RsBodyPainter pen;

    /** Connects to the server on {@code port} and sends the body; call {@link #startLoop()} next. */
    static TcpRobot connect(int port, String name) throws IOException {
        return connect(port, name, false);
    }

    /** {@link #connect(int, String)} with a pen under the axle centre that leaves a 2 cm blue trail once down. */
    static TcpRobot connectWithPen(int port, String name) throws IOException {
        return connect(port, name, true);
    }

    private static TcpRobot connect(int port, String name, boolean withPen) throws IOException {
        TcpRobot robot = new TcpRobot();
        robot.setLogger(QUIET);
        RsProperties p = new RsProperties();
        p.hostName = "127.0.0.1";
        p.port = port;
        robot.initialize(p);
        RsBody body = new RsBody(name);
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.15));
        RsDifferentialSteering drive = new RsDifferentialSteering(0.18, 0.075);
        drive.addDefaultWheels(0.075, 0.03);
        body.addPart(drive);
        if (withPen) {
            robot.pen = new RsBodyPainter(new double[] {-0.01, -0.01, 0.01, -0.01, 0.01, 0.01, -0.01, 0.01}, 4);
            robot.pen.setTrailerPosition(0.0, 0.0);
            robot.pen.setTrailerWidth(0.02);
            robot.pen.setPaintColor(Color.blue);
            body.addPart(robot.pen);
        }
        robot.sendBodySpecification(body);
        robot.addHeartbeatEventHandler(robot::record);
        robot.addPlacementEventHandler(robot::record);
        robot.addTimeoutEventHandler(robot::record);
        robot.addMotionHaltedEventHandler(robot::record);
        return robot;
    }

    /** Starts the trail (a robot connected with a pen). */
    void penDown() {
        sendPainterActivationRequest(pen);
    }

    /** Runs the event loop on a daemon thread. */
    TcpRobot startLoop() {
        Thread t = new Thread(this, "test robot");
        t.setDaemon(true);
        t.start();
        return this;
    }

    private synchronized void record(RsEvent e) {
        events.add(e);
        notifyAll();
    }

    /** The events of this type received so far. */
    synchronized <E extends RsEvent> List<E> events(Class<E> type) {
        List<E> out = new ArrayList<>();
        for (RsEvent e : events) {
            if (type.isInstance(e)) {
                out.add(type.cast(e));
            }
        }
        return out;
    }

    /** Waits (at most 20 s) for an event of this type that matches. */
    synchronized <E extends RsEvent> E await(Class<E> type, Predicate<E> condition) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (true) {
            for (E e : events(type)) {
                if (condition.test(e)) {
                    return e;
                }
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                throw new AssertionError("no matching " + type.getSimpleName() + " within 20 s");
            }
            wait(Math.max(1L, TimeUnit.NANOSECONDS.toMillis(left)));
        }
    }

    /** Ends the session. */
    void leave() {
        shutdown();
    }
}
