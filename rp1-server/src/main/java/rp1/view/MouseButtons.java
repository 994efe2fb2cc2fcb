package rp1.view;

import java.awt.event.MouseEvent;

/** The button code of a mouse-click event (behavior.md section 8.8). */
final class MouseButtons {
    /** The primary button. */
    static final int PRIMARY = 0;
    /** Any other button, or the primary one with Alt or Meta held. */
    static final int SECONDARY = 1;

    private MouseButtons() {
    }

    /** 0 for the primary button without Alt or Meta, 1 for everything else. */
    static int codeOf(MouseEvent e) {
        boolean primary = e.getButton() == MouseEvent.BUTTON1;
        return primary && !e.isAltDown() && !e.isMetaDown() ? PRIMARY : SECONDARY;
    }
}
