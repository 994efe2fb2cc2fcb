package rp1.planparser;

import java.io.IOException;

import rp1.planparser.Token.Kind;

/**
 * Splits a floor plan into tokens (behavior.md section 1.2): identifiers, strings with escapes,
 * integers (decimal or 0x hexadecimal), reals, and one-character symbols. White space (code points
 * 1 to 32, and everything above 127 outside strings), line comments and block comments are skipped.
 * Lexical errors are reported at the offending character.
 */
final class PlanLexer {
    private final CharSource chars;
    private final String fileName;
    private Token pushedBack;
    private Token statementStart;

    PlanLexer(CharSource chars, String fileName) {
        this.chars = chars;
        this.fileName = fileName;
    }

    /** The next token; at the end of the input, an {@link Kind#END} token (again and again). */
    Token next() throws IOException, RsParsingException {
        if (pushedBack != null) {
            Token t = pushedBack;
            pushedBack = null;
            return t;
        }
        return scan();
    }

    /** The next token, which must not be the end of the input: the current statement is unfinished. */
    Token nextInStatement() throws IOException, RsParsingException {
        Token t = next();
        if (t.isEnd()) {
            throw error(t, "Encountered premature end-of-file while reading statement"
                    + (statementStart == null ? "" : " starting at line " + statementStart.line()));
        }
        return t;
    }

    /** Makes {@code t} the next token again (one token of push-back). */
    void pushBack(Token t) {
        pushedBack = t;
    }

    /** Records the first token of the statement being read, for end-of-file messages. */
    void startStatement(Token first) {
        statementStart = first;
    }

    /** An error at the position of {@code t}. */
    RsParsingException error(Token t, String reason) {
        return new RsParsingException(fileName, t.line(), t.column(), reason);
    }

    private Token scan() throws IOException, RsParsingException {
        while (true) {
            skipWhiteSpace();
            int line = chars.line();
            int column = chars.column();
            int c = chars.peek();
            if (c != '/') {
                return token(c, line, column);
            }
            chars.read();
            int d = chars.peek();
            if (d == '/') {
                skipLineComment();
            } else if (d == '*') {
                chars.read();
                skipBlockComment(line, column);
            } else {
                return new Token(Kind.SYMBOL, "/", 0, 0.0, line, column);
            }
        }
    }

    private Token token(int c, int line, int column) throws IOException, RsParsingException {
        if (c == CharSource.END) {
            return new Token(Kind.END, "", 0, 0.0, line, column);
        } else if (isIdentifierStart(c)) {
            return identifier(line, column);
        } else if (c == '"') {
            return string(line, column);
        } else if (isDigit(c) || c == '.') {
            return new NumberLexer(chars, fileName).scan(line, column);
        }
        chars.read();
        return new Token(Kind.SYMBOL, String.valueOf((char) c), 0, 0.0, line, column);
    }

    private void skipWhiteSpace() throws IOException {
        int c = chars.peek();
        while ((c >= 1 && c <= ' ') || c > 127) {
            chars.read();
            c = chars.peek();
        }
    }

    private void skipLineComment() throws IOException {
        int c = chars.read();
        while (c != '\n' && c != CharSource.END) {
            c = chars.read();
        }
    }

    private void skipBlockComment(int line, int column) throws IOException, RsParsingException {
        int previous = 0;
        while (true) {
            int c = chars.read();
            if (c == CharSource.END) {
                throw new RsParsingException(fileName, line, column, "End of file encountered within comment"
                        + " starting at line " + line + ": expected '*/' to close it");
            }
            if (previous == '*' && c == '/') {
                return;
            }
            previous = c;
        }
    }

    private Token identifier(int line, int column) throws IOException, RsParsingException {
        StringBuilder text = new StringBuilder();
        while (isIdentifierStart(chars.peek()) || isDigit(chars.peek())) {
            append(text, chars.read());
        }
        return new Token(Kind.IDENTIFIER, text.toString(), 0, 0.0, line, column);
    }

    private Token string(int line, int column) throws IOException, RsParsingException {
        chars.read();
        StringBuilder text = new StringBuilder();
        while (true) {
            int c = chars.read();
            if (c == '"') {
                return new Token(Kind.STRING, text.toString(), 0, 0.0, line, column);
            }
            if (c == '\\') {
                c = chars.read();
                checkInString(c, line, column);
                c = c == 'n' ? '\n' : c == 't' ? '\t' : c;
            } else {
                checkInString(c, line, column);
            }
            append(text, c);
        }
    }

    /**
     * Rejects a raw line break or the end of the input inside a string. The original looped forever
     * at the end of the input; here both are errors at the opening quote.
     */
    private void checkInString(int c, int line, int column) throws RsParsingException {
        if (c == '\n' || c == CharSource.END) {
            throw new RsParsingException(fileName, line, column, (c == '\n' ? "End-of-line" : "End of file")
                    + " within quoted string: expected a closing '\"' on line " + line);
        }
    }

    /** Appends {@code c} to a token's text, refusing absurdly long tokens. */
    static void append(StringBuilder text, int c, String fileName, CharSource at) throws RsParsingException {
        if (text.length() >= ParserLimits.MAX_TOKEN_LENGTH) {
            throw new RsParsingException(fileName, at.line(), at.column(), "Token too long: identifiers, strings"
                    + " and numbers are limited to " + ParserLimits.MAX_TOKEN_LENGTH + " characters");
        }
        text.append((char) c);
    }

    private void append(StringBuilder text, int c) throws RsParsingException {
        append(text, c, fileName, chars);
    }

    static boolean isIdentifierStart(int c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
    }

    static boolean isDigit(int c) {
        return c >= '0' && c <= '9';
    }
}
