package rp1.simulator;

import rp1.rossum.event.RsMouseClickEvent;
import rp1.simulator.session.ClientSession;

/**
 * What the view asks of a simulation, as data: a recording writes it down and a replay applies it
 * again. Applied at a boundary between tasks like every other input ({@link ViewInput}).
 */
public sealed interface ViewAction {
    /** Applies the action to {@code simulation} at {@code simTime}, on the thread running tasks. */
    void applyTo(Simulation simulation, double simTime);

    /**
     * A mouse press at world point (x, y): every client with a robot that subscribed to mouse clicks
     * gets the event, stamped with the time the press is applied.
     */
    record MouseClick(int button, int clickCount, double x, double y) implements ViewAction {
        @Override
        public void applyTo(Simulation simulation, double simTime) {
            RsMouseClickEvent e = new RsMouseClickEvent(simTime, button, clickCount, x, y);
            for (ClientSession s : simulation.getSessions()) {
                if (s.getRobot() != null) {
                    s.sendIfSubscribed(e);
                }
            }
        }
    }

    /** Clears every paint trail (the view's "Remove Paint Trails"). */
    record RemovePaintTrails() implements ViewAction {
        @Override
        public void applyTo(Simulation simulation, double simTime) {
            simulation.getWorld().removePaintTrails();
        }
    }
}
