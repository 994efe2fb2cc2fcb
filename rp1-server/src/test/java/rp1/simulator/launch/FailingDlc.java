package rp1.simulator.launch;

import java.io.IOException;

import rp1.rossum.RsClient;

/** A dynamically loaded client whose initialize() fails. */
public class FailingDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        throw new IOException("no robot today");
    }
}
