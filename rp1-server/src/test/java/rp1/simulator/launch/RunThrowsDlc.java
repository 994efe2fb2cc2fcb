package rp1.simulator.launch;

import java.io.IOException;

import rp1.rossum.RsClient;

/** A loaded client whose run() throws as soon as it is called, after an initialize() that placed its robot. */
public class RunThrowsDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(TestServer.roundBody("short-lived"));
        sendPlacementRequest("p1");
    }

    @Override
    public void run() {
        throw new IllegalStateException("no run today");
    }
}
