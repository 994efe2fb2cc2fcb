package rp1.rossum;

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
 * Receives the requests {@link RequestCodec#decode} reads, one method per request type. Timeouts
 * arrive as raw values because the simulator honours a negative duration ("fire now, stamped in the
 * past") that {@code RsTimeoutRequest} would clamp.
 */
interface RequestSink {
    void timeout(double duration, int timeoutIndex);

    void subscription(RsSubscriptionRequest r);

    void sensorStatus(RsSensorRequest r);

    void motion(RsMotionRequest r);

    void halt(RsHaltRequest r);

    void position();

    /** The reserved request code 6: no payload, nothing to do. */
    void setPosition();

    void placement(RsPlacementRequest r);

    void targetSelection(RsTargetSelectionRequest r);

    void plan(RsPlanRequest r);

    void heartbeat(RsHeartbeatRequest r);

    void painterChange(RsPainterChangeRequest r);

    void actuatorControl(RsActuatorControlRequest r);

    void encoderStatus(RsEncoderStatusRequest r);
}
