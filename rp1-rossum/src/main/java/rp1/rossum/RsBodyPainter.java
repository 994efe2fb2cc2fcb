package rp1.rossum;

import java.awt.Color;

/**
 * A body part that leaves a paint trail on the floor while active: the trail is laid at the trailer
 * point (body coordinates) with the trailer width and the first colour of the colour list. Only the
 * outline is part of the body specification; trailer, width and colours reach the simulator with a
 * painter activation request (protocol.md section 6.12). The trailer counts as defined once its
 * position or width has been set. An active painter is drawn in its hot colours.
 */
public class RsBodyPainter extends RsBodyShape {
    private static final long serialVersionUID = 1L;

    /** Default minimum distance between recorded trail points, metres. */
    static final double DEFAULT_MINIMUM_SEGMENT_LENGTH = 0.01;

    private boolean trailerDefined;
    private double trailerX;
    private double trailerY;
    private double trailerWidth;
    private Color[] paintColors;
    private double minimumSegmentLength = DEFAULT_MINIMUM_SEGMENT_LENGTH;
    private double[] paintPattern;
    private boolean active;

    /** A painter without an outline (nothing to draw or collide with). */
    public RsBodyPainter() {
    }

    /** A painter with the given outline (see {@link RsBodyShape#RsBodyShape(double[], int)}). */
    public RsBodyPainter(double[] bodyPoints, int nPoints) {
        super(bodyPoints, nPoints);
    }

    /** Removes the dash pattern: the trail is continuous. */
    public void removePaintPattern() {
        paintPattern = null;
    }

    /** Forgets the trailer: position and width return to 0 and the trailer is no longer defined. */
    public void removeTrailer() {
        trailerDefined = false;
        trailerX = 0.0;
        trailerY = 0.0;
        trailerWidth = 0.0;
    }

    /** Whether the painter is active (set locally when activation or deactivation is requested). */
    public boolean getPainterActivationStatus() {
        return active;
    }

    /** Marks the painter active or not; an active painter is drawn hot. */
    public void setPainterActivationStatus(boolean active) {
        this.active = active;
        setHot(active);
    }

    /**
     * Sets a dash pattern: the first {@code nPattern} values are alternating painted and unpainted
     * lengths in metres. It is kept on the client only (RP1 0.60 never transmits it).
     */
    public void setPaintPattern(double[] pattern, int nPattern) {
        if (pattern == null || nPattern <= 0) {
            paintPattern = null;
            return;
        }
        paintPattern = new double[Math.min(nPattern, pattern.length)];
        System.arraycopy(pattern, 0, paintPattern, 0, paintPattern.length);
    }

    /** A copy of the dash pattern, or null for a continuous trail. */
    public double[] getPaintPattern() {
        return paintPattern == null ? null : paintPattern.clone();
    }

    /** Sets the trailer point (body coordinates, metres); the trailer becomes defined. */
    public void setTrailerPosition(double x, double y) {
        trailerX = x;
        trailerY = y;
        trailerDefined = true;
    }

    /** Sets the trail width in metres (negative values become 0); the trailer becomes defined. */
    public void setTrailerWidth(double width) {
        trailerWidth = Math.max(0.0, width);
        trailerDefined = true;
    }

    /** Minimum distance between recorded trail points (metres, default 0.01); kept on the client only. */
    public void setTrailerMinimumSegmentLength(double length) {
        minimumSegmentLength = length;
    }

    /** Paints in this one colour (null = no colour). */
    public void setPaintColor(Color color) {
        paintColors = color == null ? null : new Color[] {color};
    }

    /** Paints with this colour list (the trail is drawn in the first colour); null = no colour. */
    public void setPaintColor(Color[] colors) {
        paintColors = RsColor.copyColorList(colors);
    }

    /** Copies the painter settings and activation from another painter. */
    public void copyStateData(RsBodyPainter source) {
        super.copyStateData(source);
        trailerDefined = source.trailerDefined;
        trailerX = source.trailerX;
        trailerY = source.trailerY;
        trailerWidth = source.trailerWidth;
        paintColors = RsColor.copyColorList(source.paintColors);
        minimumSegmentLength = source.minimumSegmentLength;
        paintPattern = source.paintPattern == null ? null : source.paintPattern.clone();
        active = source.active;
    }

    /** Whether setTrailerPosition or setTrailerWidth has been called (since the last removeTrailer). */
    public boolean isTrailerDefined() {
        return trailerDefined;
    }

    /** Trailer point, body coordinates. */
    public double getTrailerX() {
        return trailerX;
    }

    /** Trailer point, body coordinates. */
    public double getTrailerY() {
        return trailerY;
    }

    /** Trail width in metres (never negative). */
    public double getTrailerWidth() {
        return trailerWidth;
    }

    /** A copy of the colour list, or null when no colour is set. */
    public Color[] getPaintColors() {
        return RsColor.copyColorList(paintColors);
    }

    /** Minimum distance between recorded trail points, metres. */
    public double getTrailerMinimumSegmentLength() {
        return minimumSegmentLength;
    }
}
