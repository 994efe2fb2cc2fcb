package rp1.view;

import rp1.rossum.RsRectangle;
import rp1.rossum.RsTransform;

/**
 * Where the world appears on a canvas of a given pixel size (behavior.md section 10): the plan
 * bounds fitted into the canvas keeping their aspect ratio, 15 pixels less than the limiting side,
 * centred, world +y up; optionally zoomed about the canvas centre. Maps world metres to pixels and
 * back, so a mouse press lands on the floor point drawn under it. Immutable.
 */
public final class ViewTransform {
    /** Pixels the fitted plan leaves free along its limiting side (when the canvas is big enough). */
    static final int MARGIN = 15;

    private final int width;
    private final int height;
    private final double scale;
    private final double originX;
    private final double originY;

    private ViewTransform(int width, int height, double scale, double originX, double originY) {
        this.width = width;
        this.height = height;
        this.scale = scale;
        this.originX = originX;
        this.originY = originY;
    }

    /**
     * The plan bounds fitted into a canvas of {@code width} by {@code height} pixels. The fitted
     * rectangle's corner is floored to whole pixels, as in RP1 0.60.
     *
     * @throws IllegalArgumentException if the canvas has no pixels or the bounds are empty
     */
    public static ViewTransform fit(RsRectangle bounds, int width, int height) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("canvas size must be positive, got " + width + " x " + height);
        }
        if (!(bounds.width > 0.0) || !(bounds.height > 0.0)) {
            throw new IllegalArgumentException("plan bounds must have an area, got " + bounds);
        }
        double aspect = bounds.width / bounds.height;
        double drawnWidth;
        double drawnHeight;
        if (aspect / ((double) width / height) < 1.0) {
            drawnHeight = height > 2 * MARGIN ? height - MARGIN : height;
            drawnWidth = aspect * drawnHeight;
        } else {
            drawnWidth = width > 2 * MARGIN ? width - MARGIN : width;
            drawnHeight = drawnWidth / aspect;
        }
        double left = Math.floor((width - drawnWidth) / 2.0);
        double top = Math.floor((height - drawnHeight) / 2.0);
        double scale = drawnWidth / bounds.width;
        return new ViewTransform(width, height, scale, left - bounds.x * scale,
                top + (bounds.y + bounds.height) * scale);
    }

    /** This view magnified by {@code factor} about the canvas centre (below 1: zoomed out). */
    public ViewTransform zoomed(double factor) {
        if (!(factor > 0.0) || Double.isInfinite(factor)) {
            throw new IllegalArgumentException("zoom factor must be positive and finite, got " + factor);
        }
        double cx = width / 2.0;
        double cy = height / 2.0;
        return new ViewTransform(width, height, scale * factor, cx + (originX - cx) * factor,
                cy + (originY - cy) * factor);
    }

    /** The transform from world metres to pixels (y flipped). */
    public RsTransform worldToPixel() {
        RsTransform t = new RsTransform();
        t.m11 = scale;
        t.m13 = originX;
        t.m22 = -scale;
        t.m23 = originY;
        return t;
    }

    /** The world x (metres) of pixel column {@code px}. */
    public double worldX(double px) {
        return (px - originX) / scale;
    }

    /** The world y (metres) of pixel row {@code py}. */
    public double worldY(double py) {
        return (originY - py) / scale;
    }

    /** The pixel column of world x. */
    public double pixelX(double x) {
        return originX + x * scale;
    }

    /** The pixel row of world y. */
    public double pixelY(double y) {
        return originY - y * scale;
    }

    /** Pixels per metre. */
    public double getScale() {
        return scale;
    }

    /** Canvas width, pixels. */
    public int getWidth() {
        return width;
    }

    /** Canvas height, pixels. */
    public int getHeight() {
        return height;
    }
}
