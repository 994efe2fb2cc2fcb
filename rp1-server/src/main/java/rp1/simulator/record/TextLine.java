package rp1.simulator.record;

import java.awt.Color;
import java.util.Locale;

/**
 * One line of a recording or an event log being written: fields separated by single spaces, in the
 * forms docs/recording.md gives. Numbers are written so that reading them back gives the same bits.
 */
final class TextLine {
    private final StringBuilder line = new StringBuilder(80);

    /** A line starting with {@code keyword}. */
    TextLine(String keyword) {
        line.append(keyword);
    }

    /** A bare word (no spaces, no quotes). */
    TextLine word(String word) {
        line.append(' ').append(word);
        return this;
    }

    TextLine integer(long value) {
        line.append(' ').append(value);
        return this;
    }

    /** As Java writes a double: the digits needed to read back the same number. */
    TextLine real(double value) {
        line.append(' ').append(value);
        return this;
    }

    TextLine bool(boolean value) {
        line.append(' ').append(value);
        return this;
    }

    /** Quoted text, or {@code -} for none. */
    TextLine text(String value) {
        line.append(' ');
        quote(line, value);
        return this;
    }

    /** {@code #rrggbb}, {@code #rrggbbaa} when not opaque, or {@code -} for none. */
    TextLine color(Color c) {
        line.append(' ');
        if (c == null) {
            line.append('-');
        } else {
            // Hex digits by hand: a recording's header has a colour per object of the plan, and a
            // format string is parsed anew for each.
            line.append('#');
            hex(c.getRed());
            hex(c.getGreen());
            hex(c.getBlue());
            if (c.getAlpha() != 255) {
                hex(c.getAlpha());
            }
        }
        return this;
    }

    /** Two lower-case hex digits of a byte. */
    private void hex(int b) {
        line.append(Character.forDigit(b >> 4, 16)).append(Character.forDigit(b & 15, 16));
    }

    /** A named field of an event line: {@code name=value}, the value a real. */
    TextLine field(String name, double value) {
        line.append(' ').append(name).append('=').append(value);
        return this;
    }

    TextLine field(String name, long value) {
        line.append(' ').append(name).append('=').append(value);
        return this;
    }

    TextLine field(String name, boolean value) {
        line.append(' ').append(name).append('=').append(value);
        return this;
    }

    /** A named text field, quoted, or {@code -} for none. */
    TextLine field(String name, String value) {
        line.append(' ').append(name).append('=');
        quote(line, value);
        return this;
    }

    /**
     * Writes {@code value} in double quotes, with backslash escapes for the quote, the backslash and
     * control characters; null as {@code -}.
     */
    static void quote(StringBuilder out, String value) {
        if (value == null) {
            out.append('-');
            return;
        }
        out.append('"');
        for (int i = 0; i < value.length(); i++) {
            char c = value.charAt(i);
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                case '\r' -> out.append("\\r");
                case '\t' -> out.append("\\t");
                default -> {
                    if (c < 0x20 || c == 0x7F) {
                        out.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        out.append('"');
    }

    @Override
    public String toString() {
        return line.toString();
    }
}
