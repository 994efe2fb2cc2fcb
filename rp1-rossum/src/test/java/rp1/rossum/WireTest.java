package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.io.EOFException;

import org.junit.jupiter.api.Test;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;

/** The primitive encodings of protocol.md section 2, checked from byte arrays. */
class WireTest {

    @Test
    void integersAndDoublesAreBigEndian() {
        byte[] b = new WireOut().i32(0x01020304).f64(2.5).toByteArray();
        assertEquals("01020304 40040000 00000000", Hex.of(b));
    }

    @Test
    void nanIsWrittenInCanonicalForm() {
        assertEquals("7ff80000 00000000", Hex.of(new WireOut().f64(Double.longBitsToDouble(0x7ff0000000000abcL)).toByteArray()));
    }

    @Test
    void nullAndEmptyStringsAreBothTwoZeroBytes() throws Exception {
        assertEquals("0000", Hex.of(new WireOut().str(null).toByteArray()));
        assertEquals("0000", Hex.of(new WireOut().str("").toByteArray()));
        assertEquals("", WireIn.of(Hex.bytes("0000")).str("s"));
    }

    @Test
    void stringsUseModifiedUtf8() throws Exception {
        String s = "A\u0000\u00e9\u20ac\uD83D\uDE00";
        byte[] b = new WireOut().str(s).toByteArray();
        assertEquals("000e41c0 80c3a9e2 82aceda0 bdedb880", Hex.of(b));
        assertEquals(s, WireIn.of(b).str("s"));
    }

    @Test
    void invalidModifiedUtf8NamesTheField() {
        RsProtocolException e = assertThrows(RsProtocolException.class,
                () -> WireIn.of(Hex.bytes("0002 c328")).str("placement name"));
        assertEquals("placement name", e.getField());
        assertTrue(e.getMessage().contains("invalid modified UTF-8"), e.getMessage());
    }

    @Test
    void overlongStringIsRefusedBeforeAnythingIsWritten() {
        WireOut out = new WireOut();
        String big = "x".repeat(65536);
        assertThrows(IllegalArgumentException.class, () -> out.str(big));
        assertEquals(0, out.size());
        assertEquals(65537, new WireOut().str("y".repeat(65535)).size(), "the 65535-byte limit itself is fine");
    }

    @Test
    void colorsCarryAPresenceFlag() throws Exception {
        byte[] b = new WireOut().color(new Color(255, 200, 0)).color(null).toByteArray();
        assertEquals("00000001 000000ff 000000c8 00000000 00000000", Hex.of(b));
        WireIn in = WireIn.of(b);
        assertEquals(new Color(255, 200, 0), in.color("fill"));
        assertNull(in.color("line"));
    }

    @Test
    void colorComponentOutOfRangeNamesTheComponent() {
        RsProtocolException e = assertThrows(RsProtocolException.class,
                () -> WireIn.of(Hex.bytes("00000001 00000100 00000000 00000000")).color("fill"));
        assertEquals("fill red", e.getField());
        assertTrue(e.getMessage().contains("256"), e.getMessage());
    }

    @Test
    void emptyColorArrayIsNull() throws Exception {
        assertEquals("00000000", Hex.of(new WireOut().colorArray(new Color[0]).toByteArray()));
        assertNull(WireIn.of(Hex.bytes("00000000")).colorArray("colors"));
        Color[] two = {Color.red, null};
        assertArrayEquals(two, WireIn.of(new WireOut().colorArray(two).toByteArray()).colorArray("colors"));
    }

    @Test
    void countsOutsideTheirRangeAreRefusedWithTheValueSeen() {
        RsProtocolException negative = assertThrows(RsProtocolException.class,
                () -> WireIn.of(Hex.bytes("ffffffff")).count("part count", 10));
        assertTrue(negative.getMessage().startsWith("part count: -1 is outside"), negative.getMessage());
        RsProtocolException huge = assertThrows(RsProtocolException.class,
                () -> WireIn.of(Hex.bytes("7fffffff")).count("part count", 10));
        assertTrue(huge.getMessage().contains("2147483647"), huge.getMessage());
    }

    @Test
    void aStreamEndingInsideAFieldIsAProtocolError() {
        RsProtocolException e = assertThrows(RsProtocolException.class, () -> WireIn.of(Hex.bytes("0000")).f64("range"));
        assertEquals("range", e.getField());
        assertTrue(e.getMessage().contains("ended in the middle"), e.getMessage());
    }

    @Test
    void aStreamEndingBetweenMessagesIsAPlainEndOfFile() {
        assertThrows(EOFException.class, () -> WireIn.of(new byte[0]).firstI32("header version"));
        assertThrows(RsProtocolException.class, () -> WireIn.of(Hex.bytes("00")).firstI32("header version"));
    }

    @Test
    void anyNonZeroByteReadsAsTrue() throws Exception {
        assertTrue(WireIn.of(Hex.bytes("7f")).bool("flag"));
        assertEquals("01", Hex.of(new WireOut().bool(true).toByteArray()));
    }
}
