package rp1.simulator.scheduler;

import java.util.HashMap;
import java.util.Map;

import rp1.rossum.RsInterlock;

/**
 * The interlock (docs/behavior.md section 4.5): every event sent to a client over a stream stops the
 * simulation clock and carries a new number from one counter shared by the whole simulation; the clock
 * runs again once the newest event has been acknowledged.
 *
 * <p>With several clients this keeps one outstanding number per client and restarts the clock only
 * when every client has acknowledged the newest event it was sent (RP1 0.60 restarted it on the
 * newest number overall, letting time run while another client was still busy). With one client the
 * two rules are the same. A client that leaves releases whatever it still held. Clients whose handlers
 * the simulation calls directly need no interlock: the call returning is the acknowledgement.
 */
public final class Interlock {
    private final Scheduler scheduler;
    private final Map<Object, Integer> pending = new HashMap<>();
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
                return open(client);
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

    /** An event is going to {@code client}: stop the clock and return its interlock number. */
    public synchronized int open(Object client) {
        scheduler.stopClock();
        counter++;
        pending.put(client, counter);
        return counter;
    }

    /**
     * {@code client} acknowledged {@code value}. Older numbers than the newest it was sent are
     * ignored.
     *
     * @return whether the clock was restarted
     */
    public synchronized boolean close(Object client, int value) {
        Integer newest = pending.get(client);
        if (newest == null || value < newest) {
            return false;
        }
        pending.remove(client);
        return restartIfNonePending();
    }

    /**
     * {@code client} left: whatever it held is released.
     *
     * @return whether the clock was restarted
     */
    public synchronized boolean release(Object client) {
        return pending.remove(client) != null && restartIfNonePending();
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
