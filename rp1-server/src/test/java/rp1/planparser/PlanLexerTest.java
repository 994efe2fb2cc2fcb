package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.planparser.Token.Kind;

class PlanLexerTest {
    private static List<Token> lex(String text) throws IOException, RsParsingException {
        PlanLexer lexer = new PlanLexer(new CharSource(new StringReader(text)), "t.txt");
        List<Token> tokens = new ArrayList<>();
        for (Token t = lexer.next(); !t.isEnd(); t = lexer.next()) {
            tokens.add(t);
        }
        return tokens;
    }

    private static Token only(String text) throws IOException, RsParsingException {
        List<Token> tokens = lex(text);
        assertEquals(1, tokens.size(), () -> "tokens of " + text + ": " + tokens);
        return tokens.get(0);
    }

    private static RsParsingException failure(String text) {
        return assertThrows(RsParsingException.class, () -> lex(text));
    }

    @Test
    void identifiersAreCaseSensitiveAndMayContainDigitsAndUnderscores() throws Exception {
        Token t = only("_Wall_2b");
        assertEquals(Kind.IDENTIFIER, t.kind());
        assertEquals("_Wall_2b", t.text());
    }

    @Test
    void numberFollowedByLettersIsTwoTokens() throws Exception {
        List<Token> tokens = lex("12abc");
        assertEquals(Kind.INTEGER, tokens.get(0).kind());
        assertEquals(12, tokens.get(0).integer());
        assertEquals("abc", tokens.get(1).text());
    }

    @Test
    void hexadecimalIntegersWrapAt32BitsWithNineDigits() throws Exception {
        assertEquals(31, only("0x1F").integer());
        assertEquals(255, only("0XfF").integer());
        assertEquals(-1, only("0xFFFFFFFF").integer());
        assertEquals(0x23456789, only("0x123456789").integer());
    }

    @Test
    void hexadecimalErrors() {
        assertTrue(failure("0xg").getReason().startsWith("Invalid hexadecimal number specification"));
        RsParsingException tooMany = failure("0x1234567890");
        assertTrue(tooMany.getReason().startsWith("Too many digits in hexadecimal number specification"));
        assertEquals(12, tooMany.getColumn(), "reported at the tenth digit");
    }

    @Test
    void realForms() throws Exception {
        assertEquals(1.5, only("1.5").real());
        assertEquals(0.5, only(".5").real());
        assertEquals(1.0, only("1.").real());
        assertEquals(150.0, only("1.5e+2").real());
        assertEquals(0.2, only("2E-1").real());
        assertEquals(100.0, only("1.0e+2.0").real());
        assertEquals(100.0, only("1e+2.").real());
        assertEquals(Kind.REAL, only("7e+0").kind());
    }

    @Test
    void loneDecimalPointIsTheRealZero() throws Exception {
        Token t = only(".");
        assertEquals(Kind.REAL, t.kind());
        assertEquals(0.0, t.real());
    }

    @Test
    void integerLimitIs2147483647() throws Exception {
        assertEquals(Integer.MAX_VALUE, only("2147483647").integer());
        assertTrue(failure("2147483648").getReason().startsWith("Integer specification exceeds max value 2147483647"));
    }

    @Test
    void exponentErrors() {
        assertTrue(failure("1e5").getReason().startsWith("Invalid character where + or - expected in exponential"));
        assertTrue(failure("1e+x").getReason().startsWith("Invalid character where numeric expected in exponential"));
        assertTrue(failure("1e+2.5").getReason().startsWith("Exponential specification must be an integer value"));
        assertTrue(failure("1e+999").getReason().startsWith("Real number out of range"));
    }

    @Test
    void secondDecimalPointIsOutOfPlace() {
        assertTrue(failure("1..5").getReason().startsWith("Decimal character out-of-place in numeric"));
        RsParsingException e = failure("x 1.5.");
        assertTrue(e.getReason().startsWith("Decimal character out-of-place in numeric"));
        assertEquals(6, e.getColumn());
    }

    @Test
    void signIsASeparateSymbol() throws Exception {
        List<Token> tokens = lex("-1.5");
        assertTrue(tokens.get(0).is('-'));
        assertEquals(1.5, tokens.get(1).real());
    }

    @Test
    void stringEscapes() throws Exception {
        Token t = only("\"a\\\"b\\\\c\\nd\\te\\q\u00e9\"");
        assertEquals(Kind.STRING, t.kind());
        assertEquals("a\"b\\c\nd\teq\u00e9", t.text());
    }

    @Test
    void unterminatedStringsAreErrorsAtTheOpeningQuote() {
        RsParsingException eol = failure("x \"abc\ny");
        assertTrue(eol.getReason().startsWith("End-of-line within quoted string"));
        assertEquals(1, eol.getLine());
        assertEquals(3, eol.getColumn());
        assertTrue(failure("\"abc").getReason().startsWith("End of file within quoted string"));
        assertTrue(failure("\"abc\\").getReason().startsWith("End of file within quoted string"));
    }

    @Test
    void nonAsciiOutsideStringsIsWhiteSpaceButNulIsAToken() throws Exception {
        List<Token> tokens = lex("a\u00e9b\u00a0c");
        assertEquals(3, tokens.size());
        assertEquals("c", tokens.get(2).text());
        assertTrue(only("\0").is('\0'));
    }

    @Test
    void commentsAreSkipped() throws Exception {
        List<Token> tokens = lex("a // b\n/* c * / d **/ e /*/ f */ g");
        assertEquals(List.of("a", "e", "g"), tokens.stream().map(Token::text).toList());
    }

    @Test
    void unterminatedBlockCommentIsReportedWhereItStarts() {
        RsParsingException e = failure("a\n  /* never\nclosed");
        assertTrue(e.getReason().startsWith("End of file encountered within comment starting at line 2"));
        assertEquals(2, e.getLine());
        assertEquals(3, e.getColumn());
    }

    @Test
    void loneSlashIsASymbol() throws Exception {
        assertTrue(only("/").is('/'));
    }

    @Test
    void positionsCountLinesForLfCrLfAndLoneCr() throws Exception {
        for (String nl : new String[] {"\n", "\r\n", "\r"}) {
            List<Token> tokens = lex("a" + nl + "\tbb 12" + nl + nl + "c");
            assertEquals(List.of(1, 2, 2, 4), tokens.stream().map(Token::line).toList(), "line ending " + nl.length());
            assertEquals(List.of(1, 2, 5, 1), tokens.stream().map(Token::column).toList());
        }
    }

    @Test
    void loneCrDirectlyAfterANumberOrIdentifierEndsIt() throws Exception {
        List<Token> tokens = lex("12\rabc\r/\r");
        assertEquals(List.of("12", "abc", "/"), tokens.stream().map(Token::text).toList());
        assertEquals(3, tokens.get(2).line());
    }

    @Test
    void numberAtTheVeryEndOfTheInputIsLexed() throws Exception {
        List<Token> tokens = lex("wall 5");
        assertEquals(5, tokens.get(1).integer());
    }

    @Test
    void absurdlyLongTokensAreRefused() {
        String longName = "a".repeat(ParserLimits.MAX_TOKEN_LENGTH + 1);
        assertTrue(failure(longName).getReason().startsWith("Token too long"));
        assertTrue(failure("\"" + longName + "\"").getReason().startsWith("Token too long"));
    }
}
