package rp1demo.clientzero;

import java.util.Locale;

import rp1.rossum.RsWheelSystem;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsPositionEventHandler;
import rp1.rossum.request.RsMotionRequest;
import rp1demo.adapter.Poses;
import rp1demo.navigation.Pose;

/**
 * With the robot's position known, turns a waiting click into a motion: an arc that ends on the
 * clicked point, or a turn on the spot towards it, both worked out by the wheel system's helpers.
 * (Using the true position is cheating, as the guide admits: it keeps the demo short.)
 */
public class ClnPositionEventHandler implements RsPositionEventHandler {
    private final ClnMain client;

    public ClnPositionEventHandler(ClnMain client) {
        this.client = client;
    }

    @Override
    public void process(RsPositionEvent event) {
        Pose pose = Poses.of(event);
        ClnNavigator.Aim aim = client.getNavigator().aimFrom(pose);
        if (aim == null) {
            client.log("Position " + pose);
            return;
        }
        RsWheelSystem wheels = client.getBody().wheelSystem;
        RsMotionRequest request = aim.go()
                ? wheels.getMotionRequest(aim.x(), aim.y(), ClnMain.SPEED)
                : wheels.getMotionRequestForPivot(aim.x(), aim.y(), ClnMain.SPEED);
        if (request == null) {
            client.log("Already there");
            return;
        }
        client.log(String.format(Locale.ROOT, "From %s: %.3f m/s, %.3f rad/s for %.2f s", pose,
                request.linearVelocity, request.rotationalVelocity, request.duration));
        client.sendMotionRequest(request);
    }
}
