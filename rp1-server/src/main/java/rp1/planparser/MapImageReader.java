package rp1.planparser;

import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.IndexColorModel;
import java.awt.image.Raster;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.Iterator;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import javax.imageio.stream.MemoryCacheImageInputStream;

/**
 * Reads a map image into its occupied cells: PGM with {@link PgmReader}, anything else (PNG above all)
 * with {@code javax.imageio}. This is the one class of the plan parser that touches
 * {@code java.awt.image}, and only to read pixel values, which works headless (ArchitectureTest keeps
 * image decoding here).
 *
 * <p>A pixel's lightness is the mean of its colour channels, each scaled to 0..1 from its own bit
 * depth, read from the raster and not through {@code getRGB}, which would put grey images through a
 * colour-space conversion and shift their values. A palette image's pixel is its palette entry. A
 * fully transparent pixel is never a wall.
 */
final class MapImageReader {
    private MapImageReader() {
    }

    /**
     * The occupied cells of the image in {@code in}.
     *
     * @throws IOException if the image cannot be read or decoded, is not an image, or is too large
     */
    static OccupancyGrid read(InputStream in, MapSpec spec) throws IOException {
        BufferedInputStream buffered = new BufferedInputStream(in, 1 << 16);
        buffered.mark(2);
        byte[] magic = buffered.readNBytes(2);
        buffered.reset();
        if (PgmReader.isPgm(magic)) {
            return PgmReader.read(buffered, spec);
        }
        return cells(decode(buffered), spec);
    }

    private static BufferedImage decode(InputStream in) throws IOException {
        // Cached in memory, not in a temporary file as ImageIO.createImageInputStream may choose to.
        try (ImageInputStream stream = new MemoryCacheImageInputStream(in)) {
            Iterator<ImageReader> readers = ImageIO.getImageReaders(stream);
            if (!readers.hasNext()) {
                throw new IOException("not an image this server can read (PGM, PNG, or another format of"
                        + " javax.imageio)");
            }
            ImageReader reader = readers.next();
            try {
                reader.setInput(stream, true, true);
                long pixels = (long) reader.getWidth(0) * reader.getHeight(0);
                if (pixels > OccupancyGrid.MAX_CELLS) {
                    throw new IOException("image of " + reader.getWidth(0) + " × " + reader.getHeight(0)
                            + " pixels: a map may have at most " + OccupancyGrid.MAX_CELLS + " pixels");
                }
                return reader.read(0);
            } finally {
                reader.dispose();
            }
        }
    }

    private static OccupancyGrid cells(BufferedImage image, MapSpec spec) {
        OccupancyGrid grid = new OccupancyGrid(image.getWidth(), image.getHeight());
        ColorModel model = image.getColorModel();
        Raster raster = image.getRaster();
        Lightness lightness = model instanceof IndexColorModel
                ? new PaletteLightness((IndexColorModel) model)
                : new ChannelLightness(model, raster);
        int bands = raster.getNumBands();
        int[] samples = new int[grid.width() * bands];
        for (int row = 0; row < grid.height(); row++) {
            raster.getPixels(0, row, grid.width(), 1, samples);
            for (int column = 0; column < grid.width(); column++) {
                double l = lightness.of(samples, column * bands);
                if (!Double.isNaN(l) && spec.isOccupied(l)) {
                    grid.occupy(column, row);
                }
            }
        }
        return grid;
    }

    /** A pixel's lightness, 0 to 1, or NaN if it is fully transparent, from its samples at {@code at}. */
    private interface Lightness {
        double of(int[] samples, int at);
    }

    /** Palette images (1-bit and other indexed PNGs): the pixel is an index into the palette. */
    private static final class PaletteLightness implements Lightness {
        private final IndexColorModel palette;

        PaletteLightness(IndexColorModel palette) {
            this.palette = palette;
        }

        @Override
        public double of(int[] samples, int at) {
            int i = samples[at];
            if (palette.getAlpha(i) == 0) {
                return Double.NaN;
            }
            return (palette.getRed(i) + palette.getGreen(i) + palette.getBlue(i)) / (3.0 * 255.0);
        }
    }

    /** Grey, grey and alpha, RGB, RGBA: colour channels averaged, the alpha channel (if any) last. */
    private static final class ChannelLightness implements Lightness {
        private final int colours;
        private final boolean alpha;
        private final double[] scale;

        ChannelLightness(ColorModel model, Raster raster) {
            this.alpha = model.hasAlpha();
            this.colours = model.getNumColorComponents();
            this.scale = new double[raster.getNumBands()];
            for (int b = 0; b < scale.length; b++) {
                scale[b] = 1.0 / ((1L << raster.getSampleModel().getSampleSize(b)) - 1);
            }
        }

        @Override
        public double of(int[] samples, int at) {
            if (alpha && samples[at + colours] == 0) {
                return Double.NaN;
            }
            double sum = 0;
            for (int b = 0; b < colours; b++) {
                sum += samples[at + b] * scale[b];
            }
            return sum / colours;
        }
    }
}
