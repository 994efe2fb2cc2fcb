package rp1.simulator.session;

import java.util.HashSet;
import java.util.Set;
import java.util.function.BooleanSupplier;

import rp1.rossum.RsBody;
import rp1.rossum.RsConnection;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsWheelSystem;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;
import rp1.simulator.scheduler.TaskHandle;
import rp1.simulator.world.EventSink;
import rp1.simulator.world.Robot;
import rp1.simulator.world.World;

/**
 * One client's session with the simulation: it translates the client's requests into scheduler tasks
 * on its robot and the world (docs/behavior.md section 4.3) and sends the client the events the world
 * produces for it.
 *
 * <p>Two halves, on two kinds of thread. Its {@link RequestIntake}, the listener its connection hands
 * each request to (on a transport thread, or on whatever thread an in-process client sends from),
 * only builds a {@link Request} record and queues it as an input of the simulation. At the next
 * boundary between tasks, the thread running tasks applies it here ({@link Request#applyTo}),
 * stamped with the current time: only then does anything change, so all session and model state is
 * touched by that thread alone.
 *
 * <p>Requests that concern the robot are ignored until the client has sent a body; requests for a
 * robot that is not on the floor are ignored as RP1 0.60 ignores them; requests naming parts the body
 * does not have are ignored with a verbose log line (RP1 0.60 crashed a thread on them). After the
 * client has left, nothing it sent is applied.
 */
public final class ClientSession implements EventSink {

    /** What a session works with: the simulation's parts, handed over by the simulation. */
    public interface Host {
        World world();

        Scheduler scheduler();

        Heartbeats heartbeats();

        RsLogInterface log();

        /** What a client may make the server hold. */
        ClientBudgets budgets();

        /** Queues a request of {@code session} for the next boundary. */
        void submit(ClientSession session, Request request);

        /**
         * An event for {@code session}'s client, just before it is sent ({@code delivered}), or one
         * the model produced that the client has not subscribed to. On the thread running tasks.
         */
        void eventOut(ClientSession session, RsEvent event, boolean delivered);
    }

    private final int number;
    private final String description;
    private final Host host;
    private final World world;
    private final Scheduler scheduler;
    private final RsLogInterface log;
    private final RsConnection connection;
    private final Subscriptions subscriptions = new Subscriptions();
    private final Set<TimeoutTask> timeouts = new HashSet<>();
    private final RequestIntake intake;
    private Robot robot;
    private boolean departed;
    private TaskHandle startMotion = TaskHandle.NONE;
    private Heartbeats.Beat heartbeat;
    private Runnable onDeparture = () -> { };
    private volatile BooleanSupplier mayWrite = () -> true;

    /**
     * A session for the client numbered {@code number} (1, 2, ... in the order clients joined) on
     * {@code connection}: its intake becomes the connection's request listener.
     */
    public ClientSession(int number, String description, RsConnection connection, Host host) {
        this.number = number;
        this.description = description;
        this.host = host;
        this.world = host.world();
        this.scheduler = host.scheduler();
        this.log = host.log();
        this.connection = connection;
        this.intake = new RequestIntake(this, host, connection);
        connection.setRequestListener(intake);
    }

    /** The transport half: where the connection's requests go, and how the client's departure is queued. */
    public RequestIntake intake() {
        return intake;
    }

    /** The client's number: 1, 2, ... in the order the clients joined. */
    public int getNumber() {
        return number;
    }

    /** Who this client is, for log lines (e.g. "client 3 (/127.0.0.1:40312)"). */
    public String getDescription() {
        return description;
    }

    /** The client's robot, or null before it sent a body. Read it on the thread running tasks. */
    public Robot getRobot() {
        return robot;
    }

    /**
     * Asked on the thread running tasks before each event is written to the client (the interlock
     * numbers it there); false: the client has left and the event is not written.
     */
    public void setWriteGate(BooleanSupplier gate) {
        mayWrite = gate;
    }

    /** Run once, on the thread running tasks, when the client's departure has been applied. */
    public void setDepartureListener(Runnable listener) {
        onDeparture = listener;
    }

    /** Applies {@code request} at {@code now}; nothing once the client has left. */
    void apply(Request request, double now) {
        if (!departed) {
            request.applyTo(this, now);
        }
    }

    @Override
    public void send(RsEvent event) {
        if (!departed) {
            host.eventOut(this, event, true);
            if (mayWrite.getAsBoolean()) {
                connection.sendEvent(event);
            }
        }
    }

    @Override
    public void sendIfSubscribed(RsEvent event) {
        if (isSubscribed(event.eventID, event.getIndex())) {
            send(event);
        } else if (!departed) {
            host.eventOut(this, event, false);
        }
    }

    @Override
    public boolean isSubscribed(int eventCode, int index) {
        return subscriptions.isSubscribed(eventCode, index);
    }

    private TaskHandle at(double time, Task task) {
        return scheduler.schedule(time, Scheduler.NORMAL, task);
    }

    /** The robot, or null (with a verbose log line) if the client has not sent a body yet. */
    private Robot robotFor(String request) {
        if (robot == null) {
            log.verbose(description + ": " + request + " request before a body was sent; ignored");
        }
        return robot;
    }

    void body(RsBody body) {
        Robot previous = robot;
        if (previous != null) {
            log.log(description + " sent a second body; it replaces the first (the robot must be placed again)");
            world.removeRobot(previous);
        }
        robot = world.addRobot(body, this);
        log.verbose(description + ": body \"" + body.getName() + "\" with " + body.getBodyPartArray().length + " parts");
    }

    void subscription(Request.Subscription r) {
        subscriptions.set(r.code(), r.index(), r.enable());
        intake.subscriptionApplied(subscriptions.size());
    }

    void timeout(Request.Timeout r, double now) {
        TimeoutTask t = new TimeoutTask(r.index());
        timeouts.add(t);
        t.handle = at(now + r.duration(), t);
    }

    /** A timeout falling due; cancelled if the client leaves first. */
    private final class TimeoutTask implements Task {
        private final int index;
        TaskHandle handle = TaskHandle.NONE;

        TimeoutTask(int index) {
            this.index = index;
        }

        @Override
        public void run(double time) {
            timeouts.remove(this);
            intake.timeoutDone();
            send(new RsTimeoutEvent(time, index));
        }
    }

    void heartbeat(double interval, double now) {
        if (heartbeat != null) {
            heartbeat.stop();
            heartbeat = null;
        }
        if (interval > 0.0) {
            double applied = Math.max(interval, Heartbeats.MIN_INTERVAL);
            if (applied != interval) {
                log.verbose(description + ": heartbeat interval " + interval + " s raised to " + applied + " s");
            }
            heartbeat = host.heartbeats().start((t, sequence) -> send(new RsHeartbeatEvent(t, sequence)), now, applied);
        }
    }

    void motion(RsMotionRequest request, double now) {
        Robot bot = robotFor("motion");
        if (bot != null && bot.isPlaced()) {
            startMotion(bot, request, now);
        }
    }

    /** Replaces any waiting start-motion task by one for {@code request}, due now. */
    private void startMotion(Robot bot, RsMotionRequest request, double now) {
        startMotion.cancel();
        startMotion = at(now, t -> world.requestMotion(bot, request, t));
    }

    /**
     * Actuator commands for the wheel system use the parameter values by position (names are
     * ignored). Commands for other parts, with fewer than two values, or for a robot off the floor
     * are ignored.
     */
    void actuatorControl(Request.ActuatorControl r, double now) {
        Robot bot = robotFor("actuator control");
        if (bot == null || !bot.isPlaced()) {
            return;
        }
        RsWheelSystem wheels = bot.getBody().wheelSystem;
        double[] values = r.valuesCopy();
        if (wheels == null || wheels.getID() != r.actuatorId() || values.length < 2) {
            log.verbose(description + ": actuator command " + r.commandId() + " for part " + r.actuatorId()
                    + " not applicable; ignored");
            return;
        }
        RsMotionRequest motion = wheels.getMotionRequestForActuatorControl(values);
        if (motion != null) {
            startMotion(bot, motion, now);
        }
    }

    void halt(double now) {
        Robot bot = robotFor("halt");
        if (bot != null) {
            scheduler.scheduleImmediate(now, t -> stop(bot, t));
        }
    }

    /** The stop-motion task: drops any waiting request and halts a motion under way. */
    private void stop(Robot bot, double time) {
        startMotion.cancel();
        world.halt(bot, time);
    }

    void position(double now) {
        Robot bot = robotFor("position");
        if (bot != null) {
            at(now, bot::reportPosition);
        }
    }

    /** Off the floor at once (requests after this one see it unplaced), on it again when the placement task runs. */
    void placement(String name, double now) {
        Robot bot = robotFor("placement");
        if (bot == null) {
            return;
        }
        scheduler.scheduleImmediate(now, t -> stop(bot, t));
        world.unplace(bot);
        at(now, t -> {
            String refusal = world.place(bot, name, t);
            if (refusal != null) {
                log.log(description + ": placement '" + (name == null ? "" : name) + "' refused: " + refusal);
            }
        });
    }

    void sensorStatus(Request.SensorStatus r, double now) {
        Robot bot = robotFor("sensor status");
        if (bot == null) {
            return;
        }
        if (!bot.hasSensor(r.sensorId())) {
            log.verbose(description + ": no sensor with id " + r.sensorId() + "; status request ignored");
            return;
        }
        at(now, t -> bot.reportSensor(r.sensorId(), t));
    }

    /** Applied at once, as RP1 0.60 answers it from the reader; selection is shared by all robots. */
    void targetSelection(Request.TargetSelection r, double now) {
        for (RsEvent e : world.selectTargets(r.toRequest(), now)) {
            send(e);
        }
    }

    void plan(double now) {
        // Stamped 0.0 whenever it is sent, as RP1 0.60 stamped it (behavior.md section 12).
        scheduler.scheduleImmediate(now, t -> send(new RsPlanEvent(0.0, world.getPlan())));
    }

    void painterChange(Request.PainterChange r, double now) {
        Robot bot = robotFor("painter change");
        if (bot != null) {
            at(now, t -> world.painterChange(bot, r.toRequest()));
        }
    }

    void encoderStatus(Request.EncoderStatus r, double now) {
        Robot bot = robotFor("encoder status");
        if (bot == null) {
            return;
        }
        at(now, t -> {
            int missing = bot.reportEncoders(r.requestIndex(), r.idsCopy(), r.clear(), t);
            if (missing > 0) {
                log.verbose(description + ": " + missing + " of the encoder ids asked for are not wheels; skipped");
            }
        });
    }

    /**
     * The client left: its waiting work is cancelled and its robot leaves the world now, before any
     * input that arrived after the departure is applied.
     */
    void depart() {
        departed = true;
        if (heartbeat != null) {
            heartbeat.stop();
        }
        startMotion.cancel();
        for (TimeoutTask t : timeouts) {
            t.handle.cancel();
        }
        timeouts.clear();
        if (robot != null) {
            world.removeRobot(robot);
        }
        onDeparture.run();
    }
}
