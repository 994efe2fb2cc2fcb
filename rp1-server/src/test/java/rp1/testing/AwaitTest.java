package rp1.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.opentest4j.AssertionFailedError;

/** The waiting helper never lets a test fall through: it returns when the condition holds, else fails. */
@Timeout(10)
class AwaitTest {
    @Test
    void aConditionThatNeverHoldsFailsAtTheDeadlineWithTheMessage() {
        long start = System.nanoTime();
        AssertionFailedError e = assertThrows(AssertionFailedError.class,
                () -> Await.await(() -> false, Duration.ofMillis(50), "the robot left"));
        assertEquals("the robot left (not within 50 ms)", e.getMessage());
        assertTrue(System.nanoTime() - start >= 50_000_000L, "it waited the whole timeout");
    }

    @Test
    void aLatchThatIsNotReleasedFailsAtTheDeadlineWithTheMessage() {
        AssertionFailedError e = assertThrows(AssertionFailedError.class,
                () -> Await.await(new CountDownLatch(1), Duration.ofMillis(20), "the task started"));
        assertEquals("the task started (not within 20 ms)", e.getMessage());
    }

    @Test
    void aConditionMadeTrueByAnotherThreadEndsTheWait() throws Exception {
        AtomicBoolean done = new AtomicBoolean();
        CountDownLatch latch = new CountDownLatch(1);
        Thread t = new Thread(() -> {
            done.set(true);
            latch.countDown();
        });
        t.start();
        Await.await(done::get, Duration.ofSeconds(5), "the other thread ran");
        Await.await(latch, Duration.ofSeconds(5), "the other thread counted down");
        t.join();
    }

    @Test
    void wallTimePassesAtLeastAsLongAsAsked() {
        long start = System.nanoTime();
        Await.letWallTimePass(Duration.ofMillis(30));
        assertTrue(System.nanoTime() - start >= 30_000_000L);
    }
}
