package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.awt.event.InputEvent;
import java.awt.event.MouseEvent;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsPlan;
import rp1.rossum.RsPoint;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.simulator.scenario.Scenario;
import rp1.simulator.scenario.ScenarioClient;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * Mouse presses on the canvas become mouse-click events with the floor point under the pointer
 * (behavior.md section 8.8), zoomed or not; moving the pointer feeds the read-out. No display needed:
 * the events are dispatched to the component directly.
 */
@Timeout(60)
class PlanCanvasTest {

    private static void press(PlanCanvas canvas, double x, double y, int button, int modifiers) {
        ViewTransform v = canvas.view();
        int px = (int) Math.round(v.pixelX(x));
        int py = (int) Math.round(v.pixelY(y));
        canvas.dispatchEvent(new MouseEvent(canvas, MouseEvent.MOUSE_PRESSED, 0L, modifiers, px, py, 1, false, button));
    }

    private static void assertClick(RsMouseClickEvent e, int button, double x, double y, double pixel) {
        assertEquals(button, e.button);
        assertEquals(1, e.clickCount);
        assertEquals(x, e.x, pixel / 2);
        assertEquals(y, e.y, pixel / 2);
    }

    @Test
    void pressesReachTheSubscribedClientAsFloorPointsZoomedOrNot() throws Exception {
        try (Scenario s = Scenario.shippedPlan("WhiteRoom.txt")) {
            RsPlan plan = s.simulation().getWorld().getPlan();
            ScenarioClient c = s.connect(new ScenarioClient(ClientZero.build()));
            c.sendPlacementRequest("home");
            c.await(RsPlacementEvent.class);
            PlanCanvas canvas = new PlanCanvas(new Renderer(plan), WorldSnapshot.planOnly(plan), s.simulation(), p -> { });
            canvas.setSize(500, 400);
            double pixel = 1.0 / canvas.view().getScale();
            press(canvas, 1.0, 0.6, MouseEvent.BUTTON1, InputEvent.BUTTON1_DOWN_MASK);
            assertClick(c.await(RsMouseClickEvent.class), 0, 1.0, 0.6, pixel);
            canvas.zoomIn();
            canvas.zoomIn();
            press(canvas, 2.2, 1.7, MouseEvent.BUTTON3, InputEvent.BUTTON3_DOWN_MASK);
            assertClick(c.await(RsMouseClickEvent.class, e -> e.button == 1), 1, 2.2, 1.7,
                    pixel / (PlanCanvas.ZOOM_STEP * PlanCanvas.ZOOM_STEP));
        }
    }

    @Test
    void movingThePointerReportsTheFloorPointAndLeavingClearsIt() throws Exception {
        RsPlan plan = Worlds.whiteRoom();
        List<RsPoint> reported = new ArrayList<>();
        PlanCanvas canvas = new PlanCanvas(new Renderer(plan), WorldSnapshot.planOnly(plan), null, reported::add);
        canvas.setSize(500, 400);
        ViewTransform v = canvas.view();
        canvas.dispatchEvent(new MouseEvent(canvas, MouseEvent.MOUSE_MOVED, 0L, 0, 57, 392, 0, false, MouseEvent.NOBUTTON));
        canvas.dispatchEvent(new MouseEvent(canvas, MouseEvent.MOUSE_EXITED, 0L, 0, 600, 392, 0, false, MouseEvent.NOBUTTON));
        assertEquals(2, reported.size());
        assertEquals(v.worldX(57), reported.get(0).x, 1e-12);
        assertEquals(-0.025, reported.get(0).x, 1e-12, "the plan's lower left corner");
        assertEquals(-0.025, reported.get(0).y, 1e-12);
        assertNull(reported.get(1));
    }
}
