package rp1.view;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.util.Arrays;

/**
 * A rectangle of an RGB picture on which trails and their marks are painted, antialiased as Java 2D
 * draws them: polylines stroked with round caps and joins, discs and rings. Each pixel is shaded by the
 * distance of its centre from the shape's middle line (or its centre, or its circle): fully within half
 * the shape's width less half a pixel, not at all beyond half its width plus half a pixel, linearly
 * between, which puts as much colour across the shape as its width. A shape is shaded once where it
 * meets itself (a polyline at its joins and crossings), and laid over the picture in its colour's alpha.
 *
 * <p>Why not Java 2D: a sweep's summary picture paints every run's trails and marks once, after the
 * last run, with Java 2D's rasterizer run before only for the warm-up's few shapes. The 64 runs of a
 * bumper sweep (2,400 legs, 192 marks) took about 70 ms of processor time there, most of it that
 * rasterizer's code run for the first time, and the picture is what a sweep's end waits for. This is a
 * few small loops, which the warm-up gets compiled ({@link #warmUp}): 10–15 ms for the same.
 */
final class TrailCanvas {
    /** Room for this many pixels of one shape before the list of them grows. */
    private static final int FIRST_ROOM = 1024;

    private final int[] pixels;
    private final int stride;
    private final int left;
    private final int top;
    private final int width;
    private final int height;
    /** The shape being painted: how much it covers each pixel of the rectangle so far (0 where none). */
    private final float[] cover;
    /** The pixels the shape covers, by their index in {@link #cover}, in the order first covered. */
    private int[] covered = new int[FIRST_ROOM];
    private int coveredCount;

    /**
     * A canvas on the rectangle of {@code image} ({@link BufferedImage#TYPE_INT_RGB}, not a subimage) at
     * ({@code left}, {@code top}), {@code width} by {@code height} pixels; a shape's coordinates are
     * pixels from the rectangle's corner, and what lies outside the rectangle is clipped.
     *
     * @throws IllegalArgumentException if the image does not hold its pixels as one packed RGB array, or
     *         the rectangle is not inside it
     */
    TrailCanvas(BufferedImage image, int left, int top, int width, int height) {
        int[] inPlace = Pictures.rgbPixelsInPlace(image);
        if (inPlace == null) {
            throw new IllegalArgumentException("trails are painted on a packed RGB picture, not " + image);
        }
        if (left < 0 || top < 0 || width < 0 || height < 0 || left + width > image.getWidth()
                || top + height > image.getHeight()) {
            throw new IllegalArgumentException("the rectangle " + width + "x" + height + " at " + left + "," + top
                    + " is not inside the picture of " + image.getWidth() + "x" + image.getHeight());
        }
        this.pixels = inPlace;
        this.stride = image.getWidth();
        this.left = left;
        this.top = top;
        this.width = width;
        this.height = height;
        this.cover = new float[width * height];
    }

    /**
     * Paints on a small picture of its own what a summary picture paints, enough times for the loops to
     * be compiled: {@link SweepPicture#warmUp} calls this while a sweep is prepared and its first run goes.
     */
    static void warmUp() {
        BufferedImage image = new BufferedImage(64, 64, BufferedImage.TYPE_INT_RGB);
        TrailCanvas canvas = new TrailCanvas(image, 0, 0, 64, 64);
        Color faint = new Color(200, 30, 30, 40);
        for (int i = 0; i < 80; i++) {
            double a = 0.37 * i;
            canvas.stroke(new double[] {32, 32, 32 + 30 * Math.cos(a), 32 + 30 * Math.sin(a), 5 + i % 50, 60 - i % 40},
                    1.6, faint);
            canvas.ring(5 + i % 50, 7 + i % 45, 4, 1.5, Color.darkGray);
            canvas.dot(60 - i % 50, 5 + i % 45, 4, Color.white);
        }
    }

    /**
     * Strokes the polyline {@code x0, y0, x1, y1, ...} ({@code lineWidth} pixels wide) in {@code colour};
     * fewer than two points paint nothing, as with Java 2D. Legs with a coordinate that is not finite
     * are left out.
     */
    void stroke(double[] xy, double lineWidth, Color colour) {
        double reach = lineWidth / 2.0 + 0.5;
        int points = xy.length / 2;
        for (int i = 1; i < points; i++) {
            leg(xy[2 * i - 2], xy[2 * i - 1], xy[2 * i], xy[2 * i + 1], reach);
        }
        blend(colour);
    }

    /** Fills the disc of {@code radius} about (x, y) in {@code colour}. */
    void dot(double x, double y, double radius, Color colour) {
        round(x, y, 0.0, radius + 0.5);
        blend(colour);
    }

    /** Draws the circle of {@code radius} about (x, y) as a line {@code lineWidth} wide in {@code colour}. */
    void ring(double x, double y, double radius, double lineWidth, Color colour) {
        round(x, y, radius, lineWidth / 2.0 + 0.5);
        blend(colour);
    }

    /**
     * Covers the pixels whose centres are within {@code reach} of the segment (ax, ay)-(bx, by). It works
     * in coordinates (u, v) with u along the leg's longer direction: at each column of pixels across
     * u, the leg's capsule spans at most reach * sqrt(1 + slope^2) either way of the leg's point there
     * (its clamped end beyond the ends), so the few pixels within that span are all it looks at.
     */
    private void leg(double ax, double ay, double bx, double by, double reach) {
        if (!(Double.isFinite(ax) && Double.isFinite(ay) && Double.isFinite(bx) && Double.isFinite(by))) {
            return;
        }
        boolean alongX = Math.abs(bx - ax) >= Math.abs(by - ay);
        double u0 = alongX ? ax : ay;
        double v0 = alongX ? ay : ax;
        double du = alongX ? bx - ax : by - ay;
        double dv = alongX ? by - ay : bx - ax;
        int uCount = alongX ? width : height;
        int vCount = alongX ? height : width;
        int uStep = alongX ? 1 : width;
        int vStep = alongX ? width : 1;
        double slope = du == 0.0 ? 0.0 : dv / du;
        double across = reach * Math.sqrt(1.0 + slope * slope);
        double lengthSquared = du * du + dv * dv;
        double inverse = lengthSquared == 0.0 ? 0.0 : 1.0 / lengthSquared;
        double reachSquared = reach * reach;
        int first = Math.max(0, firstCentreFrom(Math.min(u0, u0 + du) - reach));
        int last = Math.min(uCount - 1, lastCentreTo(Math.max(u0, u0 + du) + reach));
        for (int u = first; u <= last; u++) {
            double ru = u + 0.5 - u0;
            double v = v0 + (du == 0.0 ? 0.0 : clamp(ru / du)) * dv;
            int from = Math.max(0, firstCentreFrom(v - across));
            int to = Math.min(vCount - 1, lastCentreTo(v + across));
            for (int w = from; w <= to; w++) {
                double rv = w + 0.5 - v0;
                double t = clamp((ru * du + rv * dv) * inverse);
                double eu = ru - t * du;
                double ev = rv - t * dv;
                double d2 = eu * eu + ev * ev;
                if (d2 < reachSquared) {
                    shade(u * uStep + w * vStep, reach - Math.sqrt(d2));
                }
            }
        }
    }

    /**
     * Covers the pixels whose centres are within {@code reach} of the circle of {@code radius} about
     * (x, y) (of the point itself for a radius of 0).
     */
    private void round(double x, double y, double radius, double reach) {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(radius) && Double.isFinite(reach))) {
            return;
        }
        double outer = radius + reach;
        int c0 = Math.max(0, firstCentreFrom(x - outer));
        int c1 = Math.min(width - 1, lastCentreTo(x + outer));
        int r0 = Math.max(0, firstCentreFrom(y - outer));
        int r1 = Math.min(height - 1, lastCentreTo(y + outer));
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                double dx = c + 0.5 - x;
                double dy = r + 0.5 - y;
                double off = Math.abs(Math.sqrt(dx * dx + dy * dy) - radius);
                if (off < reach) {
                    shade(r * width + c, reach - off);
                }
            }
        }
    }

    private static double clamp(double t) {
        return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    }

    /** The first pixel whose centre is at or after {@code at} (-1 for any before the first). */
    private static int firstCentreFrom(double at) {
        return (int) Math.max(-1.0, Math.ceil(at - 0.5));
    }

    /** The last pixel whose centre is at or before {@code at}. */
    private static int lastCentreTo(double at) {
        return (int) Math.min(Integer.MAX_VALUE - 1, Math.floor(at - 0.5));
    }

    /** Notes that the shape covers pixel {@code index} of the rectangle by {@code amount} (more than 0; 1 or more is all). */
    private void shade(int index, double amount) {
        float was = cover[index];
        float now = (float) Math.min(1.0, amount);
        if (now > was) {
            if (was == 0.0f) {
                if (coveredCount == covered.length) {
                    covered = Arrays.copyOf(covered, 2 * coveredCount);
                }
                covered[coveredCount++] = index;
            }
            cover[index] = now;
        }
    }

    /** Lays the shape over the picture in {@code colour} as far as it covers each pixel, and clears it. */
    private void blend(Color colour) {
        int r = colour.getRed();
        int g = colour.getGreen();
        int b = colour.getBlue();
        float alpha = colour.getAlpha() / 255.0f;
        for (int i = 0; i < coveredCount; i++) {
            int index = covered[i];
            float a = alpha * cover[index];
            cover[index] = 0.0f;
            int row = index / width;
            int at = (top + row) * stride + left + index - row * width;
            int p = pixels[at];
            pixels[at] = mix(p >> 16 & 0xff, r, a) << 16 | mix(p >> 8 & 0xff, g, a) << 8 | mix(p & 0xff, b, a);
        }
        coveredCount = 0;
    }

    private static int mix(int under, int over, float a) {
        return Math.round(under + (over - under) * a);
    }
}
