package guidestyle;

// The example client of docs/guide.md section 3, kept here so that it must compile.

import java.awt.Color;
import java.io.IOException;

import rp1.rossum.*;
import rp1.rossum.event.*;
import rp1.rossum.request.RsMotionRequest;

public class GuideBumper extends RsClient implements RsRunnable {
    private RsBody body;

    public static void main(String[] args) throws IOException {
        GuideBumper b = new GuideBumper();
        b.initialize();
        b.run();
    }

    public GuideBumper() {               // the simulator loads clients through this constructor
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        body = build();
        sendBodySpecification(body);
        addPlacementEventHandler(e -> drive());
        addMotionHaltedEventHandler(e -> {
            // Bumped, or blocked before it could start (duration 0: see "A motion that cannot start"
            // below; asking again at once would be blocked again, for ever): back off while turning.
            // A turn on the spot would not do: the chassis is a polygon of many sides, whose corners
            // sweep out a little as it turns, into what it has just touched.
            if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION || e.duration == 0.0) {
                log("stopped at " + e.x + ", " + e.y + "; backing off");
                sendMotionRequest(new RsMotionRequest(-0.1, Math.PI / 2, 1.0));   // 10 cm back, a quarter turn
            } else {
                drive();
            }
        });
        sendPlacementRequest("home");
    }

    private void drive() {
        sendMotionRequest(new RsMotionRequest(0.3, 0.0, 10.0));   // 0.3 m/s straight ahead for 10 s
    }

    static RsBody build() {
        RsBody body = new RsBody("GuideBumper");
        RsDifferentialSteering wheels = new RsDifferentialSteering(0.18, 0.05);
        wheels.addDefaultWheels(0.05, 0.02);           // right after the wheel system: see below
        RsBodyCircle chassis = new RsBodyCircle(0.0, 0.0, 0.12);
        chassis.setName("chassis");
        chassis.setFillColor(Color.orange);
        body.addPart(chassis);
        body.addPart(wheels);
        return body;
    }
}
