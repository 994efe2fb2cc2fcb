package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Garbage, truncated and hostile input: the reader stops with one clear message naming the field and
 * the value it saw, calls the shutdown handler, and returns. Nothing hangs or spins.
 */
@Timeout(30)
class BadInputTest {
    private static final String HEADER_EVENT = "00000000 00000000 00000000 00000001 00000003";

    /** Runs a client over {@code bytes}; returns its log lines after {@code run()} returned. */
    private static List<String> runClientOn(byte[] bytes) {
        RsClient client = new RsClient();
        List<String> log = new ArrayList<>();
        client.setLogger(new ListLogger(log));
        boolean[] shutdown = {false};
        client.setProtocolShutdownHandler(() -> shutdown[0] = true);
        client.setInputOutputStreams(new ByteArrayInputStream(bytes), new ByteArrayOutputStream());
        client.run();
        assertTrue(shutdown[0], "shutdown handler called");
        assertTrue(client.isClosed(), "the session is closed");
        return log;
    }

    private static void assertLogged(List<String> log, String fragment) {
        assertTrue(log.stream().anyMatch(l -> l.contains(fragment)), "expected a log line containing '" + fragment + "', got " + log);
    }

    @Test
    void wrongVersionIsNamed() {
        assertLogged(runClientOn(Hex.bytes("00000001 00000000 00000000 00000001 00000003")),
                "header version: expected 0, got 1");
    }

    @Test
    void clientIdOrKeyMismatchIsNamed() {
        assertLogged(runClientOn(Hex.bytes("00000000 00000009 00000000 00000001 00000003")),
                "header client id: expected 0, got 9");
        assertLogged(runClientOn(Hex.bytes("00000000 00000000 ffffffff 00000001 00000003")),
                "header client key: expected 0, got -1");
    }

    @Test
    void unknownTransactionCodeIsNamed() {
        assertLogged(runClientOn(Hex.bytes("00000000 00000000 00000000 00000001 00000007")),
                "header transaction code: unknown code 7");
    }

    @Test
    void anInterlockTransactionSentToAClientIsAnOrderlyProtocolError() {
        assertLogged(runClientOn(Hex.bytes("00000000 00000000 00000000 00000001 00000006 00000001")),
                "a client accepts only EVENT (3), got INTERLOCK (6)");
    }

    @Test
    void unknownEventCodeIsNamed() {
        assertLogged(runClientOn(Hex.bytes(HEADER_EVENT + " 00000063 00000000 0000000000000000 00000000")),
                "event code: unknown code 99");
    }

    @Test
    void aStreamEndingMidEventNamesTheField() {
        assertLogged(runClientOn(Hex.bytes(HEADER_EVENT + " 00000002 00000000 0000000000000000 00000000 3ff00000")),
                "position x: stream ended in the middle of a message");
    }

    @Test
    void invalidTextNamesTheField() {
        assertLogged(runClientOn(Hex.bytes(HEADER_EVENT + " 00000009 00000000 0000000000000000 00000000 01 0002 ff41")),
                "target selection name: invalid modified UTF-8");
    }

    @Test
    void aCleanCloseBetweenMessagesIsNotReportedAsAProtocolError() {
        List<String> log = runClientOn(Hex.bytes(HEADER_EVENT + " 0000000c 00000000 3ff0000000000000 00000000 00000001"));
        assertLogged(log, "the server closed the connection");
    }

    /**
     * Each run ends the session (see {@link #runClientOn}) with exactly one line saying why: the
     * server went away between messages, or the field that was wrong and what was wrong with it.
     */
    @Test
    void randomGarbageAlwaysEndsTheSessionWithOneReason() {
        Random random = new Random(20261121L);
        Map<String, Integer> problems = new TreeMap<>();
        for (int i = 0; i < 500; i++) {
            byte[] garbage = new byte[random.nextInt(200)];
            random.nextBytes(garbage);
            if (garbage.length > 20 && random.nextBoolean()) {
                System.arraycopy(Hex.bytes(HEADER_EVENT), 0, garbage, 0, 20);
            }
            List<String> log = runClientOn(garbage);
            List<String> reasons = log.stream().filter(l -> l.startsWith("X ")).collect(Collectors.toList());
            assertEquals(1, reasons.size(), "one line says why the session ended: " + log);
            Matcher m = TERMINATION.matcher(reasons.get(0));
            assertTrue(m.matches(), "the reason names the field and the problem: " + reasons.get(0));
            problems.merge(m.group(1) != null ? m.group(1) : m.group(3).replaceAll("-?\\d+", "N"), 1, Integer::sum);
        }
        assertEquals(Set.of("expected N, got N", "unknown code N", "stream ended in the middle of a message",
                "the server closed the connection"), problems.keySet(), "the garbage reached every kind of check: " + problems);
    }

    private static final Pattern TERMINATION = Pattern.compile(
            "X RsClient terminating: (?:(the server closed the connection)|([a-z][\\w ()]*): (.+))");

    @Test
    void aServerConnectionRejectsClientOnlyTransactions() throws Exception {
        RsConnection c = new RsConnection();
        List<String> log = new ArrayList<>();
        c.setLogger(new ListLogger(log));
        c.setInputOutputStreams(new ByteArrayInputStream(Hex.bytes(HEADER_EVENT)), new ByteArrayOutputStream());
        c.run();
        assertLogged(log, "a server does not accept EVENT (3) after the handshake");
    }

    @Test
    void aHugeActuatorParameterCountIsRefusedBeforeAllocating() throws Exception {
        RsConnection c = new RsConnection();
        List<String> log = new ArrayList<>();
        c.setLogger(new ListLogger(log));
        byte[] request = Hex.bytes("00000000 00000000 00000000 00000001 00000004 0000000c 00000000 00000005 00000003 7fffffff");
        c.setInputOutputStreams(new ByteArrayInputStream(request), new ByteArrayOutputStream());
        c.run();
        assertLogged(log, "actuator parameter count: 2147483647 is outside the accepted range");
    }

    @Test
    void anUnknownRequestCodeIsNamed() throws Exception {
        RsConnection c = new RsConnection();
        List<String> log = new ArrayList<>();
        c.setLogger(new ListLogger(log));
        byte[] request = Hex.bytes("00000000 00000000 00000000 00000001 00000004 0000000e 00000000");
        c.setInputOutputStreams(new ByteArrayInputStream(request), new ByteArrayOutputStream());
        c.run();
        assertLogged(log, "request code: unknown code 14");
    }

    /** A logger that keeps its lines in a list. */
    static final class ListLogger extends RsLogAdapter {
        private final List<String> lines;

        ListLogger(List<String> lines) {
            super(true);
            this.lines = lines;
        }

        @Override
        public synchronized void logIt(String level, String message) {
            lines.add(level + " " + message);
        }
    }
}
