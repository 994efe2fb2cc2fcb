package rp1.bench;

/** Something that does round trips on demand and counts them. */
interface RoundTrips extends AutoCloseable {
    /** Does round trips for {@code seconds} of wall time; returns how many per second. */
    double measure(double seconds) throws Exception;
}
