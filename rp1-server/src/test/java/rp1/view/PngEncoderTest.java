package rp1.view;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Line2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.SplittableRandom;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

/** The PNG files written are read back by ImageIO, pixel for pixel, whatever the picture. */
class PngEncoderTest {
    @Test
    void aDrawingReadsBackAsDrawn() throws IOException {
        BufferedImage image = new BufferedImage(301, 177, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.white);
        g.fillRect(0, 0, 301, 177);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setStroke(new BasicStroke(1.6f));
        g.setColor(new Color(200, 30, 90, 60));
        for (int i = 0; i < 40; i++) {
            g.draw(new Line2D.Double(3 * i, 0, 300 - 5 * i, 176));
        }
        g.drawString("0.5 m", 10, 20);
        g.dispose();
        assertReadsBack(image);
    }

    @Test
    void noiseReadsBackAndSoDoTinyPictures() throws IOException {
        SplittableRandom random = new SplittableRandom(3);
        for (int[] size : new int[][] {{1, 1}, {1, 9}, {9, 1}, {640, 480}}) {
            BufferedImage image = new BufferedImage(size[0], size[1], BufferedImage.TYPE_INT_RGB);
            for (int y = 0; y < size[1]; y++) {
                for (int x = 0; x < size[0]; x++) {
                    image.setRGB(x, y, random.nextInt());
                }
            }
            assertReadsBack(image);
        }
    }

    @Test
    void partOfAPictureAndOtherKindsOfImageAreWrittenToo() throws IOException {
        BufferedImage whole = new BufferedImage(50, 40, BufferedImage.TYPE_INT_RGB);
        SplittableRandom random = new SplittableRandom(4);
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 50; x++) {
                whole.setRGB(x, y, random.nextInt());
            }
        }
        assertReadsBack(whole.getSubimage(7, 5, 20, 30));
        BufferedImage withAlpha = new BufferedImage(20, 10, BufferedImage.TYPE_INT_ARGB);
        withAlpha.setRGB(3, 4, 0x80ff0000);
        BufferedImage back = ImageIO.read(new ByteArrayInputStream(encoded(withAlpha)));
        assertEquals(0x80ff0000, back.getRGB(3, 4), "through ImageIO, alpha kept");
    }

    private static void assertReadsBack(BufferedImage image) throws IOException {
        BufferedImage back = ImageIO.read(new ByteArrayInputStream(encoded(image)));
        int w = image.getWidth();
        int h = image.getHeight();
        assertEquals(w, back.getWidth());
        assertEquals(h, back.getHeight());
        int[] expected = image.getRGB(0, 0, w, h, null, 0, w);
        int[] actual = back.getRGB(0, 0, w, h, null, 0, w);
        for (int i = 0; i < expected.length; i++) {
            expected[i] |= 0xff000000;
        }
        assertArrayEquals(expected, actual);
    }

    private static byte[] encoded(BufferedImage image) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PngEncoder.write(image, out);
        return out.toByteArray();
    }
}
