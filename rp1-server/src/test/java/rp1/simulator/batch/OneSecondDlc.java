package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsClient;

/** A test robot, a disc placed at "home", that misbehaves in its handler one simulated second later. */
abstract class OneSecondDlc extends RsClient {
    private final String name;

    OneSecondDlc(String name) {
        this.name = name;
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(Disc.named(name, 0.1));
        addTimeoutEventHandler(e -> atOneSecond());
        sendPlacementRequest("home");
        sendTimeoutRequest(1.0);
    }

    /** What the robot does one simulated second after it is placed, called by the simulation itself. */
    abstract void atOneSecond();
}
