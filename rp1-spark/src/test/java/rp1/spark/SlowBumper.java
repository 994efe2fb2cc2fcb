package rp1.spark;

import java.io.IOException;

import rp1demo.bumper.Bumper;

/**
 * The bumper car, taking a fifth of a second of wall time to start: the same run in simulated time,
 * long enough in wall time for a test to kill a worker while a sweep's runs are going.
 */
public class SlowBumper extends Bumper {
    @Override
    public void initialize() throws IOException {
        try {
            Thread.sleep(200);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        super.initialize();
    }
}
