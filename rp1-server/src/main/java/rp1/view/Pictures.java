package rp1.view;

import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

import javax.imageio.ImageIO;

import rp1.rossum.RsRectangle;
import rp1.simulator.snapshot.WorldSnapshot;

/** Pictures of the world drawn into images instead of a window; works with no display at all. */
public final class Pictures {
    /** Pixels along the longer side of a picture file. */
    public static final int LONG_SIDE = 800;

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
        Path partial = absolute.resolveSibling(absolute.getFileName() + ".part");
        try {
            if (!ImageIO.write(image, "png", partial.toFile())) {
                throw new IOException("no PNG writer available");
            }
            Files.move(partial, absolute, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException | RuntimeException e) {
            try {
                Files.deleteIfExists(partial);
            } catch (IOException cleanup) {
                e.addSuppressed(cleanup);
            }
            throw e;
        }
    }
}
