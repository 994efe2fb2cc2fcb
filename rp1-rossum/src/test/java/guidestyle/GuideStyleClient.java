package guidestyle;

import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsClient;
import rp1.rossum.RsRunnable;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionHaltedEventHandler;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsMouseClickEventHandler;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlacementEventHandler;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsPositionEventHandler;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.event.RsTargetSensorEventHandler;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.event.RsTimeoutEventHandler;
import rp1.rossum.request.RsMotionRequest;

/**
 * A client written like the user's guide's ClnMain: extends RsClient, implements RsRunnable, builds
 * its body in initialize(), registers handler classes, asks for the plan and a placement. Mouse
 * clicks steer it towards the clicked point using the wheel system's motion helper.
 */
public class GuideStyleClient extends RsClient implements RsRunnable {
    RsBody body;
    RsPositionEvent lastPosition;
    RsPlacementEvent lastPlacement;
    RsTargetSensorEvent lastTarget;
    RsMotionHaltedEvent lastHalt;
    int timeouts;

    public static void main(String[] args) throws IOException {
        GuideStyleClient c = new GuideStyleClient();
        c.initialize();
        c.run();
    }

    public GuideStyleClient() {
        super();
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        body = Chassis.build();
        sendBodySpecification(body);
        addMouseClickEventHandler(new ClickHandler(this));
        addPositionEventHandler(new PositionHandler(this));
        addPlacementEventHandler(new PlacementHandler(this));
        addMotionHaltedEventHandler(new HaltHandler(this));
        addTargetSensorEventHandler((RsBodyTargetSensor) (body.getPartByName("head")), new HeadHandler(this));
        addTimeoutEventHandler(new TimeoutHandler(this));
        sendPlanRequest();
        sendPlacementRequest("home");
    }

    public RsBody getBody() {
        return body;
    }

    /** Drives to a point given in world coordinates, from the last known pose. */
    void goTo(double x, double y) {
        if (lastPosition == null) {
            return;
        }
        double dx = x - lastPosition.x;
        double dy = y - lastPosition.y;
        double c = Math.cos(lastPosition.orientation);
        double s = Math.sin(lastPosition.orientation);
        RsMotionRequest r = body.wheelSystem.getMotionRequest(c * dx + s * dy, -s * dx + c * dy, 0.3);
        if (r != null) {
            sendMotionRequest(r);
        }
    }

    static final class ClickHandler implements RsMouseClickEventHandler {
        private final GuideStyleClient client;

        ClickHandler(GuideStyleClient client) {
            this.client = client;
        }

        @Override
        public void process(RsMouseClickEvent event) {
            client.goTo(event.x, event.y);
        }
    }

    static final class PositionHandler implements RsPositionEventHandler {
        private final GuideStyleClient client;

        PositionHandler(GuideStyleClient client) {
            this.client = client;
        }

        @Override
        public void process(RsPositionEvent event) {
            client.lastPosition = event;
        }
    }

    static final class PlacementHandler implements RsPlacementEventHandler {
        private final GuideStyleClient client;

        PlacementHandler(GuideStyleClient client) {
            this.client = client;
        }

        @Override
        public void process(RsPlacementEvent event) {
            client.lastPlacement = event;
            client.sendPositionRequest();
        }
    }

    static final class HaltHandler implements RsMotionHaltedEventHandler {
        private final GuideStyleClient client;

        HaltHandler(GuideStyleClient client) {
            this.client = client;
        }

        @Override
        public void process(RsMotionHaltedEvent event) {
            client.lastHalt = event;
        }
    }

    static final class HeadHandler implements RsTargetSensorEventHandler {
        private final GuideStyleClient client;

        HeadHandler(GuideStyleClient client) {
            this.client = client;
        }

        @Override
        public void process(RsTargetSensorEvent event) {
            client.lastTarget = event;
        }
    }

    static final class TimeoutHandler implements RsTimeoutEventHandler {
        private final GuideStyleClient client;

        TimeoutHandler(GuideStyleClient client) {
            this.client = client;
        }

        @Override
        public void process(RsTimeoutEvent event) {
            client.timeouts++;
        }
    }
}
