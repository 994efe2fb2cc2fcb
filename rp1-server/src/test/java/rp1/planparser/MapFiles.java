package rp1.planparser;

import java.awt.image.BufferedImage;
import java.awt.image.WritableRaster;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

/**
 * Writes test maps: a picture given as rows of text ('#' black, '?' map_server's unknown grey 205,
 * anything else white) as a PGM (plain or raw, 8 or 16 bits) or a PNG (grey, 1-bit palette, RGBA),
 * and the map_server YAML file that names it.
 */
final class MapFiles {
    private MapFiles() {
    }

    /** The grey value of a picture's character, 0 to 255. */
    static int gray(char c) {
        return c == '#' ? 0 : c == '?' ? 205 : 254;
    }

    static byte[] plainPgm(String... rows) {
        StringBuilder b = new StringBuilder("P2\n# a test map\n" + rows[0].length() + " " + rows.length + "\n255\n");
        for (String row : rows) {
            for (int c = 0; c < row.length(); c++) {
                b.append(gray(row.charAt(c))).append(c + 1 < row.length() ? " " : "\n");
            }
        }
        return b.toString().getBytes(StandardCharsets.US_ASCII);
    }

    /** A raw PGM; {@code maxValue} above 255 writes two bytes a pixel. */
    static byte[] rawPgm(int maxValue, String... rows) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(("P5 " + rows[0].length() + "\n" + rows.length + " #height\n" + maxValue + "\n")
                .getBytes(StandardCharsets.US_ASCII));
        for (String row : rows) {
            for (int c = 0; c < row.length(); c++) {
                int v = gray(row.charAt(c)) * maxValue / 255;
                if (maxValue > 255) {
                    out.write(v >> 8);
                }
                out.write(v & 0xFF);
            }
        }
        return out.toByteArray();
    }

    /** A PNG of {@code type}: TYPE_BYTE_GRAY, TYPE_USHORT_GRAY, TYPE_BYTE_BINARY or TYPE_INT_ARGB. */
    static byte[] png(int type, String... rows) {
        BufferedImage image = new BufferedImage(rows[0].length(), rows.length, type);
        WritableRaster raster = image.getRaster();
        for (int r = 0; r < rows.length; r++) {
            for (int c = 0; c < rows[r].length(); c++) {
                int g = gray(rows[r].charAt(c));
                if (type == BufferedImage.TYPE_INT_ARGB) {
                    image.setRGB(c, r, 0xFF000000 | g << 16 | g << 8 | g);
                } else if (type == BufferedImage.TYPE_BYTE_BINARY) {
                    raster.setSample(c, r, 0, g < 128 ? 0 : 1);
                } else if (type == BufferedImage.TYPE_USHORT_GRAY) {
                    raster.setSample(c, r, 0, g * 257);
                } else {
                    raster.setSample(c, r, 0, g);
                }
            }
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            ImageIO.write(image, "png", out);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }

    /** Writes {@code image} as {@code dir/name} and a YAML file naming it with {@code settings} lines. */
    static Path yaml(Path dir, String name, byte[] image, String... settings) throws IOException {
        Files.write(dir.resolve(name), image);
        String text = "image: " + name + "\n" + String.join("\n", settings) + "\n";
        Path yaml = dir.resolve(name.replaceAll("\\.[a-z]+$", "") + ".yaml");
        Files.writeString(yaml, text);
        return yaml;
    }
}
