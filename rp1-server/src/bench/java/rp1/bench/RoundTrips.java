package rp1.bench;

import java.io.IOException;

/** Something that does round trips on demand and counts them. */
interface RoundTrips extends AutoCloseable {
    /** Does round trips for {@code seconds} of wall time; returns how many per second. */
    double measure(double seconds) throws Exception;

    /** Releases the connection; closing never waits to be interrupted. */
    @Override
    void close() throws IOException;
}
