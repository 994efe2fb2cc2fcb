package rp1.simulator.launch;

import java.io.InputStream;
import java.io.OutputStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import rp1.rossum.RsClient;
import rp1.rossum.RsProtocol;
import rp1.rossum.RsRunnable;
import rp1.simulator.net.ClientConnection;
import rp1.simulator.net.InProcessClient;

/**
 * One dynamically loaded client (behavior.md section 3.4): an {@link RsRunnable} created from a class
 * name with its public no-argument constructor, then connected and initialized on a thread of its own,
 * which then runs its event loop ({@code run()}), unless the simulation calls its handlers directly.
 * Records whether it failed.
 */
final class LoadedClient {
    private static final int WAITING = 0;
    private static final int RUNS = 1;
    private static final int CALLED_OFF = 2;

    /** How a loaded client's thread ended, reported once. */
    interface Listener {
        /** {@code initialize()} threw: the client never ran. */
        void initializeFailed(LoadedClient client);

        /**
         * The client is done: {@code run()} returned or threw, initialization failed, or (called
         * directly) its session ended, on whichever thread ended it.
         */
        void finished(LoadedClient client);
    }

    final String className;
    final RsRunnable client;
    private final CountDownLatch initialized = new CountDownLatch(1);
    /** Whether the client may run ({@link #RUNS}), is waiting its turn, or was called off before it ran. */
    private final AtomicInteger turn = new AtomicInteger(WAITING);
    /** Opened when the turn is decided: the client's thread, if it was prepared, waits for it. */
    private final CountDownLatch decided = new CountDownLatch(1);
    private volatile InProcessClient link;
    /** Why the simulation cannot call the client's handlers directly, or null if it can. */
    private final String whyNotDirect;
    /** Set when the simulation calls the client's handlers directly (no event loop, no thread after initialize()). */
    private volatile ClientConnection directConnection;
    /** What failed, as the log said it, or null while nothing has. */
    private volatile String failure;
    private final AtomicBoolean done = new AtomicBoolean();
    /** The client's thread once started, else null. */
    private volatile Thread thread;

    private LoadedClient(String className, RsRunnable client) {
        this.className = className;
        this.client = client;
        this.whyNotDirect = whyNotDirect(client);
    }

    /**
     * Loads {@code className} and creates an instance.
     *
     * @throws StartupException naming the class and the reason if it cannot be found or loaded, is
     *                          not an {@code RsRunnable}, has no public no-argument constructor, or the
     *                          constructor throws
     */
    static LoadedClient create(String className, ClassLoader loader) throws StartupException {
        Class<?> type = load(className, loader);
        if (!RsRunnable.class.isAssignableFrom(type)) {
            throw failed("client class " + className + " does not implement " + RsRunnable.class.getName());
        }
        if (Modifier.isAbstract(type.getModifiers())) {
            throw failed("client class " + className + " is abstract");
        }
        Constructor<?> constructor;
        try {
            constructor = type.getConstructor();
        } catch (NoSuchMethodException e) {
            throw failed("client class " + className + " has no public constructor without arguments");
        }
        try {
            return new LoadedClient(className, (RsRunnable) constructor.newInstance());
        } catch (InvocationTargetException e) {
            throw new StartupException("client class " + className + ": its constructor failed: "
                    + describe(e.getCause()), ExitStatus.CLIENT_FAILED);
        } catch (ReflectiveOperationException e) {
            throw failed("client class " + className + " cannot be instantiated: " + describe(e));
        }
    }

    private static Class<?> load(String className, ClassLoader loader) throws StartupException {
        try {
            return Class.forName(className, true, loader);
        } catch (ClassNotFoundException e) {
            throw failed("client class " + className + " not found on the class path (dlcName)");
        } catch (LinkageError e) {
            throw failed("client class " + className + " cannot be loaded: " + describe(e));
        }
    }

    /** A client that cannot even be loaded is a client failure (exit status 2), like one that fails later. */
    private static StartupException failed(String message) {
        return new StartupException(message, ExitStatus.CLIENT_FAILED);
    }

    /** An exception as one line: its type and message. */
    static String describe(Throwable t) {
        return t.getMessage() == null ? t.getClass().getName() : t.getClass().getName() + ": " + t.getMessage();
    }

    /** The in-process link, if the client talks to the server through pipes. */
    void setLink(InProcessClient link) {
        this.link = link;
    }

    /**
     * Why the client's events cannot be delivered by direct calls, or null if they can: it must be an
     * {@code RsClient} that keeps the library's own event loop and stream handling (it overrides
     * neither {@code run()} nor {@code setInputOutputStreams}).
     */
    String whyNotDirect() {
        return whyNotDirect;
    }

    private static String whyNotDirect(RsRunnable client) {
        if (!(client instanceof RsClient)) {
            return "it is not an " + RsClient.class.getName();
        }
        String run = overridden(client, "run");
        return run != null ? run : overridden(client, "setInputOutputStreams", InputStream.class, OutputStream.class);
    }

    /**
     * "it overrides METHOD() (in CLASS)" if the client's class does, else null. One public method looked
     * up, not all of them: a sweep asks for each run's fresh robot class, and listing its hundred-odd
     * public methods (the library's included) for every run was about 1 % of what a 64-run sweep's runs ran.
     */
    private static String overridden(RsRunnable client, String method, Class<?>... parameters) {
        Class<?> declaring;
        try {
            declaring = client.getClass().getMethod(method, parameters).getDeclaringClass();
        } catch (NoSuchMethodException e) {
            return null;
        }
        return declaring == RsClient.class || declaring == RsProtocol.class ? null
                : "it overrides " + method + "() (in " + declaring.getName() + ")";
    }

    /** The simulation calls this client's handlers directly, through {@code connection}: after initialize() its thread ends. */
    void setDirect(ClientConnection connection) {
        this.directConnection = connection;
    }

    /**
     * A directly called client's session ended: it is done, as a client whose {@code run()} returns;
     * {@code failure} is what a handler threw, or null.
     */
    void sessionEnded(ServerLog log, Listener listener, Throwable failure) {
        if (failure != null) {
            fail(log, "a handler failed: " + describe(failure));
        }
        finish(listener);
    }

    /**
     * Lets the client run on its thread in {@code group} ({@link #prepare}d, or started now):
     * {@code initialize()}, then {@code run()} (for a direct client, only {@code initialize()}). The
     * threads the client starts from it join the group. Nothing, if the client was {@link #callOff called off}.
     */
    void start(ServerLog log, Listener listener, ThreadGroup group) {
        prepare(log, listener, group);
        if (turn.compareAndSet(WAITING, RUNS)) {
            decided.countDown();
        }
    }

    /**
     * Starts the client's thread in {@code group}, if it has none and was not called off, without
     * letting it run the client: it waits for {@link #start}. The launcher prepares the next client's
     * thread while the one before it initializes: starting a thread is work for the operating system,
     * and done between one client's being ready and the next one's start, it was a third of the time
     * 10,000 robots took to start (docs/performance.md).
     */
    void prepare(ServerLog log, Listener listener, ThreadGroup group) {
        if (thread != null || turn.get() == CALLED_OFF) {
            return;
        }
        Thread t = new Thread(group, () -> {
            try {
                decided.await();
            } catch (InterruptedException e) {
                // Ended before its turn (the run stopped): it never runs. Should its turn have come
                // just then, the client starts with the interrupt that ended the run.
                callOff();
                Thread.currentThread().interrupt();
            }
            if (turn.get() == RUNS) {
                runClient(log, listener);
            }
        }, "dlc " + className);
        t.setDaemon(true);
        thread = t;
        t.start();
    }

    /**
     * The run is stopping: a client still waiting its turn never runs, and its thread, if prepared,
     * ends at once; one already let run is left to end with its session. Either way the launcher
     * waits for it no longer.
     */
    void callOff() {
        if (turn.compareAndSet(WAITING, CALLED_OFF)) {
            decided.countDown();
        }
        initialized.countDown();
    }

    /** The client's thread (which may have ended, or be waiting its turn), or null if none was started. */
    Thread thread() {
        return thread;
    }

    /*
     * Whatever a client throws, Errors included, ends in one log line and a recorded failure rather
     * than a stack dump from a dead thread: the server has to know the client is gone.
     */
    private void runClient(ServerLog log, Listener listener) {
        try {
            client.initialize();
        } catch (Throwable t) {
            fail(log, "initialize() failed: " + describe(t));
            listener.initializeFailed(this);
            finish(listener);
            return;
        } finally {
            initialized.countDown();
        }
        if (directConnection != null) {
            return;
        }
        try {
            client.run();
            log.log("client " + className + ": run() returned");
        } catch (Throwable t) {
            fail(log, "run() failed: " + describe(t));
        } finally {
            finish(listener);
        }
    }

    /** The client is done: its connection is closed (if still open) and the listener told, once. */
    private void finish(Listener listener) {
        if (!done.compareAndSet(false, true)) {
            return;
        }
        InProcessClient l = link;
        if (l != null) {
            l.close();
        }
        ClientConnection c = directConnection;
        if (c != null) {
            c.close("the client is done");
        }
        listener.finished(this);
    }

    private void fail(ServerLog log, String what) {
        failure = "client " + className + ": " + what;
        log.important(failure);
    }

    /** What failed (the log's line), or null if the client has not failed. */
    String failure() {
        return failure;
    }

    /**
     * Waits until {@code initialize()} has returned (or failed) and, for an in-process client, the
     * server has read everything it sent so far, at most until {@code deadlineNanos}, or until the
     * client is {@linkplain #callOff called off}.
     *
     * @return whether the client got that far in time
     */
    boolean awaitReady(long deadlineNanos) throws InterruptedException {
        if (!initialized.await(Math.max(0L, deadlineNanos - System.nanoTime()), TimeUnit.NANOSECONDS)) {
            return false;
        }
        InProcessClient l = link;
        return l == null || failure != null
                || l.awaitDrained(Math.max(0L, TimeUnit.NANOSECONDS.toMillis(deadlineNanos - System.nanoTime())));
    }
}
