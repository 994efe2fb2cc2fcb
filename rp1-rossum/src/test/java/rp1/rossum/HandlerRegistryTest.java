package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsEventHandler;
import rp1.rossum.event.RsHeartbeatEventHandler;

/** Handlers by (code, index), for the keys kept in arrays and for those kept in the map alike. */
class HandlerRegistryTest {
    private final HandlerRegistry registry = new HandlerRegistry();
    private final RsEventHandler first = (RsHeartbeatEventHandler) e -> { };
    private final RsEventHandler second = (RsHeartbeatEventHandler) e -> { };

    /** A heartbeat (index 0), a sensor of a small id, and keys beyond the arrays: a large, a negative id, an unknown code. */
    private static final int[][] KEYS = {
        {RsEvent.EVT_HEARTBEAT, 0}, {RsEvent.EVT_RANGE_SENSOR, 3}, {RsEvent.EVT_RANGE_SENSOR, 1000},
        {RsEvent.EVT_CONTACT_SENSOR, -1}, {99, 0}, {-5, 2},
    };

    @Test
    void handlersAreKeptInRegistrationOrderForEveryKindOfKey() {
        for (int[] k : KEYS) {
            assertFalse(registry.has(k[0], k[1]));
            assertEquals(List.of(), handlers(k[0], k[1]));
            registry.add(k[0], k[1], first);
            registry.add(k[0], k[1], second);
            assertTrue(registry.has(k[0], k[1]));
            assertEquals(List.of(first, second), handlers(k[0], k[1]));
        }
        assertEquals(List.of(), handlers(RsEvent.EVT_RANGE_SENSOR, 4), "a neighbouring id has none");
        assertEquals(List.of(), handlers(RsEvent.EVT_TARGET_SENSOR, 3), "nor another code at the same id");
    }

    @Test
    void removingAHandlerRemovesEveryRegistrationOfItAndLeavesTheKeyEmpty() {
        for (int[] k : KEYS) {
            registry.add(k[0], k[1], first);
            registry.add(k[0], k[1], second);
            registry.add(k[0], k[1], first);
            registry.remove(k[0], k[1], first);
            assertEquals(List.of(second), handlers(k[0], k[1]));
            registry.remove(k[0], k[1], second);
            assertFalse(registry.has(k[0], k[1]));
            registry.add(k[0], k[1], second);
            registry.removeAll(k[0], k[1]);
            assertFalse(registry.has(k[0], k[1]));
            assertEquals(List.of(), handlers(k[0], k[1]));
        }
    }

    @Test
    void aSnapshotIsNotChangedByLaterRegistrations() {
        registry.add(RsEvent.EVT_HEARTBEAT, 0, first);
        RsEventHandler[] before = registry.snapshot(RsEvent.EVT_HEARTBEAT, 0);
        registry.add(RsEvent.EVT_HEARTBEAT, 0, second);
        registry.remove(RsEvent.EVT_HEARTBEAT, 0, first);
        registry.removeAll(RsEvent.EVT_HEARTBEAT, 0);
        assertEquals(List.of(first), List.of(before));
    }

    @Test
    void aDispatchOnAnotherThreadSeesEachKeysHandlersWholeAndInOrderWhileTheyAreAdded() throws Exception {
        // Handlers are added on a robot's own thread while the simulation's thread dispatches: every
        // snapshot read there must be one the registry published, never a half-made one.
        int count = 2_000;
        RsEventHandler[] added = new RsEventHandler[count];
        for (int i = 0; i < count; i++) {
            added[i] = (RsHeartbeatEventHandler) e -> { };
        }
        Thread adder = new Thread(() -> {
            for (RsEventHandler h : added) {
                registry.add(RsEvent.EVT_RANGE_SENSOR, 5, h);
                registry.add(RsEvent.EVT_RANGE_SENSOR, 500, h);
            }
        });
        adder.start();
        int seen = 0;
        while (seen < count) {
            for (int index : new int[] {5, 500}) {
                RsEventHandler[] now = registry.snapshot(RsEvent.EVT_RANGE_SENSOR, index);
                for (int i = 0; i < now.length; i++) {
                    assertTrue(now[i] == added[i], "handler " + i + " of " + now.length + " at index " + index);
                }
                if (index == 500) {
                    assertTrue(now.length >= seen, "a later snapshot lost handlers");
                    seen = now.length;
                }
            }
        }
        adder.join();
        assertEquals(count, registry.snapshot(RsEvent.EVT_RANGE_SENSOR, 5).length);
    }

    private List<RsEventHandler> handlers(int code, int index) {
        return List.of(registry.snapshot(code, index));
    }
}
