package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.event.InputEvent;
import java.awt.event.MouseEvent;

import javax.swing.JPanel;

import org.junit.jupiter.api.Test;

/** The button code of a mouse-click event (behavior.md section 8.8). */
class MouseButtonsTest {
    private static final JPanel SOURCE = new JPanel();

    private static int code(int button, int modifiers) {
        return MouseButtons.codeOf(new MouseEvent(SOURCE, MouseEvent.MOUSE_PRESSED, 0L, modifiers, 10, 10, 1, false, button));
    }

    @Test
    void thePrimaryButtonAloneIs0() {
        assertEquals(0, code(MouseEvent.BUTTON1, InputEvent.BUTTON1_DOWN_MASK));
        assertEquals(0, code(MouseEvent.BUTTON1, InputEvent.BUTTON1_DOWN_MASK | InputEvent.SHIFT_DOWN_MASK));
    }

    @Test
    void thePrimaryButtonWithAltOrMetaIs1() {
        assertEquals(1, code(MouseEvent.BUTTON1, InputEvent.BUTTON1_DOWN_MASK | InputEvent.ALT_DOWN_MASK));
        assertEquals(1, code(MouseEvent.BUTTON1, InputEvent.BUTTON1_DOWN_MASK | InputEvent.META_DOWN_MASK));
    }

    @Test
    void theMiddleAndSecondaryButtonsAre1() {
        assertEquals(1, code(MouseEvent.BUTTON2, InputEvent.BUTTON2_DOWN_MASK));
        assertEquals(1, code(MouseEvent.BUTTON3, InputEvent.BUTTON3_DOWN_MASK));
    }
}
