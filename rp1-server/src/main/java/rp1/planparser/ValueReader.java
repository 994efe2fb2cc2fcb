package rp1.planparser;

import java.awt.Color;
import java.io.IOException;
import java.util.Arrays;

import rp1.rossum.RsColor;
import rp1.rossum.RsMeters;
import rp1.rossum.RsUnits;

/**
 * Reads the values of specifications (what follows {@code name:} up to the {@code ;}): numeric
 * lists, colour names, strings and unsigned integers, and converts lengths from the plan's current
 * units to metres.
 */
final class ValueReader {
    /** How messages state {@link ParserLimits#MAX_COORDINATE}. */
    static final String LIMIT_IN_WORDS = "the limit of 1000000 m (1000 km) from the origin for any coordinate or"
            + " length of a plan";

    private final PlanLexer lexer;
    private RsUnits units = new RsMeters();

    ValueReader(PlanLexer lexer) {
        this.lexer = lexer;
    }

    /** The units lengths are written in from now on. */
    void setUnits(RsUnits units) {
        this.units = units;
    }

    PlanLexer lexer() {
        return lexer;
    }

    /**
     * A numeric list: numbers separated by commas, each optionally preceded by one {@code -}. The list
     * ends before a {@code ;} or {@code }}, which is left for the caller.
     */
    NumberList numbers() throws IOException, RsParsingException {
        double[] values = new double[8];
        Token[] tokens = new Token[8];
        int n = 0;
        while (true) {
            Token t = lexer.nextInStatement();
            boolean negative = t.is('-');
            if (negative) {
                t = lexer.nextInStatement();
            }
            if (!t.isNumber()) {
                throw lexer.error(t, "Invalid syntax where numeric specification expected, found " + t.describe());
            }
            if (n == ParserLimits.MAX_LIST_NUMBERS) {
                throw lexer.error(t, "Too many numbers in one specification: the limit is "
                        + ParserLimits.MAX_LIST_NUMBERS);
            }
            if (n == values.length) {
                values = Arrays.copyOf(values, 2 * n);
                tokens = Arrays.copyOf(tokens, 2 * n);
            }
            tokens[n] = t;
            values[n++] = negative ? -t.number() : t.number();
            Token separator = lexer.nextInStatement();
            if (separator.is(';') || separator.is('}')) {
                lexer.pushBack(separator);
                return new NumberList(Arrays.copyOf(values, n), Arrays.copyOf(tokens, n), separator);
            }
            if (!separator.is(',')) {
                throw lexer.error(separator, "Invalid syntax where comma expected between numbers, found "
                        + separator.describe());
            }
        }
    }

    /**
     * A numeric list of exactly {@code count} numbers.
     *
     * @param problem the start of the message if the count is wrong
     * @param meaning what the numbers are, for the message
     */
    NumberList numbers(int count, String problem, String meaning) throws IOException, RsParsingException {
        NumberList list = numbers();
        if (list.values().length != count) {
            throw lexer.error(list.end(), problem + ": expected " + count + " (" + meaning + "), found "
                    + list.values().length);
        }
        return list;
    }

    /**
     * {@code value} in the current units, in metres; {@code at} is the number it was written as. A
     * length beyond {@link ParserLimits#MAX_COORDINATE} is refused there.
     */
    double length(double value, Token at) throws RsParsingException {
        double metres = units.userToInternal(value);
        if (!(Math.abs(metres) <= ParserLimits.MAX_COORDINATE)) {
            throw lexer.error(at, "Value out of range: " + (value < 0 ? "-" : "") + at.text() + " "
                    + units.getName() + " is beyond " + LIMIT_IN_WORDS);
        }
        return metres;
    }

    /** The {@code i}th number of {@code list} as a length in metres. */
    double length(NumberList list, int i) throws RsParsingException {
        return length(list.values()[i], list.tokens()[i]);
    }

    /** The numbers of {@code list}, lengths in the current units, in metres. */
    double[] lengths(NumberList list) throws RsParsingException {
        double[] metres = new double[list.values().length];
        for (int i = 0; i < metres.length; i++) {
            metres[i] = length(list, i);
        }
        return metres;
    }

    /** A colour name (one of the thirteen, case-sensitive). */
    Color color() throws IOException, RsParsingException {
        Token t = lexer.nextInStatement();
        if (!t.isIdentifier()) {
            throw lexer.error(t, "Invalid syntax where color specification expected, found " + t.describe());
        }
        Color c = RsColor.getColorForName(t.text());
        if (c == null) {
            throw lexer.error(t, "Invalid value where color name expected: \"" + t.text() + "\" (the colors are "
                    + String.join(", ", RsColor.getColorNames()) + ")");
        }
        return c;
    }

    /** A quoted string. */
    String string() throws IOException, RsParsingException {
        Token t = lexer.nextInStatement();
        if (t.kind() != Token.Kind.STRING) {
            throw lexer.error(t, "Invalid syntax where quoted string expected, found " + t.describe());
        }
        return t.text();
    }

    /** An integer token without sign; {@code expected} starts the message otherwise. */
    Token integer(String expected) throws IOException, RsParsingException {
        Token t = lexer.nextInStatement();
        if (t.kind() != Token.Kind.INTEGER) {
            throw lexer.error(t, expected + ", found " + t.describe());
        }
        return t;
    }

    /** The next token, which must be an identifier; {@code expected} starts the message otherwise. */
    Token identifier(String expected) throws IOException, RsParsingException {
        Token t = lexer.nextInStatement();
        if (!t.isIdentifier()) {
            throw lexer.error(t, expected + ", found " + t.describe());
        }
        return t;
    }

    /** Consumes the symbol {@code c}; {@code expected} starts the message otherwise. */
    void symbol(char c, String expected) throws IOException, RsParsingException {
        Token t = lexer.nextInStatement();
        if (!t.is(c)) {
            throw lexer.error(t, expected + ", found " + t.describe());
        }
    }
}
