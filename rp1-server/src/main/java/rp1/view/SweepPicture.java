package rp1.view;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import rp1.rossum.RsPlan;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * The summary picture of a sweep: on top a box plot per metric comparing the configurations (one
 * colour each), below a picture per configuration and floor plan with the trails of its runs, a ring
 * where each robot started and a dot where it ended, and a scale bar; a key of the colours and marks
 * at the bottom.
 */
public final class SweepPicture {
    /** Pixels along the longer side of a trails picture. */
    private static final int PANEL_SIDE = 520;
    private static final int PANELS_PER_ROW = 2;
    private static final int TITLE = 20;
    private static final float TRAIL_WIDTH = 1.6f;
    private static final double MARK = 8.0;
    /** How wide a start's ring is drawn, pixels. */
    private static final double MARK_LINE = 1.5;
    private static final int KEY_HEIGHT = 18;

    /** Where one run's robots went, started and ended, in world metres: pieces {@code x0, y0, x1, y1, ...}, points {@code x, y}. */
    public record RunTrails(List<double[]> pieces, List<double[]> starts, List<double[]> ends) {
        /** Copies the lists. */
        public RunTrails {
            pieces = List.copyOf(pieces);
            starts = List.copyOf(starts);
            ends = List.copyOf(ends);
        }
    }

    /** A configuration's runs on a floor plan, titled, in the configuration's colour. */
    public record Panel(String title, Color color, RsPlan plan, List<RunTrails> runs) {
        /** Copies the list. */
        public Panel {
            runs = List.copyOf(runs);
        }
    }

    /** An entry of the key at the bottom: a configuration's colour and what it is. */
    public record Key(Color color, String label) {
    }

    private SweepPicture() {
    }

    /** The colour of configuration {@code index}: hues a golden angle apart, so neighbours differ most. */
    public static Color colour(int index) {
        float hue = (float) ((index * 0.6180339887) % 1.0);
        return Color.getHSBColor(hue, 0.85f, index % 2 == 0 ? 0.75f : 0.55f);
    }

    /**
     * Draws a small picture with what {@link #draw} uses (antialiased strokes, shapes, text) and encodes
     * it as PNG, for nothing: the first use of Java 2D and of the PNG encoder in a JVM loads and
     * compiles a great deal (fonts, the rasterizer, the encoder). A sweep calls this on a thread of its
     * own from its start, while it is prepared and its first runs compute, so that its summary picture
     * at the end does not wait for that (and the plan parser finds {@code java.awt.Color}, whose first
     * use loads the AWT library, loaded). The trails and marks, painted by {@link TrailCanvas}, are
     * painted enough times for its loops to be compiled.
     */
    public static void warmUp() {
        BufferedImage image = new BufferedImage(96, 48, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(Color.white);
            g.fillRect(0, 0, 96, 48);
            g.setColor(colour(1));
            g.draw(circle(60, 20));
            g.fill(circle(20, 20));
            g.drawString("0.5 m", 10, g.getFontMetrics().getAscent() + 2);
        } finally {
            g.dispose();
        }
        try {
            PngEncoder.write(image, new ByteArrayOutputStream());
        } catch (IOException e) {
            // Only a warm-up: the real picture reports its own failures.
        }
        TrailCanvas.warmUp();
    }

    /** Draws the picture and writes it as PNG. */
    public static void write(Path file, List<BoxPlot.Metric> metrics, List<Panel> panels, List<Key> keys)
            throws IOException {
        Pictures.writePng(draw(metrics, panels, keys), file);
    }

    /** Draws the box plots, the trails pictures in rows under them, and the key. */
    public static BufferedImage draw(List<BoxPlot.Metric> metrics, List<Panel> panels, List<Key> keys) {
        int configurations = keys.size();
        Dimension box = BoxPlot.size(configurations);
        int perRow = Math.max(1, Math.min(metrics.size(), Math.max(2, (PANEL_SIDE * PANELS_PER_ROW) / box.width)));
        int boxRows = (metrics.size() + perRow - 1) / perRow;
        int panelW = 0;
        int panelH = 0;
        for (Panel p : panels) {
            Dimension d = Pictures.sizeFor(p.plan().getBounds(), PANEL_SIDE);
            panelW = Math.max(panelW, d.width);
            panelH = Math.max(panelH, d.height);
        }
        int panelRows = (panels.size() + PANELS_PER_ROW - 1) / PANELS_PER_ROW;
        int width = Math.max(Math.max(perRow * box.width, Math.min(panels.size(), PANELS_PER_ROW) * panelW), 400);
        int keyTop = boxRows * box.height + panelRows * (panelH + TITLE) + 6;
        int height = keyTop + (keys.size() + 1) * KEY_HEIGHT + 6;
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setColor(Color.white);
            g.fillRect(0, 0, width, height);
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            for (int i = 0; i < metrics.size(); i++) {
                BoxPlot.draw(g, metrics.get(i), (i % perRow) * box.width, (i / perRow) * box.height, box);
            }
            int top = boxRows * box.height;
            for (int i = 0; i < panels.size(); i++) {
                panel(g, image, panels.get(i), (i % PANELS_PER_ROW) * panelW,
                        top + (i / PANELS_PER_ROW) * (panelH + TITLE));
            }
            key(g, keys, keyTop);
        } finally {
            g.dispose();
        }
        return image;
    }

    /** One trails picture with its title above it, its top left corner at ({@code left}, {@code top}). */
    private static void panel(Graphics2D g, BufferedImage image, Panel p, int left, int top) {
        Dimension d = Pictures.sizeFor(p.plan().getBounds(), PANEL_SIDE);
        g.setColor(p.color());
        g.drawString(p.title(), left + 6, top + TITLE - 6);
        BufferedImage plan = Pictures.render(new Renderer(p.plan()), WorldSnapshot.planOnly(p.plan()), d.width, d.height);
        g.drawImage(plan, left, top + TITLE, null);
        ViewTransform view = ViewTransform.fit(p.plan().getBounds(), d.width, d.height);
        Color c = p.color();
        Color faint = new Color(c.getRed(), c.getGreen(), c.getBlue(), Math.max(40, 200 / Math.max(1, p.runs().size() / 4)));
        TrailCanvas canvas = new TrailCanvas(image, left, top + TITLE, d.width, d.height);
        for (RunTrails run : p.runs()) {
            for (double[] piece : run.pieces()) {
                canvas.stroke(inPixels(piece, view), TRAIL_WIDTH, faint);
            }
        }
        for (RunTrails run : p.runs()) {
            marks(canvas, run, view, c);
        }
        Graphics2D t = (Graphics2D) g.create(left, top + TITLE, d.width, d.height);
        try {
            scale(t, p.plan(), view, d);
        } finally {
            t.dispose();
        }
    }

    /** The piece {@code x0, y0, x1, y1, ...} in world metres as pixels of its trails picture. */
    private static double[] inPixels(double[] piece, ViewTransform view) {
        double[] xy = new double[piece.length & ~1];
        for (int i = 0; i + 1 < piece.length; i += 2) {
            xy[i] = view.pixelX(piece[i]);
            xy[i + 1] = view.pixelY(piece[i + 1]);
        }
        return xy;
    }

    /** A ring where each robot started, a dot where it ended. */
    private static void marks(TrailCanvas canvas, RunTrails run, ViewTransform view, Color c) {
        for (double[] s : run.starts()) {
            canvas.dot(view.pixelX(s[0]), view.pixelY(s[1]), MARK / 2, Color.white);
            canvas.ring(view.pixelX(s[0]), view.pixelY(s[1]), MARK / 2, MARK_LINE, c);
        }
        for (double[] e : run.ends()) {
            canvas.dot(view.pixelX(e[0]), view.pixelY(e[1]), MARK / 2, c);
        }
    }

    private static Ellipse2D circle(double x, double y) {
        return new Ellipse2D.Double(x - MARK / 2, y - MARK / 2, MARK, MARK);
    }

    /** A bar of a round length (1, 2 or 5 times a power of ten metres) near a fifth of the plan's width. */
    private static void scale(Graphics2D g, RsPlan plan, ViewTransform view, Dimension d) {
        double target = plan.getBounds().width / 5.0;
        double power = Math.pow(10, Math.floor(Math.log10(target)));
        double metres = power;
        for (double m : new double[] {2 * power, 5 * power}) {
            if (m <= target) {
                metres = m;
            }
        }
        double pixels = Math.abs(view.pixelX(metres) - view.pixelX(0));
        int x = 12;
        int y = d.height - 12;
        g.setStroke(new BasicStroke(3f));
        g.setColor(Color.black);
        g.drawLine(x, y, x + (int) Math.round(pixels), y);
        g.drawLine(x, y - 4, x, y + 1);
        g.drawLine(x + (int) Math.round(pixels), y - 4, x + (int) Math.round(pixels), y + 1);
        String label = (metres >= 1 ? Long.toString(Math.round(metres)) : Double.toString(metres)) + " m";
        g.drawString(label, x + (int) Math.round(pixels) + 6, y + 4);
    }

    /** The configurations' colours, then what the marks mean. */
    private static void key(Graphics2D g, List<Key> keys, int top) {
        FontMetrics fm = g.getFontMetrics();
        for (int i = 0; i < keys.size(); i++) {
            int y = top + i * KEY_HEIGHT;
            g.setColor(keys.get(i).color());
            g.fillRect(8, y + 3, 12, 12);
            g.setColor(Color.darkGray);
            g.drawString(keys.get(i).label(), 26, y + 3 + fm.getAscent() - 1);
        }
        int y = top + keys.size() * KEY_HEIGHT;
        g.setColor(Color.darkGray);
        g.draw(circle(14, y + 9));
        g.fill(circle(96, y + 9));
        g.drawString("start", 24, y + 3 + fm.getAscent() - 1);
        g.drawString("end", 106, y + 3 + fm.getAscent() - 1);
        g.drawString("boxes: quartiles and median; whiskers: least and greatest", 160, y + 3 + fm.getAscent() - 1);
    }
}
