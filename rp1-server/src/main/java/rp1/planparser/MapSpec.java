package rp1.planparser;

/**
 * How to read an occupancy-grid map, after ROS's {@code map_server}: the image, the size of one
 * pixel, where the image's lower-left corner lies and how it is turned, and which pixels are walls.
 *
 * @param image          the image file as written (relative to the file that names it, or absolute)
 * @param resolution     metres per pixel, above zero
 * @param originX        x of the image's lower-left corner, metres
 * @param originY        y of the image's lower-left corner, metres
 * @param yaw            the image's rotation about that corner, radians, anticlockwise
 * @param occupiedThresh a pixel whose occupancy (1 for black, 0 for white) exceeds this is a wall
 * @param freeThresh     below this a pixel is free; between the two it is unknown (also not a wall)
 * @param negate         whether white means occupied
 */
record MapSpec(String image, double resolution, double originX, double originY, double yaw,
               double occupiedThresh, double freeThresh, boolean negate) {
    /** map_server's customary {@code occupied_thresh}. */
    static final double DEFAULT_OCCUPIED = 0.65;
    /** map_server's customary {@code free_thresh}. */
    static final double DEFAULT_FREE = 0.196;

    /**
     * Whether a pixel of this lightness (0 black to 1 white, the mean of its colour channels) is a
     * wall: its occupancy, {@code 1 - lightness} (or the lightness itself when negated), exceeds
     * {@link #occupiedThresh}.
     */
    boolean isOccupied(double lightness) {
        double occupancy = negate ? lightness : 1.0 - lightness;
        return occupancy > occupiedThresh;
    }
}
