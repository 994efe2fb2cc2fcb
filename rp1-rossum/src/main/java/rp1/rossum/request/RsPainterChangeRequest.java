package rp1.rossum.request;

import java.awt.Color;

/**
 * Turn a painter body part on or off, or erase its trail. On activation it carries the trailer point
 * (body coordinates), the trail width and the colours.
 */
public class RsPainterChangeRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** Part id of the painter. */
    public final int painterID;
    /** True to erase the painter's trail (the other fields are then meaningless). */
    public final boolean erasure;
    /** True to start painting, false to stop. */
    public final boolean activation;
    /** Whether the trailer fields below carry values (only when activating). */
    public final boolean trailerDefined;
    /** Trailer point, body coordinates, metres. */
    public final double xTrailer;
    /** Trailer point, body coordinates, metres. */
    public final double yTrailer;
    /** Trail width, metres. */
    public final double wTrailer;
    /** Trail colours (the first one is drawn), or null. */
    public final Color[] color;

    /** When {@code activation} is false the trailer fields are stored as false, 0 and null. */
    public RsPainterChangeRequest(int painterID, boolean erasure, boolean activation, boolean trailerDefined,
                                  double xTrailer, double yTrailer, double wTrailer, Color[] color) {
        super(REQ_PAINTER_CHANGE);
        this.painterID = painterID;
        this.erasure = erasure;
        this.activation = activation;
        this.trailerDefined = activation && trailerDefined;
        this.xTrailer = activation ? xTrailer : 0.0;
        this.yTrailer = activation ? yTrailer : 0.0;
        this.wTrailer = activation ? wTrailer : 0.0;
        this.color = activation ? color : null;
    }
}
