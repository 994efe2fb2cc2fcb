package rp1.planparser;

import java.io.IOException;
import java.io.Reader;

/**
 * The characters of a plan with one character of look-ahead and the position of the next character.
 * LF, CR LF and a lone CR are each delivered as a single {@code '\n'}, so the lexer never sees CR
 * (the original mishandled a lone CR after a number or identifier and aborted the process).
 */
final class CharSource {
    /** Returned at the end of the input. */
    static final int END = -1;
    private static final int NONE = -2;

    private final Reader in;
    private int rawLookahead = NONE;
    private int lookahead = NONE;
    private int line = 1;
    private int column = 1;

    CharSource(Reader in) {
        this.in = in;
    }

    /** The next character without consuming it, or {@link #END}. */
    int peek() throws IOException {
        if (lookahead == NONE) {
            lookahead = readNormalized();
        }
        return lookahead;
    }

    /** Consumes and returns the next character, or {@link #END}. */
    int read() throws IOException {
        int c = peek();
        lookahead = NONE;
        if (c == '\n') {
            line++;
            column = 1;
        } else if (c != END) {
            column++;
        }
        return c;
    }

    /** The line of the next character, from 1. */
    int line() {
        return line;
    }

    /** The column of the next character, from 1. */
    int column() {
        return column;
    }

    private int readNormalized() throws IOException {
        int c = readRaw();
        if (c == '\r') {
            int d = readRaw();
            if (d != '\n') {
                rawLookahead = d;
            }
            return '\n';
        }
        return c;
    }

    private int readRaw() throws IOException {
        if (rawLookahead != NONE) {
            int c = rawLookahead;
            rawLookahead = NONE;
            return c;
        }
        return in.read();
    }
}
