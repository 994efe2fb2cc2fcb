package rp1.web;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A CSV file read as text (RFC 4180: fields in double quotes may hold commas, line breaks and
 * doubled quotes): its header and its rows. What the columns mean is not this class's business, so
 * the sweep's files may gain or lose columns without it noticing.
 *
 * @param header the first row
 * @param rows   the others, each as long as it was written
 */
record CsvTable(List<String> header, List<List<String>> rows) {

    /** The table in {@code file}; an empty one if the file is empty. */
    static CsvTable read(Path file) throws IOException {
        List<List<String>> all = parse(new String(Files.readAllBytes(file), StandardCharsets.UTF_8));
        if (all.isEmpty()) {
            return new CsvTable(List.of(), List.of());
        }
        return new CsvTable(all.get(0), all.subList(1, all.size()));
    }

    /** The index of column {@code name}, or -1. */
    int column(String name) {
        return header.indexOf(name);
    }

    /** Row {@code r}'s value in column {@code name}, or "" if it has none. */
    String value(List<String> row, String name) {
        int c = column(name);
        return c >= 0 && c < row.size() ? row.get(c) : "";
    }

    static List<List<String>> parse(String text) {
        List<List<String>> rows = new ArrayList<>();
        List<String> row = new ArrayList<>();
        StringBuilder field = new StringBuilder();
        boolean quoted = false;
        boolean any = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (quoted) {
                if (c == '"' && i + 1 < text.length() && text.charAt(i + 1) == '"') {
                    field.append('"');
                    i++;
                } else if (c == '"') {
                    quoted = false;
                } else {
                    field.append(c);
                }
            } else if (c == '"') {
                quoted = true;
                any = true;
            } else if (c == ',') {
                row.add(field.toString());
                field.setLength(0);
                any = true;
            } else if (c == '\n' || c == '\r') {
                if (c == '\r' && i + 1 < text.length() && text.charAt(i + 1) == '\n') {
                    i++;
                }
                if (any || field.length() > 0) {
                    row.add(field.toString());
                    rows.add(row);
                }
                row = new ArrayList<>();
                field.setLength(0);
                any = false;
            } else {
                field.append(c);
                any = true;
            }
        }
        if (any || field.length() > 0) {
            row.add(field.toString());
            rows.add(row);
        }
        return rows;
    }
}
