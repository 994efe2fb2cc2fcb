package rp1.simulator.batch;

import java.util.Map;
import java.util.Properties;

/** Entries written as a properties file writes them, for {@link Properties#load} to read back as they were. */
public final class PropertiesText {
    private PropertiesText() {
    }

    /**
     * The entries as lines of a properties file, in their order, escaped as {@link Properties#store}
     * escapes them (characters outside printable ASCII as a backslash, u and four hex digits), without
     * its date line, so that {@link Properties#load} reads them back. Written by hand because a sweep
     * writes two per run (run.ini and result.txt), and the store's date and escaping ran in the
     * interpreter for most of a 64-run sweep.
     */
    public static String of(Map<String, String> entries) {
        StringBuilder text = new StringBuilder(64 * entries.size());
        entries.forEach((key, value) -> {
            escape(text, key, true);
            text.append('=');
            escape(text, value, false);
            text.append('\n');
        });
        return text.toString();
    }

    private static void escape(StringBuilder out, String s, boolean key) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case ' ' -> out.append(key || i == 0 ? "\\ " : " ");
                case '\t' -> out.append("\\t");
                case '\n' -> out.append("\\n");
                case '\r' -> out.append("\\r");
                case '\f' -> out.append("\\f");
                case '=', ':', '#', '!', '\\' -> out.append('\\').append(c);
                default -> {
                    if (c < 0x20 || c > 0x7e) {
                        out.append("\\u");
                        for (int shift = 12; shift >= 0; shift -= 4) {
                            out.append(Character.forDigit((c >> shift) & 15, 16));
                        }
                    } else {
                        out.append(c);
                    }
                }
            }
        }
    }
}
