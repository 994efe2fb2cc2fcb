package rp1.rossum;

import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/** Collects values handed over by another thread; {@link #next()} waits a bounded time for one. */
final class Capture<T> {
    private final BlockingQueue<T> queue = new LinkedBlockingQueue<>();

    void add(T value) {
        queue.add(value);
    }

    /** The next value, failing the test if none arrives within 10 seconds. */
    T next() throws InterruptedException {
        T value = queue.poll(10, TimeUnit.SECONDS);
        if (value == null) {
            throw new AssertionError("nothing arrived within 10 s");
        }
        return value;
    }

    /** The next value if one arrives within {@code millis}, else null. */
    T poll(long millis) throws InterruptedException {
        return queue.poll(millis, TimeUnit.MILLISECONDS);
    }

    boolean isEmpty() {
        return queue.isEmpty();
    }
}
