package rp1.simulator.session;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.util.HashSet;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.Test;

import rp1.rossum.event.RsEvent;

/**
 * A client's subscriptions behave as a set of (code, index) pairs, whatever order it subscribes and
 * unsubscribes in, and the events that always go out are never kept.
 */
class SubscriptionsTest {
    @Test
    void subscribingAndUnsubscribingInAnyOrderKeepsExactlyThePairsLeftWanted() {
        Subscriptions subscriptions = new Subscriptions();
        Set<String> model = new HashSet<>();
        Random random = new Random(9);
        for (int i = 0; i < 20_000; i++) {
            int code = random.nextInt(RsEvent.EVT_MAX_CODE + 3) - 1;
            int index = random.nextInt(12) - 1;
            boolean enable = random.nextInt(3) > 0;
            subscriptions.set(code, index, enable);
            boolean kept = code >= 0 && code <= RsEvent.EVT_MAX_CODE && index >= 0 && code != RsEvent.EVT_TIMEOUT
                    && code != RsEvent.EVT_POSITION && code != RsEvent.EVT_PLACEMENT;
            if (kept && enable) {
                model.add(code + "/" + index);
            } else if (kept) {
                model.remove(code + "/" + index);
            }
            assertEquals(model.size(), subscriptions.size(), "after step " + i);
            int askCode = random.nextInt(RsEvent.EVT_MAX_CODE + 1);
            int askIndex = random.nextInt(11);
            assertEquals(model.contains(askCode + "/" + askIndex), subscriptions.isSubscribed(askCode, askIndex),
                    "asked at step " + i);
        }
        assertFalse(subscriptions.isSubscribed(RsEvent.EVT_POSITION, 0), "positions always go out, unkept");
    }
}
