package rp1.view;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.SinglePixelPackedSampleModel;
import java.awt.image.WritableRaster;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import rp1.io.WholeFiles;
import rp1.rossum.RsPoint;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsTransform;
import rp1.simulator.outcome.Trail;
import rp1.simulator.snapshot.WorldSnapshot;

/** Pictures of the world drawn into images instead of a window; works with no display at all. */
public final class Pictures {
    /** Pixels along the longer side of a picture file. */
    public static final int LONG_SIDE = 800;
    /** Pixels of the band under a picture of a run that holds its simulated time and a scale bar. */
    public static final int CAPTION_BAND = 24;
    /** The robots' paths: thin, dark and half transparent, so the robots show through where they stand. */
    private static final Color PATH_COLOR = new Color(40, 40, 40, 140);

    private Pictures() {
    }

    /**
     * The size of a picture of a plan with these bounds: {@link #LONG_SIDE} pixels along the plan's
     * longer side, the other side just large enough for the plan plus the view's margin.
     */
    public static Dimension sizeFor(RsRectangle bounds) {
        return sizeFor(bounds, LONG_SIDE);
    }

    /** The size of a picture of a plan with these bounds with {@code longSide} pixels along its longer side. */
    public static Dimension sizeFor(RsRectangle bounds, int longSide) {
        int inner = longSide - ViewTransform.MARGIN;
        if (bounds.width >= bounds.height) {
            return new Dimension(longSide, (int) Math.round(inner * bounds.height / bounds.width) + ViewTransform.MARGIN);
        }
        return new Dimension((int) Math.round(inner * bounds.width / bounds.height) + ViewTransform.MARGIN, longSide);
    }

    /** Draws {@code snapshot} into a new RGB image of the given size. */
    public static BufferedImage render(Renderer renderer, WorldSnapshot snapshot, int width, int height) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            renderer.render(snapshot, g, width, height);
        } finally {
            g.dispose();
        }
        return image;
    }

    /** Draws {@code snapshot} at {@link #sizeFor the picture size} of its plan. */
    public static BufferedImage render(Renderer renderer, WorldSnapshot snapshot) {
        Dimension size = sizeFor(renderer.getPlan().getBounds());
        return render(renderer, snapshot, size.width, size.height);
    }

    /**
     * Draws {@code snapshot} as a picture of a run: the world at {@link #sizeFor the picture size} of
     * its plan (so a point is where it is in a plain picture) with the path every robot took so far,
     * and under it a band of {@link #CAPTION_BAND} pixels with the simulated time and a scale bar, so
     * that a picture found in a folder says what happened, when it was taken and how large things are.
     */
    public static BufferedImage renderCaptioned(Renderer renderer, WorldSnapshot snapshot, List<Trail> paths) {
        Dimension size = sizeFor(renderer.getPlan().getBounds());
        BufferedImage image = new BufferedImage(size.width, size.height + CAPTION_BAND, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            ViewTransform view = ViewTransform.fit(renderer.getPlan().getBounds(), size.width, size.height);
            renderer.render(snapshot, g, view);
            drawPaths(g, paths, view.worldToPixel());
            g.setColor(Color.white);
            g.fillRect(0, size.height, size.width, CAPTION_BAND);
            g.setColor(Color.darkGray);
            int baseline = size.height + CAPTION_BAND - 8;
            g.drawString(String.format(Locale.ROOT, "t = %.3f s", snapshot.simTime()), ViewTransform.MARGIN, baseline);
            drawScaleBar(g, view.worldToPixel().m11, size.width - ViewTransform.MARGIN, size.height + CAPTION_BAND / 2,
                    size.width / 5.0, baseline);
        } finally {
            g.dispose();
        }
        return image;
    }

    private static void drawPaths(Graphics2D g, List<Trail> paths, RsTransform worldToPixel) {
        g.setColor(PATH_COLOR);
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        for (Trail t : paths) {
            for (double[] piece : t.pieces()) {
                Path2D.Double line = new Path2D.Double();
                for (int i = 0; i + 1 < piece.length; i += 2) {
                    RsPoint p = worldToPixel.map(piece[i], piece[i + 1]);
                    if (i == 0) {
                        line.moveTo(p.x, p.y);
                    } else {
                        line.lineTo(p.x, p.y);
                    }
                }
                g.draw(line);
            }
        }
        g.setStroke(new BasicStroke());
    }

    /**
     * A bar of a round length (1, 2 or 5 times a power of ten metres) of at most {@code maxPixels},
     * ending at x = {@code right}, with its length written to its left.
     */
    private static void drawScaleBar(Graphics2D g, double pixelsPerMetre, int right, int y, double maxPixels,
                                     int baseline) {
        double metres = roundLength(maxPixels / pixelsPerMetre);
        int left = right - (int) Math.round(metres * pixelsPerMetre);
        g.drawLine(left, y, right, y);
        g.drawLine(left, y - 4, left, y + 4);
        g.drawLine(right, y - 4, right, y + 4);
        String label = metres >= 1.0 ? String.format(Locale.ROOT, "%.0f m", metres)
                : String.format(Locale.ROOT, "%.0f cm", metres * 100.0);
        g.drawString(label, left - 6 - g.getFontMetrics().stringWidth(label), baseline);
    }

    /** The largest of 1, 2 and 5 times a power of ten that is at most {@code limit} (which is positive). */
    static double roundLength(double limit) {
        double power = Math.pow(10.0, Math.floor(Math.log10(limit)));
        for (double m : new double[] {5.0, 2.0, 1.0}) {
            if (m * power <= limit) {
                return m * power;
            }
        }
        return power;
    }

    /**
     * The pixels of an RGB picture as its raster holds them, row after row with nothing between rows,
     * so that writing one changes the picture; null for a picture that does not hold them so (another
     * type, or a subimage, which shares its parent's array with an offset and longer rows).
     */
    static int[] rgbPixelsInPlace(BufferedImage image) {
        WritableRaster raster = image.getRaster();
        if (image.getType() == BufferedImage.TYPE_INT_RGB && raster.getParent() == null
                && raster.getDataBuffer() instanceof DataBufferInt d && d.getOffset() == 0
                && raster.getSampleModel() instanceof SinglePixelPackedSampleModel m
                && m.getScanlineStride() == image.getWidth()) {
            return d.getData();
        }
        return null;
    }

    /**
     * Writes {@code image} as a PNG file, replacing it whole: readers (a CI job, an image viewer)
     * never see a half-written picture. It is written as {@code NAME.part} and renamed; if it cannot
     * be written (a full disk) the {@code .part} is removed and the error thrown.
     */
    public static void writePng(BufferedImage image, Path file) throws IOException {
        Path absolute = file.toAbsolutePath();
        Path dir = absolute.getParent();
        if (dir != null) {
            Files.createDirectories(dir);
        }
        WholeFiles.write(absolute, part -> {
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(part), 1 << 16)) {
                PngEncoder.write(image, out);
            }
        });
    }
}
