package rp1.simulator.session;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import rp1.rossum.RsBody;
import rp1.rossum.RsConnection;
import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsEncoderStatusRequest;
import rp1.rossum.request.RsHaltRequest;
import rp1.rossum.request.RsHeartbeatRequest;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlanRequest;
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.wire.RequestListener;

/**
 * The transport half of a client's session: the listener its connection hands each decoded request
 * and body to, on a transport thread (or on whatever thread an in-process client sends from). It
 * only builds the {@link Request} record and queues it as an input of the simulation; the session
 * ({@link ClientSession}) applies it at the next boundary, on the thread running tasks. Nothing here
 * touches session or model state.
 *
 * <p>What a client makes the server hold for it is counted here, as it arrives: timeouts not yet
 * fired and subscriptions. A client over its budget is disconnected, once, naming the budget.
 */
public final class RequestIntake implements RequestListener {
    private final ClientSession session;
    private final ClientSession.Host host;
    private final RsConnection connection;
    private final ClientBudgets budgets;
    /** Timeouts asked for that have not fallen due: waiting for a boundary or scheduled. */
    private final AtomicInteger timeoutsHeld = new AtomicInteger();
    /** Subscription requests waiting for a boundary. */
    private final AtomicInteger subscriptionsWaiting = new AtomicInteger();
    /** The number of subscriptions the session holds, published by the thread running tasks. */
    private volatile int subscriptionsHeld;
    private final AtomicBoolean overBudget = new AtomicBoolean();
    private volatile Runnable afterSubmit = () -> { };

    RequestIntake(ClientSession session, ClientSession.Host host, RsConnection connection) {
        this.session = session;
        this.host = host;
        this.connection = connection;
        this.budgets = host.budgets();
    }

    /**
     * Run on the transport's thread after each request has been queued: a reader thread of its own
     * runs the tasks then due itself.
     */
    public void setAfterSubmit(Runnable action) {
        afterSubmit = action;
    }

    /** The connection ended: the client's departure is queued like its requests. Any thread. */
    public void connectionClosed() {
        submit(new Request.Departure());
    }

    /** Queues the client's departure without running what follows a submission; any thread. */
    public void queueDeparture() {
        host.submit(session, new Request.Departure());
    }

    private void submit(Request r) {
        host.submit(session, r);
        afterSubmit.run();
    }

    /** A timeout has fallen due or been applied (thread running tasks). */
    void timeoutDone() {
        timeoutsHeld.decrementAndGet();
    }

    /** A subscription request has been applied; the session now holds {@code held} (thread running tasks). */
    void subscriptionApplied(int held) {
        subscriptionsHeld = held;
        subscriptionsWaiting.decrementAndGet();
    }

    /**
     * Whether a request may be queued: {@code over} is null. Otherwise the client has asked the server
     * to hold more than its budget: it is disconnected (once), naming the budget.
     */
    private boolean withinBudget(String over) {
        if (over == null) {
            return true;
        }
        if (overBudget.compareAndSet(false, true)) {
            connection.inputFailed("over budget: " + over);
        }
        return false;
    }

    @Override
    public void body(RsBody body) {
        submit(new Request.Body(body));
    }

    @Override
    public void timeout(double duration, int timeoutIndex) {
        if (withinBudget(ClientBudgets.over(timeoutsHeld.incrementAndGet(), "pending timeouts",
                ClientBudgets.TIMEOUT_BYTES, budgets.timeouts, "clientTimeoutBudget"))) {
            submit(new Request.Timeout(duration, timeoutIndex));
        }
    }

    @Override
    public void subscription(RsSubscriptionRequest r) {
        if (withinBudget(ClientBudgets.over(subscriptionsWaiting.incrementAndGet() + subscriptionsHeld,
                "subscriptions", ClientBudgets.SUBSCRIPTION_BYTES, budgets.subscriptions, "clientSubscriptionBudget"))) {
            submit(new Request.Subscription(r.eventCode, r.eventIndex, r.eventEnable));
        }
    }

    @Override
    public void heartbeat(RsHeartbeatRequest r) {
        submit(new Request.Heartbeat(r.interval));
    }

    @Override
    public void motion(RsMotionRequest r) {
        submit(new Request.Motion(r));
    }

    @Override
    public void halt(RsHaltRequest r) {
        submit(new Request.Halt());
    }

    @Override
    public void position() {
        submit(new Request.Position());
    }

    /** The reserved code 6 carries nothing to do; logged as the connection logged it. */
    @Override
    public void setPosition() {
        connection.verbose("RsConnection: ignoring reserved SetPosition request");
    }

    @Override
    public void placement(RsPlacementRequest r) {
        submit(new Request.Placement(r.name));
    }

    @Override
    public void sensorStatus(RsSensorRequest r) {
        submit(new Request.SensorStatus(r.sensorID));
    }

    @Override
    public void targetSelection(RsTargetSelectionRequest r) {
        submit(new Request.TargetSelection(r.random, r.name, r.status, r.exclusive));
    }

    @Override
    public void plan(RsPlanRequest r) {
        submit(new Request.Plan());
    }

    @Override
    public void painterChange(RsPainterChangeRequest r) {
        submit(Request.PainterChange.of(r));
    }

    @Override
    public void actuatorControl(RsActuatorControlRequest r) {
        submit(new Request.ActuatorControl(r.actuatorID, r.commandID, r.getParameterNames(), r.getParameterValues()));
    }

    @Override
    public void encoderStatus(RsEncoderStatusRequest r) {
        submit(new Request.EncoderStatus(r.requestIndex, r.encoderID, r.clearOnReport));
    }
}
