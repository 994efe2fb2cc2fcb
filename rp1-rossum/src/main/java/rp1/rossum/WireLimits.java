package rp1.rossum;

/**
 * Upper bounds on the counts a peer may announce. Each is far above what a real robot or floor plan
 * needs and low enough that a hostile count cannot make a reader allocate more than a few megabytes.
 */
final class WireLimits {
    /** Parts in one body specification. */
    static final int MAX_BODY_PARTS = 4096;
    /** Vertices in one body-part outline (SEGLIST). */
    static final int MAX_OUTLINE_VERTICES = 65536;
    /** Wheels in one wheel system. */
    static final int MAX_WHEELS = 256;
    /** Region codes in one paint sensor's sensitivity list. */
    static final int MAX_REGIONS = 4096;
    /** Objects in one floor plan. */
    static final int MAX_PLAN_OBJECTS = 1 << 20;
    /** Doubles in one plan-object geometry (GEOM). */
    static final int MAX_GEOMETRY_DOUBLES = 1 << 20;
    /** Colours in one COLOR_ARRAY. */
    static final int MAX_COLORS = 4096;
    /** Parameters in one actuator-control request. */
    static final int MAX_ACTUATOR_PARAMETERS = 1024;
    /** Encoder ids in one encoder-status request. */
    static final int MAX_ENCODERS = 4096;
    /**
     * The longest message a non-blocking reader keeps waiting for the rest of (a body of thousands of
     * parts is far shorter), so that what one client makes a server hold stays bounded.
     */
    static final int MAX_MESSAGE_BYTES = 4 << 20;

    private WireLimits() {
    }
}
