package rp1demo.autopilot;

import java.awt.Color;
import java.io.IOException;

import rp1demo.Standalone;
import rp1demo.adapter.ScoutClient;
import rp1demo.navigation.Move;
import rp1demo.navigation.NavNetwork;
import rp1demo.navigation.Pose;

/**
 * The autopilot demo's connection to the simulator: once the floor plan and the "home" placement
 * are in, it hands every finished move to the {@link Tour} and drives the move it answers with,
 * drawing its route with a blue trail.
 */
public class ApMain extends ScoutClient {
    private volatile Tour tour;

    /**
     * Connects to a simulator on the network and runs until it goes away.
     * If it cannot be reached, says so in one line and exits with status 1.
     */
    public static void main(String[] args) {
        Standalone.run(new ApMain());
    }

    /** The no-argument constructor the simulator uses to load the class. */
    public ApMain() {
        super(Color.blue);
    }

    /** The tour, once it has begun (else null). */
    public Tour getTour() {
        return tour;
    }

    @Override
    protected void begin(NavNetwork network, Pose pose) {
        tour = new Tour(network, this::log);
        drive(tour.start(pose), pose);
    }

    @Override
    protected void moveEnded(Pose pose) {
        drive(tour.moveDone(pose), pose);
    }

    @Override
    protected void collided(Pose pose) {
        log("Ran into a wall at " + pose + "; the tour is abandoned");
        liftPen();
    }

    /** Drives the move, or with none left reports that the robot is parked at {@code at}. */
    private void drive(Move m, Pose at) {
        if (m == null) {
            log("Parked at " + at);
            liftPen();
            return;
        }
        drive(m);
    }
}
