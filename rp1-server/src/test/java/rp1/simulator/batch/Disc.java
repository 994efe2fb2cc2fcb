package rp1.simulator.batch;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;

/** The body of the sweeps' test robots: a named disc, and nothing else. */
final class Disc {
    private Disc() {
    }

    static RsBody named(String name, double radius) {
        RsBody body = new RsBody(name);
        body.addPart(new RsBodyCircle(0.0, 0.0, radius));
        return body;
    }
}
