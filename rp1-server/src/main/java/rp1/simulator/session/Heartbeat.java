package rp1.simulator.session;

import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;

/**
 * A client's periodic heartbeat: beat k is due at exactly {@code start + k * interval} (no drift),
 * with sequence numbers 1, 2, 3, ...; heartbeats run after every other task due at the same time.
 * A cancelled heartbeat neither beats nor requeues itself, even if it was running when cancelled.
 */
final class Heartbeat implements Task {
    private final Scheduler scheduler;
    private final double start;
    private final double interval;
    private final ClientSession session;
    private int sequence;
    private volatile boolean cancelled;

    Heartbeat(ClientSession session, Scheduler scheduler, double start, double interval) {
        this.session = session;
        this.scheduler = scheduler;
        this.start = start;
        this.interval = interval;
    }

    void begin() {
        scheduler.schedule(start + interval, Scheduler.HEARTBEAT, this);
    }

    void cancel() {
        cancelled = true;
        scheduler.cancel(this);
    }

    @Override
    public void run(double time) {
        if (cancelled) {
            return;
        }
        sequence++;
        session.heartbeat(time, sequence);
        if (!cancelled) {
            scheduler.schedule(start + (sequence + 1) * interval, Scheduler.HEARTBEAT, this);
        }
    }
}
