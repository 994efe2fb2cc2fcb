package rp1demo.demozero;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.GraphicsEnvironment;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1demo.DemoRun;

/** DemoZero without a display (the tests run headless): no window, ClientZero's behaviour. */
@Timeout(60)
class DemoZeroTest {

    @Test
    void withoutADisplayItGoesWhereItIsClickedLikeClientZero() throws Exception {
        assertTrue(GraphicsEnvironment.isHeadless(), "the test JVM runs with java.awt.headless=true");
        DemoMain demo = new DemoMain();
        try (DemoRun run = DemoRun.start("WhiteRoom.txt", demo, demo.getClient(), () -> demo.getClient().getBody())) {
            run.events().await(RsPlacementEvent.class, e -> e.valid, 20);
            run.simulation().mouseClick(0, 1, 2.0, 2.0);
            RsMotionHaltedEvent halted = run.events().await(RsMotionHaltedEvent.class, e -> true, 20);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, halted.causeOfHalt);
            assertEquals(2.0, halted.x, 0.005);
            assertEquals(2.0, halted.y, 0.005);
        }
    }
}
