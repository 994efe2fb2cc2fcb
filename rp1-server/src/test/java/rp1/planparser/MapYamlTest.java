package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** The map_server YAML subset: the keys map files use, and every error at its line and column. */
class MapYamlTest {
    private static MapSpec spec(String text) throws RsParsingException {
        return MapYaml.parse(text, "m.yaml").spec();
    }

    private static String failure(String text) {
        return assertThrows(RsParsingException.class, () -> spec(text)).getMessage();
    }

    @Test
    void readsWhatMapSaverWrites() throws Exception {
        MapSpec s = spec("image: ./office.pgm\nresolution: 0.050000\norigin: [-12.2, -3.5e1, 0.7853]\n"
                + "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n");
        assertEquals(new MapSpec("./office.pgm", 0.05, -12.2, -35.0, 0.7853, 0.65, 0.196, false), s);
    }

    @Test
    void takesCommentsQuotesADocumentMarkerAndDefaults() throws Exception {
        MapSpec s = spec("---\n# a map\nimage: \"my map.png\"  # quoted, with a space\nresolution: '0.1'\n"
                + "negate: true\nmode: trinary\n");
        assertEquals(new MapSpec("my map.png", 0.1, 0, 0, 0, 0.65, 0.196, true), s);
        assertEquals("a#b.pgm", spec("image: a#b.pgm\nresolution: 1\n").image(), "a # inside a word is not a comment");
        assertEquals("bob's map.pgm", spec("image: bob's map.pgm # a comment\nresolution: 1\n").image(),
                "an apostrophe inside a plain value starts no string");
    }

    @Test
    void reportsEachProblemWhereItIsWritten() {
        assertEquals("m.yaml:3:1: Missing key resolution (metres per pixel): a map file needs image and resolution",
                failure("image: a.pgm\norigin: [0, 0, 0]\n"));
        assertEquals("m.yaml:2:1: Unknown key ocupied_thresh (a map file takes image, resolution, origin,"
                + " occupied_thresh, free_thresh, negate, mode)", failure("image: a.pgm\nocupied_thresh: 0.6\nresolution: 1"));
        assertEquals("m.yaml:3:16: Invalid number for origin: x", failure("image: a.pgm\nresolution: 1\norigin: [1.5,  x, 0]"));
        assertEquals("m.yaml:2:9: Invalid origin: expected 3 numbers [x, y, yaw], found 2",
                failure("image: a\norigin: [1, 2]\nresolution: 1"));
        assertEquals("m.yaml:2:13: resolution must be above zero (metres per pixel), found 0",
                failure("image: a\nresolution: 0\n"));
        assertEquals("m.yaml:2:8: Missing value for origin (multi-line values are not supported)",
                failure("image: a\norigin:\n  - 1\nresolution: 1"));
        assertEquals("m.yaml:2:1: Indented line: a map file is a flat list of 'key: value' lines (nested mappings"
                + " and block lists are not supported)", failure("image: a\n  resolution: 1"));
        assertEquals("m.yaml:2:1: Duplicate key image (first given on line 1)", failure("image: a\nimage: b\n"));
        assertEquals("m.yaml:3:14: free_thresh 0.7 is above occupied_thresh 0.6: a pixel cannot be both free and"
                + " occupied", failure("image: a\noccupied_thresh: 0.6\nfree_thresh: 0.7\nresolution: 1"));
        assertEquals("m.yaml:2:18: occupied_thresh must be between 0 and 1, found 65",
                failure("image: a\noccupied_thresh: 65\nresolution: 1"));
        assertEquals("m.yaml:2:9: negate must be 0 or 1, found 2", failure("image: a\nnegate: 2\nresolution: 1"));
        assertEquals("m.yaml:2:7: Unsupported mode raw: expected trinary or scale (raw maps hold occupancy values,"
                + " not an image)", failure("image: a\nmode: raw\nresolution: 1"));
        assertEquals("m.yaml:1:8: Unterminated string: expected a closing \" on the same line",
                failure("image: \"a.png\nresolution: 1"));
        assertEquals("m.yaml:1:1: Invalid syntax where 'key: value' expected, found \"image a.pgm\"",
                failure("image a.pgm\nresolution: 1"));
        assertEquals("m.yaml:2:13: Number out of range for resolution: 1e999", failure("image: a\nresolution: 1e999"));
        assertEquals("m.yaml:1:8: Unsupported YAML: & (anchors, aliases, flow mappings and block scalars are not"
                + " used by map files)", failure("image: &x a\nresolution: 1"));
    }
}
