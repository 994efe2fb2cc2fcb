package rp1.planparser;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads the YAML file ROS's {@code map_server} describes a map with: a flat mapping of {@code key: value}
 * lines, {@code #} comments, values plain, quoted ({@code "..."} or {@code '...'}) or a flow list
 * ({@code [x, y, yaw]}). That is all such a file uses, so this small reader replaces a YAML library
 * (and its dependency) and can name line and column in every error. Nested mappings, block lists,
 * anchors and multi-line values are refused with a message saying so.
 *
 * <p>Keys: {@code image} and {@code resolution} are required; {@code origin} (default
 * {@code [0, 0, 0]}, yaw in radians), {@code occupied_thresh} (0.65), {@code free_thresh} (0.196),
 * {@code negate} (0) and {@code mode} ({@code trinary} or {@code scale}, which draw the same walls)
 * are optional. Any other key is an error, so a misspelt threshold is not silently ignored.
 */
final class MapYaml {
    private static final Pattern KEY = Pattern.compile("([A-Za-z_][A-Za-z0-9_]*)[ \\t]*:(?=[ \\t]|$)");
    private static final Pattern NUMBER = Pattern.compile("[-+]?(\\.[0-9]+|[0-9]+(\\.[0-9]*)?)([eE][-+]?[0-9]+)?");
    private static final List<String> KEYS =
            List.of("image", "resolution", "origin", "occupied_thresh", "free_thresh", "negate", "mode");

    /** A value as written and where it starts. */
    record Value(String text, int line, int column) {
    }

    private final String fileName;
    private final Map<String, Value> values = new HashMap<>();
    private int endLine = 1;

    private MapYaml(String fileName) {
        this.fileName = fileName;
    }

    /**
     * The map settings of the YAML text {@code text}, read from {@code fileName}; the image is
     * named as written (the caller resolves it against the file).
     *
     * @throws RsParsingException naming file, line and column of the first problem
     */
    static MapYaml parse(String text, String fileName) throws RsParsingException {
        MapYaml yaml = new MapYaml(fileName);
        yaml.read(text);
        return yaml;
    }

    /** The settings the file gives. */
    MapSpec spec() throws RsParsingException {
        Value image = required("image", "the map image's file name");
        double resolution = number(required("resolution", "metres per pixel"), "resolution");
        if (!(resolution > 0)) {
            throw error(values.get("resolution"), "resolution must be above zero (metres per pixel), found "
                    + values.get("resolution").text());
        }
        double[] origin = origin();
        double occupied = threshold("occupied_thresh", MapSpec.DEFAULT_OCCUPIED);
        double free = threshold("free_thresh", MapSpec.DEFAULT_FREE);
        if (free > occupied) {
            throw error(values.get("free_thresh"), "free_thresh " + free + " is above occupied_thresh " + occupied
                    + ": a pixel cannot be both free and occupied");
        }
        checkMode();
        return new MapSpec(unquoted(image), resolution, origin[0], origin[1], origin[2], occupied, free, negate());
    }

    /** Where the value of {@code key} is written, or the end of the file if it is not. */
    Value at(String key) {
        Value v = values.get(key);
        return v != null ? v : new Value("", endLine, 1);
    }

    private void read(String text) throws RsParsingException {
        String[] lines = text.split("\r\n|\r|\n", -1);
        endLine = lines.length;
        for (int i = 0; i < lines.length; i++) {
            line(lines[i], i + 1);
        }
    }

    private void line(String raw, int number) throws RsParsingException {
        String line = withoutComment(raw, number);
        if (line.isBlank() || (number == 1 && line.strip().equals("---"))) {
            return;
        }
        if (Character.isWhitespace(line.charAt(0))) {
            throw new RsParsingException(fileName, number, 1, "Indented line: a map file is a flat list of"
                    + " 'key: value' lines (nested mappings and block lists are not supported)");
        }
        Matcher m = KEY.matcher(line);
        if (!m.lookingAt()) {
            throw new RsParsingException(fileName, number, 1, "Invalid syntax where 'key: value' expected, found \""
                    + line.strip() + "\"");
        }
        String key = m.group(1);
        if (!KEYS.contains(key)) {
            throw new RsParsingException(fileName, number, 1, "Unknown key " + key + " (a map file takes "
                    + String.join(", ", KEYS) + ")");
        }
        int start = m.end();
        while (start < line.length() && Character.isWhitespace(line.charAt(start))) {
            start++;
        }
        Value v = new Value(line.substring(start).strip(), number, start + 1);
        if (v.text().isEmpty()) {
            throw error(v, "Missing value for " + key + " (multi-line values are not supported)");
        }
        Value previous = values.put(key, v);
        if (previous != null) {
            throw new RsParsingException(fileName, number, 1, "Duplicate key " + key + " (first given on line "
                    + previous.line() + ")");
        }
    }

    /**
     * The line without a trailing comment: a '#' at the start or after white space, outside quotes. A
     * quote starts a string only where a value or list item starts ({@code bob's.pgm} is plain).
     */
    private String withoutComment(String line, int number) throws RsParsingException {
        char quote = 0;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quote != 0) {
                quote = c == quote ? 0 : quote;
            } else if ((c == '"' || c == '\'') && (i == 0 || " \t[,".indexOf(line.charAt(i - 1)) >= 0)) {
                quote = c;
            } else if (c == '#' && (i == 0 || Character.isWhitespace(line.charAt(i - 1)))) {
                return line.substring(0, i);
            } else if ((c == '&' || c == '*' || c == '{' || c == '|' || c == '>') && (i == 0
                    || Character.isWhitespace(line.charAt(i - 1)))) {
                throw new RsParsingException(fileName, number, i + 1, "Unsupported YAML: " + c + " (anchors, aliases,"
                        + " flow mappings and block scalars are not used by map files)");
            }
        }
        if (quote != 0) {
            throw new RsParsingException(fileName, number, line.indexOf(quote) + 1, "Unterminated string: expected a"
                    + " closing " + quote + " on the same line");
        }
        return line;
    }

    private Value required(String key, String meaning) throws RsParsingException {
        Value v = values.get(key);
        if (v == null) {
            throw new RsParsingException(fileName, endLine, 1, "Missing key " + key + " (" + meaning
                    + "): a map file needs image and resolution");
        }
        return v;
    }

    private double[] origin() throws RsParsingException {
        Value v = values.get("origin");
        if (v == null) {
            return new double[3];
        }
        String t = v.text();
        if (!t.startsWith("[") || !t.endsWith("]")) {
            throw error(v, "Invalid origin: expected [x, y, yaw] (metres, metres, radians), found " + t);
        }
        List<Value> items = new ArrayList<>();
        int from = 1;
        for (int i = 1; i < t.length(); i++) {
            if (t.charAt(i) == ',' || i == t.length() - 1) {
                String item = t.substring(from, i);
                int lead = item.length() - item.stripLeading().length();
                items.add(new Value(item.strip(), v.line(), v.column() + from + lead));
                from = i + 1;
            }
        }
        if (items.size() != 3) {
            throw error(v, "Invalid origin: expected 3 numbers [x, y, yaw], found " + items.size());
        }
        double[] xyYaw = new double[3];
        for (int i = 0; i < 3; i++) {
            xyYaw[i] = number(items.get(i), "origin");
        }
        return xyYaw;
    }

    private double threshold(String key, double otherwise) throws RsParsingException {
        Value v = values.get(key);
        if (v == null) {
            return otherwise;
        }
        double t = number(v, key);
        if (t < 0 || t > 1) {
            throw error(v, key + " must be between 0 and 1, found " + v.text());
        }
        return t;
    }

    private boolean negate() throws RsParsingException {
        Value v = values.get("negate");
        if (v == null) {
            return false;
        }
        switch (unquoted(v)) {
            case "0":
            case "false":
                return false;
            case "1":
            case "true":
                return true;
            default:
                throw error(v, "negate must be 0 or 1, found " + v.text());
        }
    }

    private void checkMode() throws RsParsingException {
        Value v = values.get("mode");
        if (v != null && !unquoted(v).equals("trinary") && !unquoted(v).equals("scale")) {
            throw error(v, "Unsupported mode " + v.text() + ": expected trinary or scale (raw maps hold"
                    + " occupancy values, not an image)");
        }
    }

    private double number(Value v, String key) throws RsParsingException {
        String t = unquoted(v);
        if (!NUMBER.matcher(t).matches()) {
            throw error(v, "Invalid number for " + key + ": " + (t.isEmpty() ? "nothing" : t));
        }
        double d = Double.parseDouble(t);
        if (Double.isInfinite(d)) {
            throw error(v, "Number out of range for " + key + ": " + t);
        }
        return d;
    }

    private static String unquoted(Value v) {
        String t = v.text();
        if (t.length() >= 2 && (t.charAt(0) == '"' || t.charAt(0) == '\'') && t.charAt(t.length() - 1) == t.charAt(0)) {
            return t.substring(1, t.length() - 1);
        }
        return t;
    }

    RsParsingException error(Value at, String reason) {
        return new RsParsingException(fileName, at.line(), at.column(), reason);
    }
}
