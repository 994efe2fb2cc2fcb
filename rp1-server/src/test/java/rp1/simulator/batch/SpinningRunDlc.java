package rp1.simulator.batch;

import java.io.InputStream;
import java.io.OutputStream;

import rp1.rossum.RsLogInterface;
import rp1.rossum.RsRunnable;

/** A robot whose {@code run()} computes for ever on the thread the server gave it. */
public class SpinningRunDlc implements RsRunnable {
    @Override
    public void setInputOutputStreams(InputStream input, OutputStream output) {
    }

    @Override
    public void initialize() {
    }

    @Override
    public void setLogger(RsLogInterface logger) {
    }

    @Override
    public void run() {
        SpinningHandlerDlc.spin();
    }
}
