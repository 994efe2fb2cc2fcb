package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Client configuration: the packaged defaults, files, command-line overrides and clear errors. */
class RsPropertiesTest {
    @TempDir
    Path dir;

    private Path file(String name, String content) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, content.getBytes(StandardCharsets.ISO_8859_1));
        return p;
    }

    @Test
    void thePackagedFileGivesTheDocumentedDefaults() {
        RsProperties p = new RsProperties();
        assertEquals(7758, p.port);
        assertEquals("127.0.0.1", p.hostName);
        assertEquals("rossum.log", p.logFileName);
        assertFalse(p.logToFile);
        assertFalse(p.logToSystemOut, "the packaged rossum.ini turns standard-output logging off");
        assertFalse(p.logVerbose);
    }

    @Test
    void laterLoadsMergeAndOnlyTheFirstWordOfAValueCounts() throws Exception {
        RsProperties p = new RsProperties();
        p.loadFromFile(file("a.ini", "port = 9000   # the lab server\nlogVerbose=TRUE trailing words\n").toString());
        assertEquals(9000, p.port);
        assertTrue(p.logVerbose);
        assertEquals("127.0.0.1", p.hostName, "keys not in the new file keep their values");
    }

    @Test
    void aBadPortNamesTheValueAndTheFile() throws Exception {
        Path f = file("bad.ini", "hostName=localhost\nport=77x\n");
        RsPropertiesException e = assertThrows(RsPropertiesException.class, () -> new RsProperties().loadFromFile(f.toString()));
        assertTrue(e.getMessage().contains("Bad number format for integer port specification: \"77x\""), e.getMessage());
        assertTrue(e.getMessage().contains(f.toString()), e.getMessage());
    }

    @Test
    void aPortOutsideTheRangeIsRefused() {
        RsPropertiesException e = assertThrows(RsPropertiesException.class,
                () -> new RsProperties().load(stream("port=65536\n")));
        assertTrue(e.getMessage().startsWith("Integer port number 65536 not in valid range [1,65535]"), e.getMessage());
    }

    @Test
    void everyTcpPortIsAcceptedAsTheServerAcceptsIt() throws Exception {
        RsProperties p = new RsProperties();
        p.load(stream("port=40100\n"));
        assertEquals(40100, p.port);
    }

    @Test
    void aBooleanMustBeTrueOrFalse() {
        RsPropertiesException e = assertThrows(RsPropertiesException.class,
                () -> new RsProperties().load(stream("logToFile=yes\n")));
        assertTrue(e.getMessage().contains("true/false expected for logToFile: \"yes\""), e.getMessage());
    }

    @Test
    void logToFileNeedsAFileName() throws Exception {
        RsPropertiesException e = assertThrows(RsPropertiesException.class,
                () -> new RsProperties(new String[] {"-p", file("c.ini", "hostName=h\nport=2000\nlogToFile=true\n").toString()}));
        assertTrue(e.getMessage().contains("logToFile option was requested, but logFileName is missing"), e.getMessage());
    }

    @Test
    void commandLineOptionsOverrideTheFileGivenWithDashP() throws Exception {
        Path f = file("d.ini", "hostName=robots.example\nport=2000\n");
        RsProperties p = new RsProperties(new String[] {"-p", f.toString(), "-port", "3000", "-logVerbose", "true"});
        assertEquals("robots.example", p.hostName);
        assertEquals(3000, p.port);
        assertTrue(p.logVerbose);
    }

    @Test
    void anOptionWithoutItsValueIsReported() {
        RsPropertiesException e = assertThrows(RsPropertiesException.class,
                () -> new RsProperties(new String[] {"-port", "-hostName", "x"}));
        assertEquals("Missing specification for -port option", e.getMessage());
    }

    @Test
    void extractReadsNumbersAndNamesMissingKeys() throws Exception {
        RsProperties p = new RsProperties();
        p.load(stream("speed=2.5 fast\ncount=12\n"));
        assertEquals(2.5, p.extractDouble("speed"));
        assertEquals(12, p.extractInt("count"));
        assertThrows(RsPropertiesException.class, () -> p.extractInt("speed"));
        RsPropertiesException e = assertThrows(RsPropertiesException.class, () -> p.extractDouble("missing"));
        assertTrue(e.getMessage().contains("missing"), e.getMessage());
    }

    @Test
    void aResourceIsFoundNextToTheAnchorsClass() throws Exception {
        RsProperties p = new RsProperties();
        p.loadFromResource(this, "test-client.ini");
        assertEquals(4321, p.port);
        assertThrows(RsPropertiesException.class, () -> p.loadFromResource(this, "no-such.ini"));
    }

    private static ByteArrayInputStream stream(String s) {
        return new ByteArrayInputStream(("hostName=h\nport=2000\n" + s).getBytes(StandardCharsets.ISO_8859_1));
    }
}
