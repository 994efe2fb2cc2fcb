package rp1.planparser;

import java.io.IOException;

import rp1.planparser.Token.Kind;

/**
 * Reads one number (behavior.md section 1.2). Forms: {@code 0x} and 1 to 9 hex digits (an integer,
 * wrapping at 32 bits); {@code digits [. [digits]] [exponent]} or {@code . [digits] [exponent]},
 * where the exponent is {@code e} or {@code E}, a mandatory sign, digits, and optionally a point
 * followed only by zeros. Without point and exponent the number is an integer token (at most
 * 2147483647), otherwise a real. A lone {@code .} is 0.0.
 */
final class NumberLexer {
    private static final int MAX_HEX_DIGITS = 9;

    private final CharSource chars;
    private final String fileName;
    private final StringBuilder text = new StringBuilder();
    private final StringBuilder mantissa = new StringBuilder();
    private final StringBuilder exponent = new StringBuilder();

    NumberLexer(CharSource chars, String fileName) {
        this.chars = chars;
        this.fileName = fileName;
    }

    /** Scans the number starting at the next character (a digit or a point). */
    Token scan(int line, int column) throws IOException, RsParsingException {
        if (chars.peek() == '0') {
            take(mantissa);
            int x = chars.peek();
            if (x == 'x' || x == 'X') {
                take(null);
                return hexadecimal(line, column);
            }
        }
        digits(mantissa);
        boolean real = false;
        if (chars.peek() == '.') {
            real = true;
            take(mantissa);
            digits(mantissa);
        }
        int e = chars.peek();
        if (e == 'e' || e == 'E') {
            real = true;
            take(null);
            exponent();
        }
        if (chars.peek() == '.') {
            throw errorHere("Decimal character out-of-place in numeric: a number has at most one '.'"
                    + " (found another after " + text + ")");
        }
        return real ? real(line, column) : integer(line, column);
    }

    private Token hexadecimal(int line, int column) throws IOException, RsParsingException {
        int value = 0;
        int digits = 0;
        while (isHexDigit(chars.peek())) {
            if (digits == MAX_HEX_DIGITS) {
                throw errorHere("Too many digits in hexadecimal number specification: at most "
                        + MAX_HEX_DIGITS + " hex digits may follow 0x");
            }
            value = (value << 4) | Character.digit(chars.peek(), 16);
            take(null);
            digits++;
        }
        if (digits == 0) {
            throw errorHere("Invalid hexadecimal number specification: expected a hex digit after "
                    + text + ", found " + Token.describeCharacter(chars.peek()));
        }
        return new Token(Kind.INTEGER, text.toString(), value, 0.0, line, column);
    }

    private void exponent() throws IOException, RsParsingException {
        int sign = chars.peek();
        if (sign != '+' && sign != '-') {
            throw errorHere("Invalid character where + or - expected in exponential: the exponent of "
                    + text + " needs a sign, found " + Token.describeCharacter(sign));
        }
        take(exponent);
        if (!PlanLexer.isDigit(chars.peek())) {
            throw errorHere("Invalid character where numeric expected in exponential: expected a digit after "
                    + text + ", found " + Token.describeCharacter(chars.peek()));
        }
        digits(exponent);
        if (chars.peek() == '.') {
            take(null);
            while (chars.peek() == '0') {
                take(null);
            }
            if (PlanLexer.isDigit(chars.peek())) {
                throw errorHere("Exponential specification must be an integer value: only zeros may follow"
                        + " the point in the exponent of " + text + ", found " + Token.describeCharacter(chars.peek()));
            }
        }
    }

    private Token integer(int line, int column) throws RsParsingException {
        long value = 0;
        for (int i = 0; i < mantissa.length(); i++) {
            value = value * 10 + (mantissa.charAt(i) - '0');
            if (value > Integer.MAX_VALUE) {
                throw error(line, column, "Integer specification exceeds max value 2147483647 (found "
                        + text + "); write it as a real, e.g. " + text + ".0, if a large number is meant");
            }
        }
        return new Token(Kind.INTEGER, text.toString(), (int) value, 0.0, line, column);
    }

    private Token real(int line, int column) throws RsParsingException {
        String m = mantissa.toString();
        String canonical = (m.startsWith(".") ? "0" : "") + m + (m.endsWith(".") ? "0" : "")
                + (exponent.length() > 0 ? "e" + exponent : "");
        double value = Double.parseDouble(canonical);
        if (Double.isInfinite(value)) {
            throw error(line, column, "Real number out of range: " + text + " is too large to represent");
        }
        return new Token(Kind.REAL, text.toString(), 0, value, line, column);
    }

    private void digits(StringBuilder part) throws IOException, RsParsingException {
        while (PlanLexer.isDigit(chars.peek())) {
            take(part);
        }
    }

    /** Consumes the next character into the token text and, if given, into {@code part}. */
    private void take(StringBuilder part) throws IOException, RsParsingException {
        int c = chars.peek();
        PlanLexer.append(text, c, fileName, chars);
        chars.read();
        if (part != null) {
            part.append((char) c);
        }
    }

    private static boolean isHexDigit(int c) {
        return Character.digit(c, 16) >= 0 && c < 128;
    }

    private RsParsingException errorHere(String reason) {
        return error(chars.line(), chars.column(), reason);
    }

    private RsParsingException error(int line, int column, String reason) {
        return new RsParsingException(fileName, line, column, reason);
    }
}
