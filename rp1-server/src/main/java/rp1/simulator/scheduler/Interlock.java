package rp1.simulator.scheduler;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import rp1.rossum.RsInterlock;

/**
 * The interlock (docs/behavior.md section 4.5): every event sent to a client over a stream stops the
 * simulation clock and carries a new number from one counter shared by the whole simulation; the clock
 * runs again once the newest event has been acknowledged.
 *
 * <p>With several clients this keeps one outstanding number per client and restarts the clock only
 * when every client has acknowledged the newest event it was sent (RP1 0.60 restarted it on the
 * newest number overall, letting time run while another client was still busy). With one client the
 * two rules are the same. Clients whose handlers the simulation calls directly need no interlock: the
 * call returning is the acknowledgement.
 *
 * <p><b>A client that leaves</b> ({@link #leave}) leaves at the first moment the clock would wait for
 * it, whenever its connection happens to end: if it owes an acknowledgement, at once (the clock was
 * waiting for it); if it owes nothing, when it is next sent an event ({@link #sending}), or when
 * nothing else can run. So its robot leaves at the same point of the run however fast its connection
 * went down (behavior.md section 3.5).
 */
public final class Interlock {
    /** The newest number a client has not acknowledged, and since when (System.nanoTime) it has owed one. */
    private record Owed(int number, long since) {
    }

    private final Scheduler scheduler;
    /** Each client's newest number not yet acknowledged. */
    private final Map<Object, Owed> pending = new HashMap<>();
    /** The number {@link #sending} gave the event a client's connection is about to write. */
    private final Map<Object, Integer> numbered = new HashMap<>();
    /** Clients whose connection has ended. */
    private final Set<Object> ended = new HashSet<>();
    /** Departures of clients that left owing nothing, waiting for the moment the clock would wait for them. */
    private final Map<Object, Runnable> deferred = new LinkedHashMap<>();
    private int counter;

    /** An interlock on {@code scheduler}'s clock. */
    public Interlock(Scheduler scheduler) {
        this.scheduler = scheduler;
    }

    /**
     * The view of this interlock a client's connection uses ({@code RsConnection.addInterlock}).
     *
     * @param afterRestart run on the acknowledging thread when an acknowledgement restarted the clock
     *                     (a reader thread then runs the tasks due itself)
     */
    public RsInterlock forClient(Object client, Runnable afterRestart) {
        return new RsInterlock() {
            @Override
            public int openInterlock() {
                return numberFor(client);
            }

            @Override
            public boolean closeInterlock(int interlock) {
                boolean restarted = close(client, interlock);
                if (restarted) {
                    afterRestart.run();
                }
                return restarted;
            }

            @Override
            public int getMaximumInterlockIndex() {
                return getCounter();
            }
        };
    }

    /**
     * An event is about to go to {@code client} (on the thread running tasks, before its connection
     * writes it): the clock stops until the client acknowledges it, and the event gets the next number.
     * If the client's connection has already ended, this is the first moment the clock would wait for
     * it: its departure, if still waiting, is handed over now (applied at the next boundary) and the
     * clock does not stop.
     *
     * @return whether the event is to be written (false: the client has left)
     */
    public synchronized boolean sending(Object client) {
        counter++;
        if (ended.contains(client)) {
            Runnable departure = deferred.remove(client);
            if (departure != null) {
                departure.run();
            }
            return false;
        }
        scheduler.stopClock();
        owe(client, counter);
        numbered.put(client, counter);
        return true;
    }

    /** {@code client} owes the acknowledgement of {@code number}; it began to keep the clock waiting if it owed none. */
    private void owe(Object client, int number) {
        Owed before = pending.get(client);
        pending.put(client, new Owed(number, before == null ? System.nanoTime() : before.since()));
    }

    /** The number of the event {@code client}'s connection writes: the one {@link #sending} gave it, or a new one. */
    private synchronized int numberFor(Object client) {
        Integer n = numbered.remove(client);
        return n != null ? n : open(client);
    }

    /** An event is going to {@code client}: stop the clock and return its interlock number. */
    public synchronized int open(Object client) {
        scheduler.stopClock();
        counter++;
        owe(client, counter);
        return counter;
    }

    /**
     * {@code client} acknowledged {@code value}. Older numbers than the newest it was sent are
     * ignored.
     *
     * @return whether the clock was restarted
     */
    public synchronized boolean close(Object client, int value) {
        Owed newest = pending.get(client);
        if (newest == null || value < newest.number()) {
            return false;
        }
        pending.remove(client);
        return restartIfNonePending();
    }

    /**
     * {@code client}'s connection ended (any thread). If the clock waits for it, {@code departure} (which
     * queues the client's departure as an input) runs now, before the clock is released, so the
     * departure is applied before any further task. Otherwise it runs at the first moment the clock
     * would wait for the client: when the client is next sent an event, or when nothing else can run,
     * whichever comes first.
     *
     * @return whether the clock was restarted
     */
    public synchronized boolean leave(Object client, Runnable departure) {
        ended.add(client);
        numbered.remove(client);
        if (pending.remove(client) != null) {
            departure.run();
            return restartIfNonePending();
        }
        deferred.put(client, departure);
        scheduler.whenIdle(this::departIdle);
        return false;
    }

    /** Nothing else can run: the departures still waiting are handed over. */
    private synchronized void departIdle() {
        for (Runnable departure : deferred.values()) {
            departure.run();
        }
        deferred.clear();
    }

    /** {@code client}'s departure has been applied: nothing about it is kept. */
    public synchronized void forget(Object client) {
        ended.remove(client);
        pending.remove(client);
        numbered.remove(client);
        deferred.remove(client);
    }

    /**
     * The clients that have kept the clock waiting for more than {@code nanos} of wall time (an
     * acknowledgement they owe since then), in no order. Any thread.
     */
    public synchronized List<Object> overdue(long nanos) {
        long now = System.nanoTime();
        List<Object> late = new ArrayList<>();
        pending.forEach((client, owed) -> {
            if (now - owed.since() > nanos) {
                late.add(client);
            }
        });
        return late;
    }

    private boolean restartIfNonePending() {
        if (!pending.isEmpty()) {
            return false;
        }
        scheduler.resumeClock();
        return true;
    }

    /** The newest interlock number handed out. */
    public synchronized int getCounter() {
        return counter;
    }

    /** Whether any client still has to acknowledge an event. */
    public synchronized boolean isOpen() {
        return !pending.isEmpty();
    }
}
