package rp1.planparser;

/**
 * One token of a floor plan and where it starts. Numbers keep the text they were written as, for
 * messages; signs are separate {@code '-'} symbols, never part of a number.
 *
 * @param kind what sort of token
 * @param text the identifier, the string's contents (escapes resolved), the number as written, or
 *     the one-character symbol; empty at the end of the input
 * @param integer the value of an {@link Kind#INTEGER} token
 * @param real the value of a {@link Kind#REAL} token
 * @param line line of the first character, from 1
 * @param column column of the first character, from 1
 */
record Token(Kind kind, String text, int integer, double real, int line, int column) {
    /** The sorts of token. */
    enum Kind {
        IDENTIFIER, STRING, INTEGER, REAL, SYMBOL, END
    }

    /** Longest piece of a string or identifier quoted in a message. */
    private static final int QUOTE_LIMIT = 40;

    /** Whether this is the one-character symbol {@code c}. */
    boolean is(char c) {
        return kind == Kind.SYMBOL && text.length() == 1 && text.charAt(0) == c;
    }

    boolean isIdentifier() {
        return kind == Kind.IDENTIFIER;
    }

    /** Integer or real: either is accepted wherever a number is. */
    boolean isNumber() {
        return kind == Kind.INTEGER || kind == Kind.REAL;
    }

    /** The value of a number token. */
    double number() {
        return kind == Kind.INTEGER ? integer : real;
    }

    boolean isEnd() {
        return kind == Kind.END;
    }

    /** How the token reads in an error message, e.g. {@code identifier abc} or {@code ';'}. */
    String describe() {
        switch (kind) {
            case IDENTIFIER:
                return "identifier " + shorten(text);
            case STRING:
                return "string \"" + shorten(text) + "\"";
            case INTEGER:
                return "integer " + text;
            case REAL:
                return "number " + text;
            case END:
                return "end of file";
            default:
                return describeCharacter(text.charAt(0));
        }
    }

    /** A character as a message shows it: quoted if printable, else by its code. */
    static String describeCharacter(int c) {
        if (c == CharSource.END) {
            return "end of file";
        } else if (c == '\n') {
            return "end of line";
        } else if (c > ' ' && c < 127) {
            return "'" + (char) c + "'";
        }
        return String.format("character U+%04X", c);
    }

    private static String shorten(String s) {
        return s.length() <= QUOTE_LIMIT ? s : s.substring(0, QUOTE_LIMIT) + "...";
    }
}
