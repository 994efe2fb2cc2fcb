package rp1.planparser;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;

/**
 * Reads a portable graymap (netpbm PGM), plain ({@code P2}, decimal samples) or raw ({@code P5},
 * one byte per sample, two big-endian bytes when the maximum exceeds 255), into the cells a
 * {@link MapSpec} calls occupied. The header may carry {@code #} comments. Sizes are checked before
 * anything is allocated, so a corrupt header cannot exhaust memory.
 */
final class PgmReader {
    private final InputStream in;
    private int line = 1;
    private int pushedBack = -2;

    private PgmReader(InputStream in) {
        this.in = in;
    }

    /** Whether the first two bytes are a PGM's magic number. */
    static boolean isPgm(byte[] firstBytes) {
        return firstBytes.length >= 2 && firstBytes[0] == 'P' && (firstBytes[1] == '2' || firstBytes[1] == '5');
    }

    /**
     * Reads the whole image from {@code in} (buffered by the caller).
     *
     * @throws IOException if the stream fails or is not a well-formed PGM; the message says where
     */
    static OccupancyGrid read(InputStream in, MapSpec spec) throws IOException {
        return new PgmReader(in).image(spec);
    }

    private OccupancyGrid image(MapSpec spec) throws IOException {
        int p = read();
        int kind = read();
        if (p != 'P' || (kind != '2' && kind != '5')) {
            throw new IOException("not a PGM image: it must start with P2 or P5");
        }
        int width = headerNumber("width");
        int height = headerNumber("height");
        int maxValue = headerNumber("maximum gray value");
        if (width < 1 || height < 1 || (long) width * height > OccupancyGrid.MAX_CELLS) {
            throw new IOException("image of " + width + " × " + height + " pixels: a map must have at least one"
                    + " and at most " + OccupancyGrid.MAX_CELLS + " pixels");
        }
        if (maxValue < 1 || maxValue > 65535) {
            throw new IOException("maximum gray value " + maxValue + " on line " + line + ": expected 1 to 65535");
        }
        OccupancyGrid grid = new OccupancyGrid(width, height);
        boolean[] occupiedByValue = new boolean[maxValue + 1];
        for (int v = 0; v <= maxValue; v++) {
            occupiedByValue[v] = spec.isOccupied(v / (double) maxValue);
        }
        if (kind == '5') {
            int c = read();
            if (!isWhiteSpace(c)) {
                throw new IOException("expected one white-space character after the maximum gray value on line "
                        + line + ", found " + Token.describeCharacter(c));
            }
        }
        for (int row = 0; row < height; row++) {
            for (int column = 0; column < width; column++) {
                int v = kind == '5' ? rawSample(maxValue) : plainSample(column, row);
                if (v > maxValue) {
                    throw new IOException("pixel (" + column + ", " + row + ") has value " + v
                            + ", above the maximum gray value " + maxValue);
                }
                if (occupiedByValue[v]) {
                    grid.occupy(column, row);
                }
            }
        }
        return grid;
    }

    private int rawSample(int maxValue) throws IOException {
        int v = dataByte();
        return maxValue < 256 ? v : (v << 8) | dataByte();
    }

    private int dataByte() throws IOException {
        int b = in.read();
        if (b < 0) {
            throw new EOFException("the image data ends before the last pixel (truncated file?)");
        }
        return b;
    }

    private int plainSample(int column, int row) throws IOException {
        int c = skipSpaceAndComments();
        if (c < 0) {
            throw new EOFException("the image data ends before pixel (" + column + ", " + row + ") (truncated file?)");
        }
        return digits(c, "the value of pixel (" + column + ", " + row + ")");
    }

    private int headerNumber(String what) throws IOException {
        int c = skipSpaceAndComments();
        return digits(c, "the " + what);
    }

    /** A decimal number starting with {@code c}, at most 65535 x 65535 wide in value. */
    private int digits(int c, String what) throws IOException {
        if (c < '0' || c > '9') {
            throw new IOException("expected " + what + " (a decimal number) on line " + line + ", found "
                    + Token.describeCharacter(c));
        }
        long value = 0;
        while (c >= '0' && c <= '9') {
            value = value * 10 + (c - '0');
            if (value > Integer.MAX_VALUE) {
                throw new IOException(what + " on line " + line + " is too large");
            }
            c = read();
        }
        if (c >= 0 && !isWhiteSpace(c) && c != '#') {
            throw new IOException("expected white space after " + what + " on line " + line + ", found "
                    + Token.describeCharacter(c));
        }
        pushedBack = c;
        return (int) value;
    }

    /** The first character that is neither white space nor inside a comment, or -1 at the end. */
    private int skipSpaceAndComments() throws IOException {
        int c = read();
        while (isWhiteSpace(c) || c == '#') {
            if (c == '#') {
                while (c >= 0 && c != '\n' && c != '\r') {
                    c = read();
                }
            } else {
                c = read();
            }
        }
        return c;
    }

    private int read() throws IOException {
        int c;
        if (pushedBack != -2) {
            c = pushedBack;
            pushedBack = -2;
            return c;
        }
        c = in.read();
        if (c == '\n') {
            line++;
        }
        return c;
    }

    private static boolean isWhiteSpace(int c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == 0x0B || c == 0x0C;
    }
}
