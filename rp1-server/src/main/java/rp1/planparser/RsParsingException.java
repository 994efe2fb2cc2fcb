package rp1.planparser;

/**
 * A floor plan could not be read. The message has the form {@code FILE:LINE:COLUMN: reason}, where the
 * position is that of the offending token (lines and columns count from 1; a tab is one column) and
 * the reason says what was expected and what was found. Parsing stops at the first error.
 */
public class RsParsingException extends Exception {
    private static final long serialVersionUID = 1L;

    private final String fileName;
    private final int line;
    private final int column;
    private final String reason;

    /** An error at {@code line}, {@code column} of {@code fileName}; {@code reason} explains it. */
    public RsParsingException(String fileName, int line, int column, String reason) {
        super(fileName + ":" + line + ":" + column + ": " + reason);
        this.fileName = fileName;
        this.line = line;
        this.column = column;
        this.reason = reason;
    }

    /** The name of the plan file, as given to the parser. */
    public String getFileName() {
        return fileName;
    }

    /** The line of the offending token, from 1. */
    public int getLine() {
        return line;
    }

    /** The column of the offending token's first character, from 1. */
    public int getColumn() {
        return column;
    }

    /** The message without the position prefix. */
    public String getReason() {
        return reason;
    }
}
