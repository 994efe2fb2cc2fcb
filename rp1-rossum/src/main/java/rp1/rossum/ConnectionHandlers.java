package rp1.rossum;

import java.util.HashSet;
import java.util.Set;

import rp1.rossum.event.RsEvent;
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
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSensorRequestHandler;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.request.RsSubscriptionRequestHandler;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.request.RsTargetSelectionRequestHandler;
import rp1.rossum.request.RsTimeoutRequestHandler;
import rp1.rossum.wire.EventKey;
import rp1.rossum.wire.RequestListener;

/**
 * RP1 0.60's way for a server to take a connection's requests: one handler per request type, set with
 * {@code RsConnection}'s {@code set...Handler} methods, and a subscription table filled from the
 * subscription requests. A connection hands its requests here while no
 * {@link RsConnection#setRequestListener request listener} is set, so programs written for 0.60 keep
 * working; this simulator sets a listener and uses neither the handlers nor the table (it keeps its
 * own subscriptions, {@code rp1.simulator.session.Subscriptions}). A request without a handler is
 * dropped. Handlers may be set from any thread; they run on the thread that decodes the request.
 */
final class ConnectionHandlers implements RequestListener {
    private final RsConnection connection;
    /**
     * Subscriptions as (event code, index) keys. RP1 0.60 kept a fixed table of indices 0..1000, so
     * sensors whose part id exceeded 1000 could never subscribe; a client may give a part any id, so
     * any index is accepted.
     */
    private final Set<Long> subscriptions = new HashSet<>();

    volatile RsTimeoutRequestHandler timeout;
    volatile RsSubscriptionRequestHandler subscription;
    volatile RsMotionRequestHandler motion;
    volatile RsPositionRequestHandler position;
    volatile RsPlacementRequestHandler placement;
    volatile RsHaltRequestHandler halt;
    volatile RsSensorRequestHandler sensor;
    volatile RsTargetSelectionRequestHandler targetSelection;
    volatile RsPainterChangeRequestHandler painterChange;
    volatile RsActuatorControlRequestHandler actuatorControl;
    volatile RsEncoderStatusRequestHandler encoderStatus;
    volatile RsConnectionBodyHandler body;
    volatile RsPlanRequestHandler plan;
    volatile RsHeartbeatRequestHandler heartbeat;

    ConnectionHandlers(RsConnection connection) {
        this.connection = connection;
    }

    /** Records a subscription; event codes outside 0..13 and negative indices are ignored. */
    void setSubscription(int code, int index, boolean value) {
        if (code < 0 || code > RsEvent.EVT_MAX_CODE || index < 0) {
            return;
        }
        synchronized (subscriptions) {
            if (value) {
                subscriptions.add(EventKey.of(code, index));
            } else {
                subscriptions.remove(EventKey.of(code, index));
            }
        }
    }

    boolean isSubscribed(int code, int index) {
        synchronized (subscriptions) {
            return subscriptions.contains(EventKey.of(code, index));
        }
    }

    @Override
    public void body(RsBody b) {
        RsConnectionBodyHandler h = body;
        if (h != null) {
            h.process(b);
        }
    }

    @Override
    public void timeout(double duration, int timeoutIndex) {
        RsTimeoutRequestHandler h = timeout;
        if (h != null) {
            h.process(duration, timeoutIndex);
        }
    }

    /** Timeout, position and placement events are always delivered, so their subscriptions are not recorded. */
    @Override
    public void subscription(RsSubscriptionRequest r) {
        int code = r.eventCode;
        if (code != RsEvent.EVT_TIMEOUT && code != RsEvent.EVT_POSITION && code != RsEvent.EVT_PLACEMENT) {
            setSubscription(code, r.eventIndex, r.eventEnable);
        }
        RsSubscriptionRequestHandler h = subscription;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void sensorStatus(RsSensorRequest r) {
        RsSensorRequestHandler h = sensor;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void motion(RsMotionRequest r) {
        RsMotionRequestHandler h = motion;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void halt(RsHaltRequest r) {
        RsHaltRequestHandler h = halt;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void position() {
        RsPositionRequestHandler h = position;
        if (h != null) {
            h.process();
        }
    }

    @Override
    public void setPosition() {
        connection.verbose("RsConnection: ignoring reserved SetPosition request");
    }

    @Override
    public void placement(RsPlacementRequest r) {
        RsPlacementRequestHandler h = placement;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void targetSelection(RsTargetSelectionRequest r) {
        RsTargetSelectionRequestHandler h = targetSelection;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void plan(RsPlanRequest r) {
        RsPlanRequestHandler h = plan;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void heartbeat(RsHeartbeatRequest r) {
        RsHeartbeatRequestHandler h = heartbeat;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void painterChange(RsPainterChangeRequest r) {
        RsPainterChangeRequestHandler h = painterChange;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void actuatorControl(RsActuatorControlRequest r) {
        RsActuatorControlRequestHandler h = actuatorControl;
        if (h != null) {
            h.process(r);
        }
    }

    @Override
    public void encoderStatus(RsEncoderStatusRequest r) {
        RsEncoderStatusRequestHandler h = encoderStatus;
        if (h != null) {
            h.process(r);
        }
    }
}
