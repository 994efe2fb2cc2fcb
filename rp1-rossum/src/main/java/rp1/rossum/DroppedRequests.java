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

/** Where a directly linked client's requests go once its session has ended: nowhere, as over a closed stream. */
enum DroppedRequests implements RequestSink {
    INSTANCE;

    @Override
    public void timeout(double duration, int timeoutIndex) {
    }

    @Override
    public void subscription(RsSubscriptionRequest r) {
    }

    @Override
    public void sensorStatus(RsSensorRequest r) {
    }

    @Override
    public void motion(RsMotionRequest r) {
    }

    @Override
    public void halt(RsHaltRequest r) {
    }

    @Override
    public void position() {
    }

    @Override
    public void setPosition() {
    }

    @Override
    public void placement(RsPlacementRequest r) {
    }

    @Override
    public void targetSelection(RsTargetSelectionRequest r) {
    }

    @Override
    public void plan(RsPlanRequest r) {
    }

    @Override
    public void heartbeat(RsHeartbeatRequest r) {
    }

    @Override
    public void painterChange(RsPainterChangeRequest r) {
    }

    @Override
    public void actuatorControl(RsActuatorControlRequest r) {
    }

    @Override
    public void encoderStatus(RsEncoderStatusRequest r) {
    }
}
