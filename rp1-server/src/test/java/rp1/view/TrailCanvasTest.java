package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

/** Trails and marks painted into a picture's pixels look as Java 2D draws them, antialiased. */
class TrailCanvasTest {
    private static final float WIDTH = 1.6f;

    @Test
    void randomTrailsPutTheColourWhereJava2DsStrokePutsIt() {
        SplittableRandom random = new SplittableRandom(21);
        for (int round = 0; round < 20; round++) {
            Color colour = randomColour(random);
            double[] xy = new double[2 * (2 + random.nextInt(12))];
            for (int i = 0; i < xy.length; i += 2) {
                xy[i] = -20 + 240 * random.nextDouble();
                xy[i + 1] = -20 + 190 * random.nextDouble();
            }
            Graphics2D g = java2d(colour);
            g.setStroke(new BasicStroke(WIDTH, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            g.draw(path(xy));
            new TrailCanvas(ours, 0, 0, 200, 150).stroke(xy, WIDTH, colour);
            assertAlike("trail " + round, colour, g);
        }
    }

    @Test
    void randomDotsAndRingsPutTheColourWhereJava2DPutsIt() {
        SplittableRandom random = new SplittableRandom(22);
        for (int round = 0; round < 20; round++) {
            Color colour = randomColour(random);
            double x = 200 * random.nextDouble();
            double y = 150 * random.nextDouble();
            double radius = 3 + 8 * random.nextDouble(); // a mark's is 4
            Ellipse2D circle = new Ellipse2D.Double(x - radius, y - radius, 2 * radius, 2 * radius);
            Graphics2D g = java2d(colour);
            if (round % 2 == 0) {
                g.fill(circle);
                new TrailCanvas(ours, 0, 0, 200, 150).dot(x, y, radius, colour);
            } else {
                g.setStroke(new BasicStroke(1.5f));
                g.draw(circle);
                new TrailCanvas(ours, 0, 0, 200, 150).ring(x, y, radius, 1.5, colour);
            }
            assertAlike((round % 2 == 0 ? "dot " : "ring ") + round, colour, g);
        }
    }

    @Test
    void aTrailThatCrossesItselfIsShadedOnceWhereItDoes() {
        Color colour = new Color(0, 0, 0, 128);
        BufferedImage once = white(60, 60);
        new TrailCanvas(once, 0, 0, 60, 60).stroke(new double[] {10.5, 10.5, 50.5, 50.5, 50.5, 10.5, 10.5, 50.5}, WIDTH,
                colour);
        BufferedImage twice = white(60, 60);
        TrailCanvas legs = new TrailCanvas(twice, 0, 0, 60, 60);
        legs.stroke(new double[] {10.5, 10.5, 50.5, 50.5}, WIDTH, colour);
        legs.stroke(new double[] {50.5, 10.5, 10.5, 50.5}, WIDTH, colour);

        int onALeg = once.getRGB(20, 20);
        assertEquals(onALeg, once.getRGB(30, 30), "where the trail crosses itself");
        assertEquals(onALeg, once.getRGB(50, 50), "at its joins");
        assertEquals(onALeg, once.getRGB(50, 30), "on its next leg");
        assertEquals(onALeg, twice.getRGB(20, 20));
        assertTrue(ink(twice.getRGB(30, 30)) > ink(onALeg) + 40, "two trails that cross are shaded twice");
    }

    @Test
    void aLegAlongARowShadesItFullyAndNothingBeyondItsEdge() {
        BufferedImage image = white(40, 20);
        new TrailCanvas(image, 0, 0, 40, 20).stroke(new double[] {5, 10.5, 35, 10.5}, WIDTH, Color.black);
        for (int x = 6; x < 35; x++) {
            assertEquals(0x000000, image.getRGB(x, 10) & 0xffffff, "on the line at " + x);
            assertEquals(0xffffff, image.getRGB(x, 8) & 0xffffff, "two pixels off the line at " + x);
            assertEquals(0xffffff, image.getRGB(x, 12) & 0xffffff, "two pixels off the line at " + x);
            int edge = ink(image.getRGB(x, 9));
            assertEquals(edge, ink(image.getRGB(x, 11)), "the edges alike at " + x);
            assertTrue(edge > 150 && edge < 300, "the edge pixels' centres 0.3 px inside the shading's end: " + edge);
        }
        assertEquals(0xffffff, image.getRGB(2, 10) & 0xffffff, "beyond the round cap");
        assertEquals(0xffffff, image.getRGB(38, 10) & 0xffffff, "beyond the round cap");
    }

    @Test
    void onlyTheRectangleIsPaintedAndLegsThatAreNotFiniteAreLeftOut() {
        BufferedImage image = white(50, 50);
        TrailCanvas inner = new TrailCanvas(image, 10, 20, 30, 20);
        inner.stroke(new double[] {-1e9, 10.5, 1e9, 10.5, 15, 1e12, Double.NaN, 3, 15, 3}, WIDTH, Color.black);
        for (int y = 0; y < 50; y++) {
            for (int x = 0; x < 50; x++) {
                boolean inside = x >= 10 && x < 40 && y >= 20 && y < 40;
                if (!inside || Math.abs(y - 30) > 1) {
                    assertEquals(0xffffff, image.getRGB(x, y) & 0xffffff, "at " + x + "," + y);
                }
            }
        }
        for (int x = 10; x < 40; x++) {
            assertEquals(0x000000, image.getRGB(x, 30) & 0xffffff, "the line across the rectangle, at " + x);
        }
    }

    @Test
    void picturesItCannotPaintAreTurnedDown() {
        BufferedImage argb = new BufferedImage(10, 10, BufferedImage.TYPE_INT_ARGB);
        assertThrows(IllegalArgumentException.class, () -> new TrailCanvas(argb, 0, 0, 10, 10));
        BufferedImage rgb = white(10, 10);
        assertThrows(IllegalArgumentException.class, () -> new TrailCanvas(rgb, 5, 0, 6, 10));
        assertThrows(IllegalArgumentException.class,
                () -> new TrailCanvas(rgb.getSubimage(1, 1, 5, 5), 0, 0, 5, 5));
    }

    private BufferedImage theirs;
    private BufferedImage ours;

    /**
     * A white picture to draw on in {@code colour} with Java 2D as the summary picture does (antialiased, in the shape's own
     * geometry: by default Java 2D also moves lines by up to half a pixel), and another for the canvas.
     */
    private Graphics2D java2d(Color colour) {
        theirs = white(200, 150);
        ours = white(200, 150);
        Graphics2D g = theirs.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.setColor(colour);
        return g;
    }

    /** That the two pictures hold as much colour, in the same pixels within a shade. */
    private void assertAlike(String what, Color colour, Graphics2D g) {
        g.dispose();
        double inkJava2d = 0.0;
        double inkOurs = 0.0;
        double apart = 0.0;
        int worst = 0;
        for (int y = 0; y < 150; y++) {
            for (int x = 0; x < 200; x++) {
                int a = ink(theirs.getRGB(x, y));
                int b = ink(ours.getRGB(x, y));
                inkJava2d += a;
                inkOurs += b;
                apart += Math.abs(a - b);
                worst = Math.max(worst, Math.abs(a - b));
            }
        }
        String seen = what + ": ink " + inkOurs + " against Java 2D's " + inkJava2d + ", apart " + apart
                + ", worst pixel " + worst;
        // Within a few per cent (they read 0.98-1.04): Java 2D rounds its blending down, and draws circles
        // as curves it flattens into chords.
        assertEquals(inkJava2d, inkOurs, 0.05 * inkJava2d, seen);
        // A shape drawn half a pixel off is apart by about half the ink it has (they read 0.3-4 %).
        assertTrue(apart < 0.1 * inkJava2d, seen);
        assertTrue(worst <= 0.6 * maxInk(colour), seen);
    }

    private static Color randomColour(SplittableRandom random) {
        return new Color(random.nextInt(200), random.nextInt(200), random.nextInt(200), 40 + random.nextInt(200));
    }

    private static BufferedImage white(int width, int height) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.white);
        g.fillRect(0, 0, width, height);
        g.dispose();
        return image;
    }

    private static Path2D path(double[] xy) {
        Path2D.Double p = new Path2D.Double();
        p.moveTo(xy[0], xy[1]);
        for (int i = 2; i < xy.length; i += 2) {
            p.lineTo(xy[i], xy[i + 1]);
        }
        return p;
    }

    /** How far a pixel is from white: the sum of what its three channels lack. */
    private static int ink(int rgb) {
        return 3 * 255 - (rgb >> 16 & 0xff) - (rgb >> 8 & 0xff) - (rgb & 0xff);
    }

    private static double maxInk(Color c) {
        return c.getAlpha() / 255.0 * (3 * 255 - c.getRed() - c.getGreen() - c.getBlue());
    }
}
