package rp1.simulator.scenario;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Predicate;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyContactSensor;
import rp1.rossum.RsBodyPaintSensor;
import rp1.rossum.RsBodyPart;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsClient;
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

/**
 * A test robot client: it records every event it receives (subscribing to every sensor of its body
 * and to motion events) and runs the reactions a test registers, inside the event handler, so that
 * with the interlock on they happen at the simulation time of the event.
 */
public class ScenarioClient extends RsClient {
    private final RsBody body;
    private final List<RsEvent> events = new ArrayList<>();
    private final List<Reaction<?>> reactions = new ArrayList<>();
    private Runnable beforeWaiting = () -> { };
    private double lastAwaited = Double.NEGATIVE_INFINITY;

    public ScenarioClient(RsBody body) {
        this.body = body;
        setLogger(Scenario.QUIET);
    }

    public RsBody getBody() {
        return body;
    }

    /** Sends the body and registers recording handlers for everything. */
    public void join() {
        sendBodySpecification(body);
        addMotionStartedEventHandler(this::record);
        addMotionHaltedEventHandler(this::record);
        addMouseClickEventHandler(this::record);
        addPlacementEventHandler(this::record);
        addPositionEventHandler(this::record);
        addTimeoutEventHandler(this::record);
        addHeartbeatEventHandler(this::record);
        addPlanEventHandler(this::record);
        addTargetSelectionEventHandler(this::record);
        addEncoderStatusEventHandler(this::record);
        for (RsBodyPart p : body.getBodyPartArray()) {
            if (p instanceof RsBodyTargetSensor) {
                addTargetSensorEventHandler((RsBodyTargetSensor) p, this::record);
            } else if (p instanceof RsBodyRangeSensor) {
                addRangeSensorEventHandler((RsBodyRangeSensor) p, this::record);
            } else if (p instanceof RsBodyPaintSensor) {
                addPaintSensorEventHandler((RsBodyPaintSensor) p, this::record);
            } else if (p instanceof RsBodyContactSensor) {
                addContactSensorEventHandler((RsBodyContactSensor) p, this::record);
            }
        }
    }

    /** Runs {@code action} for every later event of this type, in the handler. */
    public synchronized <E extends RsEvent> void on(Class<E> type, Consumer<E> action) {
        reactions.add(new Reaction<>(type, action));
    }

    /** Runs {@code action} once, for the next event of this type. */
    public <E extends RsEvent> void once(Class<E> type, Consumer<E> action) {
        boolean[] done = {false};
        on(type, e -> {
            if (!done[0]) {
                done[0] = true;
                action.accept(e);
            }
        });
    }

    private void record(RsEvent e) {
        List<Reaction<?>> now;
        synchronized (this) {
            events.add(e);
            notifyAll();
            now = new ArrayList<>(reactions);
        }
        for (Reaction<?> r : now) {
            r.offer(e);
        }
    }

    /** A copy of the events received so far, in order. */
    public synchronized List<RsEvent> events() {
        return new ArrayList<>(events);
    }

    /** The received events of one type, in order. */
    public synchronized <E extends RsEvent> List<E> events(Class<E> type) {
        List<E> out = new ArrayList<>();
        for (RsEvent e : events) {
            if (type.isInstance(e)) {
                out.add(type.cast(e));
            }
        }
        return out;
    }

    /** Runs before the first wait for an event (the scenario starts its clock there). */
    void beforeWaiting(Runnable r) {
        beforeWaiting = r;
    }

    /** Waits (at most 20 s) for an event of this type matching the condition, and returns it. */
    public <E extends RsEvent> E await(Class<E> type, Predicate<E> condition) throws InterruptedException {
        beforeWaiting.run();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        synchronized (this) {
            while (true) {
                for (RsEvent e : events) {
                    if (type.isInstance(e) && condition.test(type.cast(e))) {
                        lastAwaited = Math.max(lastAwaited, e.simTime);
                        return type.cast(e);
                    }
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new AssertionError("no matching " + type.getSimpleName() + " within 20 s; got " + describe(events));
                }
                wait(Math.max(1, TimeUnit.NANOSECONDS.toMillis(left)));
            }
        }
    }

    /** Waits for the first event of this type. */
    public <E extends RsEvent> E await(Class<E> type) throws InterruptedException {
        return await(type, e -> true);
    }

    /** The whole event stream as text with full precision, for comparing runs. */
    public synchronized String transcript() {
        return describe(events);
    }

    /** The latest simulation time of an event a test waited for (minus infinity before any). */
    synchronized double lastAwaited() {
        return lastAwaited;
    }

    /**
     * The events stamped before {@code time}, as text. With the interlock, every event before the
     * time of an event a test has seen has been handled by its client by then, whatever the threads
     * did; later ones may still be on their way when a scenario ends.
     */
    synchronized String transcriptBefore(double time) {
        List<RsEvent> before = new ArrayList<>();
        for (RsEvent e : events) {
            if (e.simTime < time) {
                before.add(e);
            }
        }
        return describe(before);
    }

    static String describe(List<RsEvent> events) {
        StringBuilder b = new StringBuilder();
        for (RsEvent e : events) {
            b.append(describe(e)).append('\n');
        }
        return b.toString();
    }

    /** One event as text: time, type and every field. */
    public static String describe(RsEvent e) {
        String head = String.format(Locale.ROOT, "%.17g %s", e.simTime, e.getClass().getSimpleName());
        if (e instanceof RsMotionStartedEvent) {
            RsMotionStartedEvent s = (RsMotionStartedEvent) e;
            return head + " v=" + s.linearVelocity + " w=" + s.rotationalVelocity + " T=" + s.duration + " @" + s.x + "," + s.y + "," + s.orientation;
        } else if (e instanceof RsMotionHaltedEvent) {
            RsMotionHaltedEvent h = (RsMotionHaltedEvent) e;
            return head + " cause=" + h.causeOfHalt + " @" + h.x + "," + h.y + "," + h.orientation + " T=" + h.duration;
        } else if (e instanceof RsPlacementEvent) {
            RsPlacementEvent p = (RsPlacementEvent) e;
            return head + " " + p.valid + " " + p.name + " @" + p.x + "," + p.y + "," + p.orientation;
        } else if (e instanceof RsPositionEvent) {
            RsPositionEvent p = (RsPositionEvent) e;
            return head + " @" + p.x + "," + p.y + "," + p.orientation + " v=" + p.velocity + " w=" + p.turnRate;
        } else if (e instanceof RsTimeoutEvent) {
            return head + " " + ((RsTimeoutEvent) e).timeoutIndex;
        } else if (e instanceof RsHeartbeatEvent) {
            return head + " " + ((RsHeartbeatEvent) e).sequence;
        } else if (e instanceof RsTargetSensorEvent) {
            RsTargetSensorEvent t = (RsTargetSensorEvent) e;
            return head + " " + t.sensorID + " " + t.status + " r=" + t.range + " b=" + t.bearing + " " + t.getNameOfObjectDetected();
        } else if (e instanceof RsRangeSensorEvent) {
            RsRangeSensorEvent r = (RsRangeSensorEvent) e;
            return head + " " + r.sensorID + " " + r.status + " r=" + r.range + " " + r.getNameOfObjectDetected();
        } else if (e instanceof RsPaintSensorEvent) {
            RsPaintSensorEvent p = (RsPaintSensorEvent) e;
            return head + " " + p.sensorID + " " + p.status + " region=" + p.region;
        } else if (e instanceof RsContactSensorEvent) {
            RsContactSensorEvent c = (RsContactSensorEvent) e;
            return head + " " + c.sensorID + " " + c.status + " " + c.getNameOfObjectDetected();
        } else if (e instanceof RsMouseClickEvent) {
            RsMouseClickEvent m = (RsMouseClickEvent) e;
            return head + " " + m.button + " " + m.x + "," + m.y;
        } else if (e instanceof RsTargetSelectionEvent) {
            RsTargetSelectionEvent t = (RsTargetSelectionEvent) e;
            return head + " " + t.targetName + " " + t.status;
        } else if (e instanceof RsEncoderStatusEvent) {
            RsEncoderStatusEvent s = (RsEncoderStatusEvent) e;
            return head + " " + s.encoderID + " A=" + s.accumulatorValue + " B=" + s.absoluteAccumulatorValue + " angle=" + s.encoderAngle;
        } else if (e instanceof RsPlanEvent) {
            return head;
        }
        return head + " " + e;
    }

    private static final class Reaction<E extends RsEvent> {
        private final Class<E> type;
        private final Consumer<E> action;

        Reaction(Class<E> type, Consumer<E> action) {
            this.type = type;
            this.action = action;
        }

        void offer(RsEvent e) {
            if (type.isInstance(e)) {
                action.accept(type.cast(e));
            }
        }
    }
}
