package rp1.rossum.wire;

import rp1.rossum.RsBody;
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

/**
 * What a client sends, one method per kind (docs/protocol.md sections 6 and 8): the requests
 * {@link RequestCodec#decode} reads, and the body a connection decodes. A server sets one on each
 * connection ({@code RsConnection.setRequestListener}); the client library sends through one too.
 * Methods are called on the thread that decodes the message (or, for a client connected directly,
 * the thread that sends it), one message at a time. Timeouts arrive as raw values because the
 * simulator honours a negative duration ("fire now, stamped in the past") that
 * {@code RsTimeoutRequest} would clamp.
 */
public interface RequestListener {
    /**
     * A timeout request.
     *
     * @param duration     seconds from now; may be negative
     * @param timeoutIndex the client's index, echoed in the event
     */
    void timeout(double duration, int timeoutIndex);

    /** A subscription request (or its withdrawal). */
    void subscription(RsSubscriptionRequest r);

    /** A request for one sensor's state. */
    void sensorStatus(RsSensorRequest r);

    /** A motion request. */
    void motion(RsMotionRequest r);

    /** A halt request. */
    void halt(RsHaltRequest r);

    /** A position request (it has no payload). */
    void position();

    /** The reserved request code 6: no payload, nothing to do. */
    void setPosition();

    /** A placement request. */
    void placement(RsPlacementRequest r);

    /** A target-selection request. */
    void targetSelection(RsTargetSelectionRequest r);

    /** A request for the floor plan. */
    void plan(RsPlanRequest r);

    /** A heartbeat request. */
    void heartbeat(RsHeartbeatRequest r);

    /** A painter change: activation, deactivation or erasure. */
    void painterChange(RsPainterChangeRequest r);

    /** An actuator command. */
    void actuatorControl(RsActuatorControlRequest r);

    /** A request for encoder states. */
    void encoderStatus(RsEncoderStatusRequest r);

    /**
     * The client's body specification, decoded (a copy of its own body for a directly connected
     * client), its parts carrying the ids the client gave them.
     */
    void body(RsBody body);
}
