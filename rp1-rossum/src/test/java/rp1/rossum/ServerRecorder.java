package rp1.rossum;

import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsActuatorControlRequestHandler;
import rp1.rossum.request.RsEncoderStatusRequest;
import rp1.rossum.request.RsEncoderStatusRequestHandler;
import rp1.rossum.request.RsHaltRequest;
import rp1.rossum.request.RsHaltRequestHandler;
import rp1.rossum.request.RsHeartbeatRequest;
import rp1.rossum.request.RsHeartbeatRequestHandler;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsMotionRequestHandler;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsPainterChangeRequestHandler;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlacementRequestHandler;
import rp1.rossum.request.RsPlanRequest;
import rp1.rossum.request.RsPlanRequestHandler;
import rp1.rossum.request.RsPositionRequestHandler;
import rp1.rossum.request.RsRequest;
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSensorRequestHandler;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.request.RsSubscriptionRequestHandler;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.request.RsTargetSelectionRequestHandler;
import rp1.rossum.request.RsTimeoutRequest;
import rp1.rossum.request.RsTimeoutRequestHandler;

/**
 * Registers itself for every request type on a connection and records what arrives, in order.
 * Timeouts are recorded as an {@code RsTimeoutRequest} built without clamping (see
 * {@link #timeoutDuration}); position requests as the string "position"; bodies as {@code RsBody}.
 */
final class ServerRecorder implements RsTimeoutRequestHandler, RsSubscriptionRequestHandler, RsMotionRequestHandler,
        RsPositionRequestHandler, RsPlacementRequestHandler, RsHaltRequestHandler, RsSensorRequestHandler,
        RsTargetSelectionRequestHandler, RsPainterChangeRequestHandler, RsActuatorControlRequestHandler,
        RsEncoderStatusRequestHandler, RsPlanRequestHandler, RsHeartbeatRequestHandler {
    final Capture<Object> received = new Capture<>();
    volatile double timeoutDuration;

    ServerRecorder(RsConnection c) {
        c.setTimeoutRequestHandler(this);
        c.setSubscriptionRequestHandler(this);
        c.setMotionRequestHandler(this);
        c.setPositionRequestHandler(this);
        c.setPlacementRequestHandler(this);
        c.setHaltRequestHandler(this);
        c.setSensorRequestHandler(this);
        c.setTargetSelectionRequestHandler(this);
        c.setPainterChangeRequestHandler(this);
        c.setActuatorControlRequestHandler(this);
        c.setEncoderStatusRequestHandler(this);
        c.setPlanRequestHandler(this);
        c.setHeartbeatRequestHandler(this);
        c.setBodyHandler(new RsConnectionBodyHandler() {
            @Override
            public void process(RsBody body) {
                received.add(body);
            }
        });
    }

    @Override
    public void processRequest(RsRequest r) {
        received.add(r);
    }

    @Override
    public void process(double duration, int index) {
        timeoutDuration = duration;
        received.add(new RsTimeoutRequest(duration, index));
    }

    @Override
    public void process(RsSubscriptionRequest r) {
        received.add(r);
    }

    @Override
    public void process(RsMotionRequest r) {
        received.add(r);
    }

    @Override
    public void process() {
        received.add("position");
    }

    @Override
    public void process(RsPlacementRequest r) {
        received.add(r);
    }

    @Override
    public void process(RsHaltRequest r) {
        received.add(r);
    }

    @Override
    public void process(RsSensorRequest r) {
        received.add(r);
    }

    @Override
    public void process(RsTargetSelectionRequest r) {
        received.add(r);
    }

    @Override
    public void process(RsPainterChangeRequest r) {
        received.add(r);
    }

    @Override
    public void process(RsActuatorControlRequest r) {
        received.add(r);
    }

    @Override
    public void process(RsEncoderStatusRequest r) {
        received.add(r);
    }

    @Override
    public void process(RsPlanRequest r) {
        received.add(r);
    }

    @Override
    public void process(RsHeartbeatRequest r) {
        received.add(r);
    }
}
