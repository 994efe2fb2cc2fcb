package rp1.rossum.wire;

/**
 * Upper bounds on the counts a peer may announce. Each is far above what a real robot or floor plan
 * needs and low enough that a hostile count cannot make a reader allocate more than a few megabytes.
 */
public final class WireLimits {
    /** Parts in one body specification. */
    public static final int MAX_BODY_PARTS = 4096;
    /** Vertices in one body-part outline (SEGLIST). */
    public static final int MAX_OUTLINE_VERTICES = 65536;
    /** Wheels in one wheel system. */
    public static final int MAX_WHEELS = 256;
    /** Region codes in one paint sensor's sensitivity list. */
    public static final int MAX_REGIONS = 4096;
    /** Objects in one floor plan. */
    public static final int MAX_PLAN_OBJECTS = 1 << 20;
    /** Doubles in one plan-object geometry (GEOM). */
    public static final int MAX_GEOMETRY_DOUBLES = 1 << 20;
    /** Colours in one COLOR_ARRAY. */
    public static final int MAX_COLORS = 4096;
    /** Parameters in one actuator-control request. */
    public static final int MAX_ACTUATOR_PARAMETERS = 1024;
    /** Encoder ids in one encoder-status request. */
    public static final int MAX_ENCODERS = 4096;
    /**
     * The longest message a non-blocking reader keeps waiting for the rest of (a body of thousands of
     * parts is far shorter), so that what one client makes a server hold stays bounded.
     */
    public static final int MAX_MESSAGE_BYTES = 4 << 20;

    private WireLimits() {
    }
}
