package rp1.spark;

import java.io.IOException;

import rp1.rossum.RsClient;

/** A robot that fails as it starts: every run of it fails by itself, wherever it runs. */
public class FailingRobot extends RsClient {
    @Override
    public void initialize() throws IOException {
        throw new IOException("this robot always fails");
    }
}
