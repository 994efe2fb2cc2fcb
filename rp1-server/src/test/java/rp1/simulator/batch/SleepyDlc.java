package rp1.simulator.batch;

import java.io.InputStream;
import java.io.OutputStream;

import rp1.rossum.RsLogInterface;
import rp1.rossum.RsRunnable;

/** A loaded client that never finishes and never places a robot: its run only ends when it is stopped. */
public class SleepyDlc implements RsRunnable {
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
        try {
            Thread.sleep(Long.MAX_VALUE);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
