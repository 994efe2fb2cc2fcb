package rp1demo.clientzero;

import java.util.Locale;

import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.event.RsTargetSensorEventHandler;
import rp1demo.adapter.Poses;

/** Reports what the "head" sees: a target coming into view (and where it is), or losing it. */
public class ClnTargetSensorEventHandler implements RsTargetSensorEventHandler {
    private final ClnMain client;

    public ClnTargetSensorEventHandler(ClnMain client) {
        this.client = client;
    }

    @Override
    public void process(RsTargetSensorEvent event) {
        if (!event.status) {
            client.log("Head: no target in sight");
            return;
        }
        double[] at = Poses.targetPosition(event);
        client.log(String.format(Locale.ROOT, "Head: target %s at range %.3f m, bearing %.1f deg, so at (%.3f, %.3f)",
                event.getNameOfObjectDetected(), event.range, Math.toDegrees(event.bearing), at[0], at[1]));
    }
}
