package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import javax.swing.SwingUtilities;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.RsBody;
import rp1.rossum.RsPlan;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.simulator.Simulation;
import rp1.simulator.scenario.Scenario;
import rp1.simulator.scenario.ScenarioClient;
import rp1.simulator.snapshot.SnapshotPublisher;

/**
 * A slow window and picture files never change what the clients are told: the same lockstep
 * scenario gives the same events, to the last bit, whether or not it is being watched (the window's
 * animation reads snapshots and the clock).
 */
@Timeout(120)
class ObservingChangesNothingTest {

    /**
     * ClientZero paints its way from home into the diagonal wall, backs off, turns and drives on, with a
     * heartbeat every 0.25 s (at the same times as the pictures, whose tasks share its priority).
     */
    private static String drive(Scenario s) throws InterruptedException {
        RsBody body = ClientZero.withPainter();
        ScenarioClient c = s.connect(new ScenarioClient(body));
        AtomicInteger halts = new AtomicInteger();
        c.once(RsPlacementEvent.class, e -> {
            c.sendPainterActivationRequest(ClientZero.painterOf(body));
            c.sendHeartbeatRequest(0.25);
            c.sendMotionRequest(new RsMotionRequest(0.5, 0.0, 4.0));
        });
        c.on(RsMotionHaltedEvent.class, h -> {
            int n = halts.incrementAndGet();
            if (n == 1) {
                c.sendMotionRequest(new RsMotionRequest(-0.3, 0.0, 1.0));
            } else if (n == 2) {
                c.sendMotionRequest(new RsMotionRequest(0.0, Math.PI / 4, 2.0));
            } else if (n == 3) {
                c.sendMotionRequest(new RsMotionRequest(0.4, 0.0, 3.0));
            } else {
                c.sendHeartbeatCancellationRequest();
            }
        });
        c.sendPlacementRequest("home");
        c.await(RsMotionHaltedEvent.class, h -> c.events(RsMotionHaltedEvent.class).indexOf(h) == 3);
        return c.transcript();
    }

    private static String unobserved() throws InterruptedException {
        try (Scenario s = Scenario.shippedPlan("WhiteRoom.txt")) {
            return drive(s);
        }
    }

    @Test
    // "try": the SnapshotWriter is never used in its try block; it only has to be there, writing
    // pictures, while the scenario is driven.
    @SuppressWarnings("try")
    void aSlowWindowAndPictureFilesLeaveTheEventsAsTheyAre(@TempDir Path dir) throws Exception {
        String alone = unobserved();
        String watched;
        int frames;
        try (Scenario s = Scenario.shippedPlan("WhiteRoom.txt");
             SnapshotPublisher publisher = new SnapshotPublisher(s.simulation());
             SnapshotWriter writer = new SnapshotWriter(s.simulation(), dir.resolve("w.png"), 0.25, new Worlds.RecordingLog())) {
            SlowWindow window = new SlowWindow(s.simulation(), publisher);
            window.start();
            watched = drive(s);
            frames = window.finish();
            s.simulation().shutdown();
        }
        assertTrue(alone.contains("RsMotionHaltedEvent cause=" + RsMotionHaltedEvent.HALTED_ON_COLLISION),
                "the scenario hits the wall:\n" + alone);
        assertTrue(frames > 1, "the window drew " + frames + " frames");
        assertEquals(alone, watched);
    }

    /**
     * Runs the window's animation frames (snapshot and clock) on the event thread, as its timer does,
     * and draws each, taking 30 ms per frame.
     */
    private static final class SlowWindow extends Thread {
        private final Renderer renderer;
        private final PlanCanvas canvas;
        private final Animation animation;
        private final AtomicBoolean running = new AtomicBoolean(true);
        private int frames;
        private volatile Throwable failure;

        SlowWindow(Simulation simulation, SnapshotPublisher publisher) {
            super("slow-window");
            RsPlan plan = simulation.getWorld().getPlan();
            this.renderer = new Renderer(plan);
            StatusPanel status = new StatusPanel(DisplayUnits.of(plan.getUnits()));
            this.canvas = new PlanCanvas(renderer, publisher.poll(), simulation, p -> { });
            this.animation = new Animation(publisher, simulation::getSimTime, canvas, status);
            setDaemon(true);
        }

        @Override
        public void run() {
            while (running.get()) {
                try {
                    SwingUtilities.invokeAndWait(animation::frame);
                    Pictures.render(renderer, canvas.shown(), 400, 400);
                    frames++;
                    Thread.sleep(30);
                } catch (InvocationTargetException e) {
                    failure = e.getCause();
                    return;
                } catch (InterruptedException e) {
                    return;
                }
            }
        }

        int finish() throws InterruptedException {
            running.set(false);
            join(5000);
            if (failure != null) {
                throw new AssertionError("an animation frame failed", failure);
            }
            return frames;
        }
    }
}
