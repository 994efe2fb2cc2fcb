package rp1.simulator.scheduler;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** Inputs applied at a boundary: one that fails does not take the others with it. */
class InputQueueTest {
    @Test
    void anInputThatThrowsIsReportedAndTheRestOfTheBatchIsStillApplied() {
        Scheduler scheduler = new Scheduler(SimClock.lockstep());
        List<RuntimeException> failures = new ArrayList<>();
        scheduler.setFailureHandler(failures::add);
        InputQueue inputs = new InputQueue(scheduler);
        List<String> applied = new ArrayList<>();
        inputs.submit(input(1, false, () -> {
            throw new IllegalStateException("a request the world could not take");
        }));
        inputs.submit(input(2, false, () -> applied.add("client 2's request")));
        inputs.submit(input(3, true, () -> applied.add("client 3 leaves")));
        inputs.cross(1.5);
        assertEquals(List.of("client 3 leaves", "client 2's request"), applied, "departures first, then by source");
        assertEquals(1, failures.size());
        assertEquals("a request the world could not take", failures.get(0).getMessage());
        assertTrue(inputs.isSettled(), "every input counts as applied");
    }

    private static Input input(int source, boolean departure, Runnable action) {
        return new Input() {
            @Override
            public int source() {
                return source;
            }

            @Override
            public boolean isDeparture() {
                return departure;
            }

            @Override
            public void apply(double simTime) {
                action.run();
            }
        };
    }
}
