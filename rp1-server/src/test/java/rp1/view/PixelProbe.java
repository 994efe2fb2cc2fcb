package rp1.view;

import java.awt.Color;
import java.awt.image.BufferedImage;

import rp1.rossum.RsPoint;
import rp1.rossum.RsTransform;

/** Reads the colour a picture has at a world point. */
final class PixelProbe {
    private final BufferedImage image;
    private final ViewTransform view;

    PixelProbe(BufferedImage image, ViewTransform view) {
        this.image = image;
        this.view = view;
    }

    /** The colour at world point (x, y). */
    Color at(double x, double y) {
        return new Color(image.getRGB((int) Math.round(view.pixelX(x)), (int) Math.round(view.pixelY(y))));
    }

    /** The colour at body point (bx, by) of a body at {@code pose}. */
    Color atBody(RsTransform pose, double bx, double by) {
        RsPoint p = pose.map(bx, by);
        return at(p.x, p.y);
    }

    /** Whether a pixel within {@code radius} pixels of world point (x, y) has colour {@code c}. */
    boolean near(double x, double y, int radius, Color c) {
        int px = (int) Math.round(view.pixelX(x));
        int py = (int) Math.round(view.pixelY(y));
        for (int dy = -radius; dy <= radius; dy++) {
            for (int dx = -radius; dx <= radius; dx++) {
                if (image.getRGB(px + dx, py + dy) == c.getRGB()) {
                    return true;
                }
            }
        }
        return false;
    }
}
