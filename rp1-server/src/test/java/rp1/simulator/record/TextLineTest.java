package rp1.simulator.record;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.Color;
import java.util.Locale;
import java.util.Random;

import org.junit.jupiter.api.Test;

/** Fields of a recording's lines in the forms docs/recording.md gives. */
class TextLineTest {

    @Test
    void coloursAreHexTripletsWithTheAlphaOnlyWhenNotOpaque() {
        assertEquals("c #000000", new TextLine("c").color(Color.black).toString());
        assertEquals("c #ff00a0", new TextLine("c").color(new Color(255, 0, 160)).toString());
        assertEquals("c #0a0b0c80", new TextLine("c").color(new Color(10, 11, 12, 128)).toString());
        assertEquals("c #ffffff00", new TextLine("c").color(new Color(255, 255, 255, 0)).toString());
        assertEquals("c -", new TextLine("c").color(null).toString());
    }

    @Test
    void coloursReadAsTheFormatStringWroteThem() {
        Random random = new Random(7);
        for (int i = 0; i < 5_000; i++) {
            Color c = new Color(random.nextInt(256), random.nextInt(256), random.nextInt(256),
                    i % 3 == 0 ? 255 : random.nextInt(256));
            String expected = c.getAlpha() == 255
                    ? String.format(Locale.ROOT, "#%06x", c.getRGB() & 0xFFFFFF)
                    : String.format(Locale.ROOT, "#%06x%02x", c.getRGB() & 0xFFFFFF, c.getAlpha());
            assertEquals("c " + expected, new TextLine("c").color(c).toString());
        }
    }
}
