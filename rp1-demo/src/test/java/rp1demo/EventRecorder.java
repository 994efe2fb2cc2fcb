package rp1demo;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyPaintSensor;
import rp1.rossum.RsBodyPart;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsClient;
import rp1.rossum.event.RsEvent;

/**
 * Records the events a demo's client receives, in order, by adding handlers of its own to the
 * demo's client, and lets a test wait for one.
 */
public final class EventRecorder {
    private final List<RsEvent> events = new ArrayList<>();

    /**
     * Registers recording handlers for the events that concern the whole robot. Called before the
     * demo initializes, so these run before the demo's own: once the demo has reacted to an event
     * (say, by declaring itself done), the event is already recorded.
     */
    void attachFirst(RsClient client) {
        client.addMotionStartedEventHandler(this::record);
        client.addMotionHaltedEventHandler(this::record);
        client.addPlacementEventHandler(this::record);
        client.addPositionEventHandler(this::record);
        client.addMouseClickEventHandler(this::record);
        client.addTimeoutEventHandler(this::record);
    }

    /** Registers recording handlers for the body's target and paint sensors (once the demo has made its body). */
    void attachSensors(RsClient client, RsBody body) {
        for (RsBodyPart p : body.getBodyPartArray()) {
            if (p instanceof RsBodyTargetSensor t) {
                client.addTargetSensorEventHandler(t, this::record);
            } else if (p instanceof RsBodyPaintSensor s) {
                client.addPaintSensorEventHandler(s, this::record);
            }
        }
    }

    private synchronized void record(RsEvent e) {
        events.add(e);
        notifyAll();
    }

    /** The events of this type received so far, in order. */
    public synchronized <E extends RsEvent> List<E> events(Class<E> type) {
        List<E> out = new ArrayList<>();
        for (RsEvent e : events) {
            if (type.isInstance(e)) {
                out.add(type.cast(e));
            }
        }
        return out;
    }

    /** Waits (at most {@code seconds} of wall time) for an event of this type matching the condition. */
    public synchronized <E extends RsEvent> E await(Class<E> type, Predicate<E> condition, double seconds)
            throws InterruptedException {
        long deadline = System.nanoTime() + (long) (seconds * 1e9);
        int checked = 0;
        while (true) {
            for (; checked < events.size(); checked++) {
                RsEvent e = events.get(checked);
                if (type.isInstance(e) && condition.test(type.cast(e))) {
                    return type.cast(e);
                }
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                throw new AssertionError("no matching " + type.getSimpleName() + " within " + seconds + " s");
            }
            wait(Math.max(1, TimeUnit.NANOSECONDS.toMillis(left)));
        }
    }
}
