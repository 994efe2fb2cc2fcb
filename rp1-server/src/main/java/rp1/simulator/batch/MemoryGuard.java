package rp1.simulator.batch;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.lang.management.MemoryUsage;
import java.lang.ref.WeakReference;
import java.util.List;
import java.util.function.Consumer;

/**
 * Tells once when the runs sharing this process have left it short of memory: when a collection of
 * the heap's oldest generation leaves it more than {@link #LOW} full. The heap is the process's, not
 * a run's: a robot that keeps memory without end fills it for the runs beside it, whose allocations
 * then fail at random points, and long before that every run crawls while the collector works on a
 * nearly full heap for a few freed bytes at a time (a sweep of forty 30-second runs took minutes
 * beside one such robot, its other runs 40 s each). The runs going then are better stopped and
 * carried out where their memory is their own ({@link LoaderRuns}).
 *
 * <p>It looks every {@link #PERIOD_MILLIS} ms, on a thread of its own, at what the last collection
 * left of the heap, which the collector counts anyway. A collector can let the heap fill between two
 * looks (ZGC on a small heap); the guard's own thread then fails to allocate, lets go of a reserve it
 * kept for this ({@link #reserveFor}) and tells as a look would have. The management classes that read it take 30 ms
 * to load, which a short sweep would feel at its start, so they are loaded after
 * {@link #LOAD_AFTER_MILLIS} ms or as soon as a quarter of the heap is in use, whichever comes first;
 * not later: on a heap that is full, the collector stops every thread for one full collection after
 * another with a fraction of a millisecond between them, and loading them then took the guard 20 s.
 */
final class MemoryGuard<T> implements AutoCloseable {
    /** The share of the oldest generation still in use after its collection that counts as short. */
    static final double LOW = 0.85;
    /** The share of the whole heap in use, garbage included, from which the collections are looked at. */
    private static final double WATCHED = 0.25;
    /** How long after it starts the guard looks at the collections whatever the heap's use, milliseconds. */
    private static final long LOAD_AFTER_MILLIS = 2_000;
    private static final long PERIOD_MILLIS = 50;
    /** The share of the heap set aside while the guard looks, for the stops of the runs when it fills. */
    private static final double RESERVE_SHARE = 1.0 / 32;
    private static final int RESERVE_MOST = 4 << 20;

    /**
     * Held weakly: the guard stops once its owner is gone, so that a guard whose owner was never
     * closed (a sweep that failed) does not look on for ever.
     */
    private final WeakReference<T> owner;
    private final Consumer<? super T> whenShort;
    private final Thread thread;
    private volatile boolean closed;
    /**
     * Memory set aside, let go when the heap fills all the same, so that the runs' stops (a thread
     * each, log lines, closing files) find room instead of failing for want of it.
     */
    private volatile byte[] reserve;

    /**
     * Starts looking on behalf of {@code owner}: {@code whenShort} is given it once, on the guard's
     * thread, if memory runs short before {@link #close}.
     */
    MemoryGuard(T owner, Consumer<? super T> whenShort) {
        this.owner = new WeakReference<>(owner);
        this.whenShort = whenShort;
        thread = new Thread(this::watch, "rp1-memory-guard");
        thread.setDaemon(true);
        thread.start();
    }

    private void watch() {
        Runtime runtime = Runtime.getRuntime();
        long loadBy = System.nanoTime() + LOAD_AFTER_MILLIS * 1_000_000;
        List<MemoryPoolMXBean> oldest = null;
        try {
            // Here rather than in the constructor: off the first run's way, on the other processor.
            reserve = new byte[reserveFor(runtime.maxMemory())];
            while (!closed && owner.get() != null) {
                Thread.sleep(PERIOD_MILLIS);
                if (oldest == null) {
                    if (runtime.totalMemory() - runtime.freeMemory() < WATCHED * runtime.maxMemory()
                            && System.nanoTime() - loadBy < 0) {
                        continue;
                    }
                    oldest = oldestGeneration();
                }
                if (!closed && isShort(oldest, runtime.maxMemory()) && told()) {
                    return;
                }
            }
        } catch (InterruptedException e) {
            // Closed.
        } catch (OutOfMemoryError e) {
            // The heap filled between two looks: a collector that lets it fill faster than it is looked
            // at (ZGC on a small heap). The reserve makes room for the runs' stops, then the owner is
            // told as a look would have told it.
            reserve = null;
            if (!closed) {
                told();
            }
        }
    }

    /** Lets go of the memory set aside for the runs' stops: the heap filled, and they need it now. */
    void letGoOfReserve() {
        reserve = null;
    }

    /** {@link #RESERVE_SHARE} of a heap of {@code maxBytes}, at most {@link #RESERVE_MOST} bytes. */
    static int reserveFor(long maxBytes) {
        return (int) Math.min(RESERVE_MOST, Math.max(0, maxBytes) * RESERVE_SHARE);
    }

    /**
     * The heap's pools whose use after a collection is counted: the oldest generation's ("PS Old Gen",
     * "Tenured Gen", "G1 Old Gen"), where what the runs keep ends up; a pool that is collected but keeps
     * nothing for long (the young generation's) is left out by its name. A collector with one
     * generation (ZGC, Shenandoah) has its one pool counted.
     */
    private static List<MemoryPoolMXBean> oldestGeneration() {
        List<MemoryPoolMXBean> collected = ManagementFactory.getMemoryPoolMXBeans().stream()
                .filter(p -> p.getType() == MemoryType.HEAP && p.isCollectionUsageThresholdSupported())
                .toList();
        List<MemoryPoolMXBean> oldest = collected.stream()
                .filter(p -> p.getName().contains("Old") || p.getName().contains("Tenured"))
                .toList();
        return oldest.isEmpty() ? collected : oldest;
    }

    /**
     * Tells the owner that memory ran short, if it is still there; whether it was. (A method of its
     * own, so that the guard's loop holds no strong reference to the owner while it sleeps.)
     */
    private boolean told() {
        T o = owner.get();
        if (o != null) {
            whenShort.accept(o);
        }
        return o != null;
    }

    /** Whether a pool's last collection left it more than {@link #LOW} full. */
    static boolean isShort(List<MemoryPoolMXBean> pools, long heapMax) {
        for (MemoryPoolMXBean p : pools) {
            MemoryUsage after = p.getCollectionUsage();
            if (after != null && isShort(after.getUsed(), after.getMax() > 0 ? after.getMax() : heapMax)) {
                return true;
            }
        }
        return false;
    }

    /** Whether {@code used} bytes of {@code max} are more than {@link #LOW} of it. */
    static boolean isShort(long used, long max) {
        return max > 0 && used > LOW * max;
    }

    /** Whether the guard still looks (it has not been closed, nor seen its owner go, nor told of memory running short). */
    boolean isLooking() {
        return thread.isAlive();
    }

    /** Stops looking (a look under way may still end in {@code whenShort}). */
    @Override
    public void close() {
        closed = true;
        thread.interrupt();
    }
}
