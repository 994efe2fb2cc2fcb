package rp1.web;

import java.io.IOException;

/** A {@link Wanderer} whose client leaves after its third halt: its robot leaves the floor. */
public class Leaver extends Wanderer {
    private int halts;

    @Override
    public void initialize() throws IOException {
        super.initialize();
        addMotionHaltedEventHandler(e -> {
            if (++halts == 3) {
                shutdown();
            }
        });
    }
}
