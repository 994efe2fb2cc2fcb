package rp1.view;

import java.util.function.DoubleSupplier;

import rp1.simulator.snapshot.SnapshotPublisher;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * One frame of the window's animation, run by its timer on the event thread. A new snapshot goes to
 * the canvas; the status line shows the robots' poses from the snapshot and the time from the
 * simulation's clock, because the clock runs on while nothing moves and no new snapshot is taken.
 * Reading the clock is what every client request does too: a paced clock is brought up to the wall
 * clock, never past the next queued task, and a lockstep clock is not touched.
 */
final class Animation {
    private final SnapshotPublisher publisher;
    private final DoubleSupplier simTime;
    private final PlanCanvas canvas;
    private final StatusPanel status;
    private WorldSnapshot shown;

    /**
     * @param publisher where the snapshots come from
     * @param simTime   the simulation's current time
     * @param canvas    shows the snapshots
     * @param status    shows the time and the poses
     */
    Animation(SnapshotPublisher publisher, DoubleSupplier simTime, PlanCanvas canvas, StatusPanel status) {
        this.publisher = publisher;
        this.simTime = simTime;
        this.canvas = canvas;
        this.status = status;
        this.shown = canvas.shown();
    }

    /** Shows the latest snapshot, if it is new, and the time now. */
    void frame() {
        WorldSnapshot s = publisher.poll();
        if (s != shown) {
            shown = s;
            canvas.show(s);
        }
        status.showState(s, simTime.getAsDouble());
    }
}
