package rp1.bench;

import rp1.rossum.RsLogAdapter;

/** A log that drops everything: benchmark clients have nothing to say, least of all when the server stops first. */
final class Quiet extends RsLogAdapter {
    static final Quiet LOG = new Quiet();

    private Quiet() {
    }

    @Override
    public void logIt(String level, String message) {
    }
}
