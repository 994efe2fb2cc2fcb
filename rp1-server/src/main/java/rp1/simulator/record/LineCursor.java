package rp1.simulator.record;

import java.awt.Color;
import java.util.function.Function;

/**
 * Reads the fields of one recording line in order (the forms {@link TextLine} writes). Every error
 * names the file, the line and the field that was expected.
 */
final class LineCursor {
    private final String file;
    private final int number;
    private final String text;
    private int pos;

    /** The line numbered {@code number} (from 1) of {@code file}. */
    LineCursor(String file, int number, String text) {
        this.file = file;
        this.number = number;
        this.text = text;
    }

    int number() {
        return number;
    }

    /** An error at this line. */
    RecordingException error(String message) {
        return new RecordingException(file + ":" + number + ": " + message);
    }

    boolean atEnd() {
        return pos >= text.length();
    }

    /** The next space-delimited word; {@code what} names it in the error if there is none. */
    String word(String what) throws RecordingException {
        if (atEnd()) {
            throw error("the line ends where " + what + " was expected");
        }
        int end = text.indexOf(' ', pos);
        if (end < 0) {
            end = text.length();
        }
        if (end == pos) {
            throw error("an empty field where " + what + " was expected (fields are separated by one space)");
        }
        String w = text.substring(pos, end);
        pos = Math.min(text.length(), end + 1);
        if (end == text.length() - 1) {
            throw error("the line ends with a space after " + what);
        }
        return w;
    }

    long integer(String what) throws RecordingException {
        return parsed(what, "an integer", Long::parseLong);
    }

    /** An integer in the range of an int. */
    int smallInteger(String what) throws RecordingException {
        long v = integer(what);
        if (v < Integer.MIN_VALUE || v > Integer.MAX_VALUE) {
            throw error(what + ": " + v + " is out of range");
        }
        return (int) v;
    }

    /**
     * A finite number: what a recording holds came from the wire, which refuses NaN and infinities, or
     * from the view; a recording with one was edited, and would replay as a run that never was.
     */
    double real(String what) throws RecordingException {
        double v = parsed(what, "a number", Double::parseDouble);
        if (!Double.isFinite(v)) {
            throw error(what + ": a finite number was expected, found " + v);
        }
        return v;
    }

    /** The next word as {@code parse} reads it; {@code kind} says what it should have been. */
    private <T> T parsed(String what, String kind, Function<String, T> parse) throws RecordingException {
        String w = word(what);
        try {
            return parse.apply(w);
        } catch (NumberFormatException e) {
            throw error(what + ": " + kind + " was expected, found \"" + w + "\"");
        }
    }

    boolean bool(String what) throws RecordingException {
        String w = word(what);
        if (w.equals("true")) {
            return true;
        }
        if (w.equals("false")) {
            return false;
        }
        throw error(what + ": true or false was expected, found \"" + w + "\"");
    }

    /** Quoted text (null for {@code -}). */
    String text(String what) throws RecordingException {
        if (atEnd()) {
            throw error("the line ends where " + what + " was expected");
        }
        if (text.startsWith("- ", pos) || (pos == text.length() - 1 && text.charAt(pos) == '-')) {
            word(what);
            return null;
        }
        if (text.charAt(pos) != '"') {
            throw error(what + ": quoted text was expected");
        }
        StringBuilder out = new StringBuilder();
        int i = pos + 1;
        while (true) {
            if (i >= text.length()) {
                throw error(what + ": the closing quote is missing");
            }
            char c = text.charAt(i++);
            if (c == '"') {
                break;
            }
            if (c != '\\') {
                out.append(c);
                continue;
            }
            if (i >= text.length()) {
                throw error(what + ": the line ends inside an escape");
            }
            i = unescape(text.charAt(i), i + 1, out, what);
        }
        if (i < text.length() && text.charAt(i) != ' ') {
            throw error(what + ": a space was expected after the closing quote");
        }
        if (i == text.length() - 1) {
            throw error("the line ends with a space after " + what);
        }
        pos = Math.min(text.length(), i + 1);
        return out.toString();
    }

    /** Appends what escape {@code c} stands for; returns where the text goes on. */
    private int unescape(char c, int next, StringBuilder out, String what) throws RecordingException {
        switch (c) {
            case '"', '\\' -> out.append(c);
            case 'n' -> out.append('\n');
            case 'r' -> out.append('\r');
            case 't' -> out.append('\t');
            case 'u' -> {
                if (next + 4 > text.length()) {
                    throw error(what + ": \\u needs four hexadecimal digits");
                }
                try {
                    out.append((char) Integer.parseInt(text.substring(next, next + 4), 16));
                } catch (NumberFormatException e) {
                    throw error(what + ": \\u needs four hexadecimal digits");
                }
                return next + 4;
            }
            default -> throw error(what + ": unknown escape \\" + c);
        }
        return next;
    }

    /** {@code #rrggbb}, {@code #rrggbbaa}, or {@code -} for none (null). */
    Color color(String what) throws RecordingException {
        String w = word(what);
        if (w.equals("-")) {
            return null;
        }
        if (w.charAt(0) != '#' || (w.length() != 7 && w.length() != 9)) {
            throw error(what + ": a colour #rrggbb or #rrggbbaa was expected, found \"" + w + "\"");
        }
        try {
            int rgb = Integer.parseInt(w.substring(1, 7), 16);
            int alpha = w.length() == 9 ? Integer.parseInt(w.substring(7), 16) : 255;
            return new Color((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF, alpha);
        } catch (NumberFormatException e) {
            throw error(what + ": a colour #rrggbb or #rrggbbaa was expected, found \"" + w + "\"");
        }
    }

    /** Checks that nothing follows the fields read. */
    void end() throws RecordingException {
        if (!atEnd()) {
            throw error("unexpected text at the end of the line: \"" + text.substring(pos) + "\"");
        }
    }
}
