package rp1demo.clientzero;

import java.util.Locale;

import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsMouseClickEventHandler;

/**
 * A click on the simulator's floor plan gives the robot a goal. Where the robot is matters, so the
 * handler asks for its position; the position handler then starts the motion.
 */
public class ClnMouseClickEventHandler implements RsMouseClickEventHandler {
    private final ClnMain client;

    public ClnMouseClickEventHandler(ClnMain client) {
        this.client = client;
    }

    @Override
    public void process(RsMouseClickEvent event) {
        boolean go = event.button == 0;
        client.log(String.format(Locale.ROOT, "Mouse click at (%.3f, %.3f): %s", event.x, event.y,
                go ? "going there" : "turning to face it"));
        client.getNavigator().clicked(go, event.x, event.y);
        client.sendPositionRequest();
    }
}
