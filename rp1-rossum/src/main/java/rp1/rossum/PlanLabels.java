package rp1.rossum;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;

/** Label and marker drawing shared by the point-like plan objects (targets, placements, nodes). */
final class PlanLabels {
    /** The label font of the original view. */
    static final Font LABEL_FONT = new Font("SansSerif", Font.BOLD, 14);

    private PlanLabels() {
    }

    /** Draws {@code label} centred on pixel (px, py), or a small "+" there if there is no label. */
    static void labelOrCross(Graphics g, String label, int px, int py, Color color) {
        if (color == null) {
            return;
        }
        g.setColor(color);
        if (label == null || label.isEmpty()) {
            g.drawLine(px - 4, py, px + 4, py);
            g.drawLine(px, py - 4, px, py + 4);
            return;
        }
        g.setFont(LABEL_FONT);
        FontMetrics fm = g.getFontMetrics();
        g.drawString(label, px - fm.stringWidth(label) / 2, py + (fm.getAscent() - fm.getDescent()) / 2);
    }
}
