package rp1.web;

import java.awt.Color;
import java.util.Locale;

/**
 * A JSON text being written: just the forms the page's data needs (numbers, text, colours, arrays
 * and objects), with the commas put in by the writer. Not thread-safe.
 */
final class Json {
    private final StringBuilder out = new StringBuilder();
    /** Whether the value about to be written is the first in its array or object. */
    private boolean first = true;

    Json beginObject() {
        separate();
        out.append('{');
        first = true;
        return this;
    }

    Json endObject() {
        out.append('}');
        first = false;
        return this;
    }

    Json beginArray() {
        separate();
        out.append('[');
        first = true;
        return this;
    }

    Json endArray() {
        out.append(']');
        first = false;
        return this;
    }

    /** The name of the next member of an object. */
    Json key(String name) {
        separate();
        text(out, name);
        out.append(':');
        first = true;
        return this;
    }

    Json value(long v) {
        separate();
        out.append(v);
        return this;
    }

    /** A number as Java writes a double (integral values without ".0"); non-finite numbers as null. */
    Json value(double v) {
        separate();
        if (!Double.isFinite(v)) {
            out.append("null");
        } else if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            out.append((long) v);
        } else {
            out.append(v);
        }
        return this;
    }

    Json value(boolean v) {
        separate();
        out.append(v ? '1' : '0');
        return this;
    }

    /** Text, or null. */
    Json value(String v) {
        separate();
        if (v == null) {
            out.append("null");
        } else {
            text(out, v);
        }
        return this;
    }

    /** A colour as {@code "#rrggbb"} ({@code "#rrggbbaa"} when not opaque), or null for none. */
    Json color(Color c) {
        if (c == null) {
            return value((String) null);
        }
        String rgb = String.format(Locale.ROOT, "#%02x%02x%02x", c.getRed(), c.getGreen(), c.getBlue());
        return value(c.getAlpha() == 255 ? rgb : rgb + String.format(Locale.ROOT, "%02x", c.getAlpha()));
    }

    /** Already written JSON, as one value. */
    Json raw(String json) {
        separate();
        out.append(json);
        return this;
    }

    private void separate() {
        if (!first) {
            out.append(',');
        }
        first = false;
    }

    private static void text(StringBuilder out, String s) {
        out.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                // "</" would end the script element the data sits in; "<" escaped keeps it out.
                case '<' -> out.append("\\u003c");
                default -> {
                    if (c < 0x20 || c == 0x2028 || c == 0x2029) {
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
        return out.toString();
    }
}
