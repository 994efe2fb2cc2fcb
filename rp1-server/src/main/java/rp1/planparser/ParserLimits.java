package rp1.planparser;

/**
 * Sizes beyond which a floor plan is rejected rather than read. Each is far above what a real plan
 * needs and keeps a hostile or corrupted file from exhausting memory, producing a plan that cannot be
 * transmitted (strings are limited to 65535 bytes on the wire), or making the polygon check slow.
 */
final class ParserLimits {
    /** Characters in one identifier, string or number (at most 3 wire bytes each, so under 65535). */
    static final int MAX_TOKEN_LENGTH = 20_000;
    /** Numbers in one numeric list (a polygon of 50000 vertices). */
    static final int MAX_LIST_NUMBERS = 100_000;
    /** Objects in one plan; the protocol layer refuses more. */
    static final int MAX_OBJECTS = 1 << 20;
    /**
     * Metres from the origin, along x and along y, within which every length and every object of a plan
     * lies (1000 km: no building comes near it). It bounds the plan's extent to 2000 km a side, which
     * keeps the simulator's arithmetic and its spatial indexes sound.
     */
    static final double MAX_COORDINATE = 1.0e6;

    /** Characters of a map_server YAML file (real ones are a few hundred). */
    static final int MAX_MAP_FILE = 1 << 16;

    private ParserLimits() {
    }
}
