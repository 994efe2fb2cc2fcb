package rp1.rossum.wire;

import java.awt.Color;
import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.UTFDataFormatException;

import rp1.rossum.RsProtocolException;

/**
 * Reads RP1 primitives (protocol.md section 2) field by field from a stream, naming each field so that
 * any failure becomes an {@link RsProtocolException} that says what was being read and what was seen.
 * Socket-free: tests feed it byte arrays.
 */
public final class WireIn {
    private final DataInputStream in;

    /** A reader of the messages on {@code in}. */
    public WireIn(DataInputStream in) {
        this.in = in;
    }

    /** A reader over a byte array, for tests and for decoding captured messages. */
    public static WireIn of(byte[] bytes) {
        return of(bytes, 0, bytes.length);
    }

    /** Reads {@code length} bytes of {@code bytes} from {@code offset}. */
    public static WireIn of(byte[] bytes, int offset, int length) {
        return new WireIn(new DataInputStream(new ByteArrayInputStream(bytes, offset, length)));
    }

    /** An I32 (big-endian); {@code field} names it if the bytes end first. */
    public int i32(String field) throws IOException {
        try {
            return in.readInt();
        } catch (EOFException e) {
            throw ended(field);
        }
    }

    /** An F64 (IEEE 754, big-endian), any value; {@code field} names it if the bytes end first. */
    public double f64(String field) throws IOException {
        try {
            return in.readDouble();
        } catch (EOFException e) {
            throw ended(field);
        }
    }

    /**
     * An f64 that a client sends (a request's field, a body's dimension): NaN and the infinities are
     * refused, since one of them in a time, an interval or a velocity poisons the clock or a pose.
     */
    public double finite(String field) throws IOException {
        double v = f64(field);
        if (!Double.isFinite(v)) {
            throw new RsProtocolException(field, v + " is not a finite number");
        }
        return v;
    }

    /** Any non-zero byte is true, as Java's DataInput reads it. */
    public boolean bool(String field) throws IOException {
        try {
            return in.readBoolean();
        } catch (EOFException e) {
            throw ended(field);
        }
    }

    /** A STR: u16 byte count then modified UTF-8; never null. */
    public String str(String field) throws IOException {
        try {
            return in.readUTF();
        } catch (EOFException e) {
            throw ended(field);
        } catch (UTFDataFormatException e) {
            throw new RsProtocolException(field, "invalid modified UTF-8 (" + e.getMessage() + ")");
        }
    }

    /** A non-negative i32 count no larger than {@code max}. */
    public int count(String field, int max) throws IOException {
        int n = i32(field);
        if (n < 0 || n > max) {
            throw new RsProtocolException(field, n + " is outside the accepted range 0.." + max);
        }
        return n;
    }

    /** A COLOR: i32 presence flag (0 = null), then red, green, blue in 0..255. */
    public Color color(String field) throws IOException {
        if (i32(field + " present") == 0) {
            return null;
        }
        int r = component(field + " red");
        int g = component(field + " green");
        int b = component(field + " blue");
        return new Color(r, g, b);
    }

    private int component(String field) throws IOException {
        int v = i32(field);
        if (v < 0 || v > 255) {
            throw new RsProtocolException(field, v + " is outside 0..255");
        }
        return v;
    }

    /** A COLOR_ARRAY: i32 count (0 = null), then that many COLORs. */
    public Color[] colorArray(String field) throws IOException {
        int n = count(field + " count", WireLimits.MAX_COLORS);
        if (n == 0) {
            return null;
        }
        Color[] colors = new Color[n];
        for (int i = 0; i < n; i++) {
            colors[i] = color(field + "[" + i + "]");
        }
        return colors;
    }

    /**
     * Reads the first i32 of a message. A stream that ends before its first byte ended cleanly
     * between messages, which is reported as a plain {@link EOFException}, not a protocol violation.
     */
    public int firstI32(String field) throws IOException {
        int b0 = in.read();
        if (b0 < 0) {
            throw new EOFException("connection closed by peer");
        }
        byte[] rest = new byte[3];
        try {
            in.readFully(rest);
        } catch (EOFException e) {
            throw ended(field);
        }
        return (b0 << 24) | ((rest[0] & 0xFF) << 16) | ((rest[1] & 0xFF) << 8) | (rest[2] & 0xFF);
    }

    private static RsProtocolException ended(String field) {
        return new TruncatedMessageException(field);
    }
}
