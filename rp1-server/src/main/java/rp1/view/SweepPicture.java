package rp1.view;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import rp1.rossum.RsPlan;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * The summary picture of a sweep: each floor plan as the view draws it, with the trails of every run
 * on it over it, one colour per run and a dot where each robot ended, plans side by side, and a key
 * of the colours underneath.
 */
public final class SweepPicture {
    private static final float TRAIL_WIDTH = 2.0f;
    private static final double END_DOT = 7.0;
    private static final int KEY_WIDTH = 80;
    private static final int KEY_HEIGHT = 18;

    /**
     * Where one run's robots went and ended, in world metres: pieces of path {@code x0, y0, x1, y1,
     * ...} and end points {@code x, y}.
     */
    public record RunTrails(Color color, List<double[]> pieces, List<double[]> ends) {
        /** Copies the lists. */
        public RunTrails {
            pieces = List.copyOf(pieces);
            ends = List.copyOf(ends);
        }
    }

    /** A floor plan and the runs on it. */
    public record Panel(RsPlan plan, List<RunTrails> runs) {
        /** Copies the list. */
        public Panel {
            runs = List.copyOf(runs);
        }
    }

    /** An entry of the key under the panels. */
    public record Key(Color color, String label) {
    }

    private SweepPicture() {
    }

    /** The colour of run {@code index}: hues a golden angle apart, so neighbours differ most. */
    public static Color colour(int index) {
        float hue = (float) ((index * 0.6180339887) % 1.0);
        return Color.getHSBColor(hue, 0.85f, index % 2 == 0 ? 0.8f : 0.6f);
    }

    /** Draws the panels side by side with the key underneath, and writes the picture as PNG. */
    public static void write(Path file, List<Panel> panels, List<Key> keys) throws IOException {
        Pictures.writePng(draw(panels, keys), file);
    }

    /** Draws the panels side by side with the key underneath. */
    public static BufferedImage draw(List<Panel> panels, List<Key> keys) {
        int width = 0;
        int height = 0;
        for (Panel p : panels) {
            Dimension d = Pictures.sizeFor(p.plan().getBounds());
            width += d.width;
            height = Math.max(height, d.height);
        }
        int perRow = Math.max(1, width / KEY_WIDTH);
        int keyRows = (keys.size() + perRow - 1) / perRow;
        BufferedImage image = new BufferedImage(width, height + keyRows * KEY_HEIGHT + (keyRows > 0 ? 6 : 0),
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setColor(Color.white);
            g.fillRect(0, 0, image.getWidth(), image.getHeight());
            int x = 0;
            for (Panel p : panels) {
                x += panel(g, p, x);
            }
            key(g, keys, perRow, height + 4);
        } finally {
            g.dispose();
        }
        return image;
    }

    /** Draws one panel with its left edge at {@code left}; returns its width. */
    private static int panel(Graphics2D g, Panel p, int left) {
        Dimension d = Pictures.sizeFor(p.plan().getBounds());
        BufferedImage plan = Pictures.render(new Renderer(p.plan()), WorldSnapshot.planOnly(p.plan()), d.width, d.height);
        g.drawImage(plan, left, 0, null);
        ViewTransform view = ViewTransform.fit(p.plan().getBounds(), d.width, d.height);
        Graphics2D t = (Graphics2D) g.create(left, 0, d.width, d.height);
        try {
            t.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            t.setStroke(new BasicStroke(TRAIL_WIDTH, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            for (RunTrails run : p.runs()) {
                trails(t, run, view);
            }
        } finally {
            t.dispose();
        }
        return d.width;
    }

    private static void trails(Graphics2D g, RunTrails run, ViewTransform view) {
        Color c = run.color();
        g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), 200));
        for (double[] piece : run.pieces()) {
            if (piece.length < 2) {
                continue;
            }
            Path2D.Double path = new Path2D.Double();
            path.moveTo(view.pixelX(piece[0]), view.pixelY(piece[1]));
            for (int i = 2; i + 1 < piece.length; i += 2) {
                path.lineTo(view.pixelX(piece[i]), view.pixelY(piece[i + 1]));
            }
            g.draw(path);
        }
        g.setColor(c);
        for (double[] end : run.ends()) {
            double px = view.pixelX(end[0]);
            double py = view.pixelY(end[1]);
            g.fill(new Ellipse2D.Double(px - END_DOT / 2, py - END_DOT / 2, END_DOT, END_DOT));
        }
    }

    private static void key(Graphics2D g, List<Key> keys, int perRow, int top) {
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        FontMetrics fm = g.getFontMetrics();
        for (int i = 0; i < keys.size(); i++) {
            int x = 6 + (i % perRow) * KEY_WIDTH;
            int y = top + (i / perRow) * KEY_HEIGHT;
            g.setColor(keys.get(i).color());
            g.fillRect(x, y + 3, 12, 12);
            g.setColor(Color.darkGray);
            g.drawString(keys.get(i).label(), x + 17, y + 3 + fm.getAscent() - 1);
        }
    }
}
