package rp1.rossum.wire;

import java.awt.Color;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UTFDataFormatException;
import java.io.UncheckedIOException;

/**
 * Builds one complete RP1 message in memory. Messages are only handed to a stream once they are
 * whole, so an encoding failure (an over-long string, an unencodable part) can never leave half a
 * message in the stream, and concurrent senders never interleave bytes.
 */
public final class WireOut {
    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream(128);
    private final DataOutputStream out = new DataOutputStream(bytes);

    /** Appends an I32 (big-endian). */
    public WireOut i32(int v) {
        try {
            out.writeInt(v);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return this;
    }

    /** Appends an F64 (IEEE 754, big-endian). */
    public WireOut f64(double v) {
        try {
            out.writeDouble(v);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return this;
    }

    /** Appends a BOOL: one byte, 1 or 0. */
    public WireOut bool(boolean v) {
        try {
            out.writeBoolean(v);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return this;
    }

    /**
     * A STR; null is written as the empty string.
     *
     * @throws IllegalArgumentException if the text needs more than 65535 bytes of modified UTF-8
     */
    public WireOut str(String s) {
        try {
            out.writeUTF(s == null ? "" : s);
        } catch (UTFDataFormatException e) {
            throw new IllegalArgumentException("string too long for the RP1 wire format (limit 65535 bytes): "
                    + s.substring(0, Math.min(40, s.length())) + "...", e);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return this;
    }

    /** A COLOR: 0 for null, else 1 and the red, green and blue components. */
    public WireOut color(Color c) {
        if (c == null) {
            return i32(0);
        }
        return i32(1).i32(c.getRed()).i32(c.getGreen()).i32(c.getBlue());
    }

    /** A COLOR_ARRAY: 0 for null or empty, else the count and each COLOR. */
    public WireOut colorArray(Color[] colors) {
        if (colors == null || colors.length == 0) {
            return i32(0);
        }
        i32(colors.length);
        for (Color c : colors) {
            color(c);
        }
        return this;
    }

    /** The 20-byte transaction header (protocol.md section 3). */
    public WireOut header(int clientId, int clientKey, int sequence, int transactionCode) {
        return i32(WireCodes.VERSION).i32(clientId).i32(clientKey).i32(sequence).i32(transactionCode);
    }

    /** The bytes so far. */
    public int size() {
        return bytes.size();
    }

    /** A copy of the bytes so far. */
    public byte[] toByteArray() {
        return bytes.toByteArray();
    }

    /** Writes the bytes so far to {@code target}, unflushed. */
    public void writeTo(OutputStream target) throws IOException {
        bytes.writeTo(target);
    }
}
