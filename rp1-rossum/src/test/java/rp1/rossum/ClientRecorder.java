package rp1.rossum;

import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.event.RsEncoderStatusEventHandler;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsHeartbeatEventHandler;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionHaltedEventHandler;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsMotionStartedEventHandler;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsMouseClickEventHandler;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlacementEventHandler;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsPlanEventHandler;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsPositionEventHandler;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.event.RsTargetSelectionEventHandler;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.event.RsTimeoutEventHandler;

/** Registers a handler for every non-sensor event type on a client and records the events, in order. */
final class ClientRecorder implements RsMouseClickEventHandler, RsPositionEventHandler, RsTimeoutEventHandler,
        RsMotionStartedEventHandler, RsMotionHaltedEventHandler, RsPlacementEventHandler,
        RsTargetSelectionEventHandler, RsPlanEventHandler, RsHeartbeatEventHandler, RsEncoderStatusEventHandler {
    final Capture<RsEvent> events = new Capture<>();

    ClientRecorder(RsClient c) {
        c.addMouseClickEventHandler(this);
        c.addPositionEventHandler(this);
        c.addTimeoutEventHandler(this);
        c.addMotionStartedEventHandler(this);
        c.addMotionHaltedEventHandler(this);
        c.addPlacementEventHandler(this);
        c.addTargetSelectionEventHandler(this);
        c.addPlanEventHandler(this);
        c.addHeartbeatEventHandler(this);
        c.addEncoderStatusEventHandler(this);
    }

    @Override
    public void process(RsMouseClickEvent e) {
        events.add(e);
    }

    @Override
    public void process(RsPositionEvent e) {
        events.add(e);
    }

    @Override
    public void process(RsTimeoutEvent e) {
        events.add(e);
    }

    @Override
    public void process(RsMotionStartedEvent e) {
        events.add(e);
    }

    @Override
    public void process(RsMotionHaltedEvent e) {
        events.add(e);
    }

    @Override
    public void process(RsPlacementEvent e) {
        events.add(e);
    }

    @Override
    public void process(RsTargetSelectionEvent e) {
        events.add(e);
    }

    @Override
    public void process(RsPlanEvent e) {
        events.add(e);
    }

    @Override
    public void process(RsHeartbeatEvent e) {
        events.add(e);
    }

    @Override
    public void process(RsEncoderStatusEvent e) {
        events.add(e);
    }
}
