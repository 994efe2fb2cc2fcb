package rp1.view;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.Arrays;
import java.util.List;

/**
 * One metric of a sweep drawn as a box plot per configuration: the box from the first to the third
 * quartile with the median across it, whiskers to the least and the greatest value, the values'
 * axis labelled with the metric and its unit.
 */
public final class BoxPlot {
    private static final int HEIGHT = 210;
    private static final int PER_BOX = 46;
    private static final int LEFT = 52;
    private static final int TOP = 24;
    private static final int BOTTOM = 26;

    /** A metric and each configuration's values of it (configurations in the key's order). */
    public record Metric(String title, List<Box> boxes) {
        /** Copies the list. */
        public Metric {
            boxes = List.copyOf(boxes);
        }
    }

    /** One configuration's values of a metric, in its colour, labelled under its box. */
    public record Box(String label, Color color, double[] values) {
    }

    private BoxPlot() {
    }

    /** The size of a plot of {@code configurations} boxes. */
    static Dimension size(int configurations) {
        return new Dimension(Math.max(220, LEFT + 16 + PER_BOX * Math.max(1, configurations)), HEIGHT);
    }

    /** Draws {@code m} in the area of size {@code d} whose top left corner is ({@code left}, {@code top}). */
    static void draw(Graphics2D g, Metric m, int left, int top, Dimension d) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Box b : m.boxes()) {
            for (double v : b.values()) {
                lo = Math.min(lo, v);
                hi = Math.max(hi, v);
            }
        }
        FontMetrics fm = g.getFontMetrics();
        g.setColor(Color.black);
        g.drawString(m.title(), left + LEFT, top + 16);
        int plotTop = top + TOP;
        int plotBottom = top + d.height - BOTTOM;
        g.setColor(Color.gray);
        g.drawLine(left + LEFT, plotTop, left + LEFT, plotBottom);
        if (lo > hi) {
            g.drawString("no values", left + LEFT + 8, (plotTop + plotBottom) / 2);
            return;
        }
        double[] range = range(lo, hi);
        Axis axis = new Axis(range[0], range[1], plotTop, plotBottom);
        for (int i = 0; i <= 4; i++) {
            double v = axis.lo + (axis.hi - axis.lo) * i / 4.0;
            int y = axis.y(v);
            g.setColor(new Color(230, 230, 230));
            g.drawLine(left + LEFT + 1, y, left + d.width - 8, y);
            g.setColor(Color.darkGray);
            String label = tick(v, axis.hi - axis.lo);
            if (fm.stringWidth(label) > LEFT - 6) {
                label = compact(v); // 1234567.5 would run into the plot on its left
            }
            g.drawString(label, left + LEFT - 4 - fm.stringWidth(label), y + fm.getAscent() / 2 - 1);
        }
        for (int i = 0; i < m.boxes().size(); i++) {
            box(g, m.boxes().get(i), axis, left + LEFT + 10 + i * PER_BOX, plotBottom, fm);
        }
    }

    /** Values to pixels, upwards. */
    private record Axis(double lo, double hi, int top, int bottom) {
        int y(double v) {
            return (int) Math.round(bottom - (v - lo) / (hi - lo) * (bottom - top));
        }
    }

    private static void box(Graphics2D g, Box b, Axis axis, int x, int bottom, FontMetrics fm) {
        int w = PER_BOX - 14;
        g.setColor(b.color());
        String label = b.label();
        g.drawString(label, x + w / 2 - fm.stringWidth(label) / 2, bottom + fm.getAscent() + 4);
        if (b.values().length == 0) {
            return;
        }
        double[] v = b.values().clone();
        Arrays.sort(v);
        int min = axis.y(v[0]);
        int max = axis.y(v[v.length - 1]);
        int q1 = axis.y(quantile(v, 0.25));
        int q3 = axis.y(quantile(v, 0.75));
        int median = axis.y(quantile(v, 0.5));
        g.setStroke(new BasicStroke(1.3f));
        g.drawLine(x + w / 2, max, x + w / 2, q3);
        g.drawLine(x + w / 2, q1, x + w / 2, min);
        g.drawLine(x + w / 4, max, x + 3 * w / 4, max);
        g.drawLine(x + w / 4, min, x + 3 * w / 4, min);
        Color c = b.color();
        g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), 70));
        g.fillRect(x, q3, w, Math.max(1, q1 - q3));
        g.setColor(c);
        g.drawRect(x, q3, w, Math.max(1, q1 - q3));
        g.setStroke(new BasicStroke(2.5f));
        g.drawLine(x, median, x + w, median);
        g.setStroke(new BasicStroke(1f));
    }

    /** The {@code p} quantile of sorted values, interpolated linearly between order statistics. */
    static double quantile(double[] sorted, double p) {
        double at = p * (sorted.length - 1);
        int i = (int) Math.floor(at);
        int j = Math.min(sorted.length - 1, i + 1);
        return sorted[i] + (at - i) * (sorted[j] - sorted[i]);
    }

    /**
     * The axis from the least value {@code lo} to the greatest {@code hi}: a twentieth of the span more
     * on either side, but not below 0 when no value is (a distance, a count, a time is never negative).
     */
    static double[] range(double lo, double hi) {
        if (hi - lo < 1e-12) {
            lo -= 0.5;
            hi += 0.5;
        }
        double pad = (hi - lo) * 0.05;
        return new double[] {lo >= 0 ? Math.max(0, lo - pad) : lo - pad, hi + pad};
    }

    /** {@code v} to 3 significant digits with a power of ten: 1.23e6. */
    static String compact(double v) {
        if (v == 0) {
            return "0";
        }
        int exponent = (int) Math.floor(Math.log10(Math.abs(v)));
        BigDecimal mantissa = BigDecimal.valueOf(v / Math.pow(10, exponent)).setScale(2, RoundingMode.HALF_UP);
        if (mantissa.abs().compareTo(BigDecimal.TEN) >= 0) {
            mantissa = mantissa.movePointLeft(1).setScale(2, RoundingMode.HALF_UP);
            exponent++;
        }
        return mantissa.stripTrailingZeros().toPlainString() + "e" + exponent;
    }

    private static String tick(double v, double span) {
        int places = Math.max(0, Math.min(4, (int) Math.ceil(-Math.log10(span / 4.0)) + 1));
        // Rounded as "%.Nf" rounds (half up, from the shortest decimal form) but without a Formatter,
        // whose first use in the process loads the locale data: 9 ms at the end of a sweep.
        return BigDecimal.valueOf(v).setScale(places, RoundingMode.HALF_UP).toPlainString();
    }
}
