package rp1.simulator.session;

import java.util.Collections;
import java.util.HashSet;
import java.util.Set;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyPart;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsConnection;
import rp1.rossum.RsConnectionBodyHandler;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsWheel;
import rp1.rossum.RsWheelSystem;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsSensorEvent;
import rp1.rossum.event.RsTargetSelectionEvent;
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
import rp1.rossum.request.RsRequest;
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSensorRequestHandler;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.request.RsTargetSelectionRequestHandler;
import rp1.rossum.request.RsTimeoutRequestHandler;
import rp1.simulator.scheduler.Interlock;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;
import rp1.simulator.world.EventSink;
import rp1.simulator.world.Robot;
import rp1.simulator.world.World;

/**
 * One client's session with the simulation: turns the requests its connection reads into scheduler
 * tasks stamped with the current simulation time (behavior.md section 4.3), and sends the events the
 * world produces for its robot. Requests that concern the robot are ignored until the client has
 * sent a body; requests for a robot that is not on the floor are ignored as RP1 0.60 ignores them;
 * requests naming parts the body does not have are ignored (RP1 0.60 crashed a thread on them).
 */
public final class ClientSession implements EventSink, RsTimeoutRequestHandler, RsMotionRequestHandler,
        RsPositionRequestHandler, RsPlacementRequestHandler, RsHaltRequestHandler, RsSensorRequestHandler,
        RsTargetSelectionRequestHandler, RsPainterChangeRequestHandler, RsActuatorControlRequestHandler,
        RsEncoderStatusRequestHandler, RsPlanRequestHandler, RsHeartbeatRequestHandler {
    private final World world;
    private final Scheduler scheduler;
    private final Interlock interlock;
    private final RsConnection connection;
    private final RsLogInterface log;
    private final String description;
    private final Set<Task> timeouts = Collections.synchronizedSet(new HashSet<>());
    private volatile Robot robot;
    private volatile boolean closed;
    private Task startMotion;
    private Heartbeat heartbeat;
    private Runnable onClose;

    /**
     * Attaches to {@code connection}: registers every request handler, the body handler, the
     * interlock (if enabled) and the shutdown handler. Start the connection's reader afterwards.
     */
    public ClientSession(World world, Scheduler scheduler, Interlock interlock, RsConnection connection,
                         RsLogInterface log, String description) {
        this.world = world;
        this.scheduler = scheduler;
        this.interlock = interlock;
        this.connection = connection;
        this.log = log;
        this.description = description;
        register();
    }

    private void register() {
        RsConnection c = connection;
        c.setTimeoutRequestHandler(this);
        c.setMotionRequestHandler(this);
        c.setPositionRequestHandler(this);
        c.setPlacementRequestHandler(this);
        c.setHaltRequestHandler(this);
        c.setSensorRequestHandler(this);
        c.setTargetSelectionRequestHandler(this);
        c.setPainterChangeRequestHandler(this);
        c.setActuatorControlRequestHandler(this);
        c.setEncoderStatusRequestHandler(this);
        c.setPlanRequestHandler(this);
        c.setHeartbeatRequestHandler(this);
        c.setBodyHandler(new RsConnectionBodyHandler() {
            @Override
            public void process(RsBody body) {
                bodyReceived(body);
            }
        });
        if (interlock != null) {
            c.addInterlock(interlock.forClient(this));
        }
        c.setProtocolShutdownHandler(this::connectionClosed);
    }

    /** Who this client is, for log lines (e.g. "client 3 (/127.0.0.1:40312)"). */
    public String getDescription() {
        return description;
    }

    /** The client's robot, or null before it sent a body. */
    public Robot getRobot() {
        return robot;
    }

    public RsConnection getConnection() {
        return connection;
    }

    /** Whether the connection has ended. */
    public boolean isClosed() {
        return closed;
    }

    /** Called once, after the session ended and its robot left the world. */
    public void setCloseListener(Runnable listener) {
        onClose = listener;
    }

    @Override
    public void send(RsEvent event) {
        connection.sendEvent(event);
    }

    @Override
    public boolean isSubscribed(int eventCode, int index) {
        return connection.isClientSubscribedToEvent(eventCode, index);
    }

    private double now() {
        return scheduler.now();
    }

    private void at(double time, Task task) {
        scheduler.schedule(time, Scheduler.NORMAL, task);
    }

    private void bodyReceived(RsBody body) {
        Robot previous = robot;
        if (previous != null) {
            log.log(description + " sent a second body; it replaces the first (the robot must be placed again)");
            scheduler.scheduleImmediate(t -> world.removeRobot(previous));
        }
        robot = world.addRobot(body, this);
        log.verbose(description + ": body \"" + body.getName() + "\" with " + body.getBodyPartArray().length + " parts");
    }

    /** The robot, or null (with a verbose log line) if the client has not sent a body yet. */
    private Robot robotFor(String request) {
        Robot r = robot;
        if (r == null) {
            log.verbose(description + ": " + request + " request before a body was sent; ignored");
        }
        return r;
    }

    @Override
    public void processRequest(RsRequest r) {
        log.verbose(description + ": unexpected untyped request " + r);
    }

    @Override
    public void process(double duration, int timeoutIndex) {
        double due = now() + duration;
        Task[] self = new Task[1];
        self[0] = t -> {
            timeouts.remove(self[0]);
            send(new RsTimeoutEvent(t, timeoutIndex));
        };
        timeouts.add(self[0]);
        at(due, self[0]);
    }

    @Override
    public void process(RsHeartbeatRequest r) {
        double start = now();
        synchronized (this) {
            if (heartbeat != null) {
                heartbeat.cancel();
                heartbeat = null;
            }
            if (r.interval > 0.0 && !closed) {
                heartbeat = new Heartbeat(this, scheduler, start, r.interval);
                heartbeat.begin();
            }
        }
    }

    void heartbeat(double time, int sequence) {
        send(new RsHeartbeatEvent(time, sequence));
    }

    @Override
    public void process(RsMotionRequest r) {
        Robot bot = robotFor("motion");
        if (bot != null && bot.isPlaced()) {
            startMotion(bot, r);
        }
    }

    /** Replaces any waiting start-motion task by one for {@code request}, due now. */
    private synchronized void startMotion(Robot bot, RsMotionRequest request) {
        if (startMotion != null) {
            scheduler.cancel(startMotion);
        }
        Task task = new Task() {
            @Override
            public void run(double t) {
                clearStartMotion(this);
                world.requestMotion(bot, request, t);
            }
        };
        startMotion = task;
        at(now(), task);
    }

    private synchronized void clearStartMotion(Task task) {
        if (startMotion == task) {
            startMotion = null;
        }
    }

    private synchronized void cancelStartMotion() {
        if (startMotion != null) {
            scheduler.cancel(startMotion);
            startMotion = null;
        }
    }

    @Override
    public void process(RsHaltRequest r) {
        Robot bot = robotFor("halt");
        if (bot != null) {
            scheduler.scheduleImmediate(t -> stop(bot, t));
        }
    }

    /** The stop-motion task: drops any waiting request and halts a motion under way. */
    private void stop(Robot bot, double time) {
        cancelStartMotion();
        world.halt(bot, time);
    }

    @Override
    public void process() {
        Robot bot = robotFor("position");
        if (bot != null) {
            at(now(), t -> send(bot.getBody().getPositionEvent(t)));
        }
    }

    @Override
    public void process(RsPlacementRequest r) {
        Robot bot = robotFor("placement");
        if (bot == null) {
            return;
        }
        scheduler.scheduleImmediate(t -> stop(bot, t));
        bot.markUnplaced();
        at(now(), t -> world.place(bot, r.name, t));
    }

    @Override
    public void process(RsSensorRequest r) {
        Robot bot = robotFor("sensor status");
        if (bot == null) {
            return;
        }
        at(now(), t -> {
            RsBodyPart part = bot.getBody().getPartByID(r.sensorID);
            if (!(part instanceof RsBodySensor)) {
                log.verbose(description + ": no sensor with id " + r.sensorID + "; status request ignored");
            } else if (bot.isPlaced()) {
                RsSensorEvent e = ((RsBodySensor) part).getSensorEvent(t);
                if (e != null) {
                    send(e);
                }
            }
        });
    }

    /** Answered at once from the reader, as RP1 0.60 does; selection is shared by all robots. */
    @Override
    public void process(RsTargetSelectionRequest r) {
        RsTargetSelectionEvent[] events;
        synchronized (world.getPlan()) {
            events = world.getPlan().processTargetSelectionRequest(now(), r);
        }
        for (RsTargetSelectionEvent e : events) {
            send(e);
        }
        world.changed(Double.NaN);
    }

    @Override
    public void process(RsPlanRequest r) {
        scheduler.scheduleImmediate(t -> send(new RsPlanEvent(0.0, world.getPlan())));
    }

    @Override
    public void process(RsPainterChangeRequest r) {
        Robot bot = robotFor("painter change");
        if (bot != null) {
            at(now(), t -> world.painterChange(bot, r));
        }
    }

    /**
     * Actuator commands for the wheel system use the parameter values by position (names are
     * ignored). Commands for other parts, with fewer than two values, or for a robot off the floor
     * are ignored.
     */
    @Override
    public void process(RsActuatorControlRequest r) {
        Robot bot = robotFor("actuator control");
        if (bot == null || !bot.isPlaced()) {
            return;
        }
        RsWheelSystem wheels = bot.getBody().wheelSystem;
        double[] values = r.getParameterValues();
        if (wheels == null || wheels.getID() != r.actuatorID || values.length < 2) {
            log.verbose(description + ": actuator command " + r + " not applicable; ignored");
            return;
        }
        RsMotionRequest motion = wheels.getMotionRequestForActuatorControl(values);
        if (motion != null) {
            startMotion(bot, motion);
        }
    }

    @Override
    public void process(RsEncoderStatusRequest r) {
        Robot bot = robotFor("encoder status");
        if (bot == null) {
            return;
        }
        at(now(), t -> {
            RsWheelSystem wheels = bot.getBody().wheelSystem;
            for (int id : r.encoderID) {
                RsWheel wheel = wheels == null ? null : wheels.getWheelForID(id);
                if (wheel == null) {
                    log.verbose(description + ": no wheel with id " + id + "; encoder status skipped");
                } else {
                    send(wheel.getEncoderStatusEvent(t, r.requestIndex, r.clearOnReport));
                }
            }
        });
    }

    /**
     * The connection ended: pending work for this client is cancelled, its interlock released, and
     * its robot leaves the world.
     */
    private void connectionClosed() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
            if (heartbeat != null) {
                heartbeat.cancel();
            }
        }
        cancelStartMotion();
        Task[] pending;
        synchronized (timeouts) {
            pending = timeouts.toArray(new Task[0]);
            timeouts.clear();
        }
        for (Task t : pending) {
            scheduler.cancel(t);
        }
        if (interlock != null) {
            interlock.release(this);
        }
        Robot bot = robot;
        if (bot != null) {
            bot.markUnplaced();
            scheduler.scheduleImmediate(t -> world.removeRobot(bot));
        }
        Runnable listener = onClose;
        if (listener != null) {
            listener.run();
        }
    }
}
