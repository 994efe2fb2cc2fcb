package rp1.simulator.scheduler;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The inputs waiting for the next boundary, and the order they are applied in there: first every
 * departure (a client that has left is gone before anything that arrived with it is looked at), then
 * the rest by source (the view, then clients in the order they connected), each source's inputs in
 * the order they arrived. With the interlock, everything the clients send in answer to one task's
 * events arrives before the clock may run again, so this order makes a run independent of which
 * client's thread happened to be faster.
 */
public final class InputQueue implements Scheduler.Boundary {
    /** Told about every input just before it is applied (a recording, for instance). */
    @FunctionalInterface
    public interface Listener {
        void applying(Input input, double simTime);
    }

    private static final Comparator<Input> ORDER =
            Comparator.comparing((Input i) -> !i.isDeparture()).thenComparingInt(Input::source);

    private final Scheduler scheduler;
    private final List<Input> waiting = new ArrayList<>();
    /** Inputs submitted but not yet applied (those being applied included). */
    private final AtomicInteger unapplied = new AtomicInteger();
    private volatile Listener listener;

    /** A queue whose inputs {@code scheduler} applies at its boundaries. */
    public InputQueue(Scheduler scheduler) {
        this.scheduler = scheduler;
        scheduler.setBoundary(this);
    }

    /** Sets who is told about each input as it is applied (null: nobody). */
    public void setListener(Listener listener) {
        this.listener = listener;
    }

    /** Queues {@code input} for the next boundary. Any thread. */
    public void submit(Input input) {
        unapplied.incrementAndGet();
        synchronized (waiting) {
            waiting.add(input);
        }
        scheduler.inputsArrived();
    }

    @Override
    public void cross(double simTime) {
        List<Input> batch;
        synchronized (waiting) {
            if (waiting.isEmpty()) {
                return;
            }
            batch = new ArrayList<>(waiting);
            waiting.clear();
        }
        batch.sort(ORDER);
        Listener l = listener;
        try {
            for (Input input : batch) {
                if (l != null) {
                    l.applying(input, simTime);
                }
                try {
                    input.apply(simTime);
                } catch (RuntimeException e) {
                    // One client's request that fails must not drop the rest of the batch (departures
                    // included), nor end the thread applying it: it goes where a failing task goes.
                    scheduler.failed(e);
                }
            }
        } finally {
            unapplied.addAndGet(-batch.size());
        }
    }

    /** Whether every input submitted so far has been applied. Any thread. */
    public boolean isSettled() {
        return unapplied.get() == 0;
    }
}
