package rp1.rossum;

import java.util.ArrayList;
import java.util.List;

import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsEncoderStatusRequest;
import rp1.rossum.request.RsHaltRequest;
import rp1.rossum.request.RsHeartbeatRequest;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlanRequest;
import rp1.rossum.request.RsRequest;
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.wire.RequestListener;

/** A request sink that records what it was handed, for codec tests. */
final class RecordingSink implements RequestListener {
    final List<String> calls = new ArrayList<>();
    RsRequest last;
    double timeoutDuration;
    int timeoutIndex;

    private void record(String call, RsRequest r) {
        calls.add(call);
        last = r;
    }

    @Override
    public void body(RsBody body) {
        record("body", null);
    }

    @Override
    public void timeout(double duration, int index) {
        timeoutDuration = duration;
        timeoutIndex = index;
        record("timeout", null);
    }

    @Override
    public void subscription(RsSubscriptionRequest r) {
        record("subscription", r);
    }

    @Override
    public void sensorStatus(RsSensorRequest r) {
        record("sensorStatus", r);
    }

    @Override
    public void motion(RsMotionRequest r) {
        record("motion", r);
    }

    @Override
    public void halt(RsHaltRequest r) {
        record("halt", r);
    }

    @Override
    public void position() {
        record("position", null);
    }

    @Override
    public void setPosition() {
        record("setPosition", null);
    }

    @Override
    public void placement(RsPlacementRequest r) {
        record("placement", r);
    }

    @Override
    public void targetSelection(RsTargetSelectionRequest r) {
        record("targetSelection", r);
    }

    @Override
    public void plan(RsPlanRequest r) {
        record("plan", r);
    }

    @Override
    public void heartbeat(RsHeartbeatRequest r) {
        record("heartbeat", r);
    }

    @Override
    public void painterChange(RsPainterChangeRequest r) {
        record("painterChange", r);
    }

    @Override
    public void actuatorControl(RsActuatorControlRequest r) {
        record("actuatorControl", r);
    }

    @Override
    public void encoderStatus(RsEncoderStatusRequest r) {
        record("encoderStatus", r);
    }
}
