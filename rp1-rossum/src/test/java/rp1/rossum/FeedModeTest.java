package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlacementRequestHandler;
import rp1.rossum.request.RsRequest;
import rp1.rossum.request.RsTimeoutRequest;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.WireOut;

/**
 * A connection fed bytes by a non-blocking reader ({@link RsConnection#receive}) handles the handshake
 * and the client's messages exactly as a connection reading a stream does, however the bytes are cut.
 */
@Timeout(60)
class FeedModeTest {
    private static final int ACK = 5;

    /** What a real client sends: CONNECT, its body, some requests and an interlock acknowledgement. */
    private static byte[] clientSession() throws Exception {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsClient client = ClientEventLoopTest.quietClient();
        byte[] accept = new WireOut().header(0, 0, 1, RsProtocol.ACCEPT).toByteArray();
        client.setInputOutputStreams(new ByteArrayInputStream(accept), sent);
        client.exchangeIntroductions();
        RsBody body = new RsBody("fed");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.1));
        client.sendBodySpecification(body);
        client.sendPlacementRequest("home");
        client.sendMotionRequest(new RsMotionRequest(0.5, 0.25, 3.0));
        client.sendTimeoutRequest(-1.0);
        client.sendTargetSelectionRequest("F1", true);
        client.send(RsProtocol.INTERLOCK, new WireOut().i32(ACK));
        return sent.toByteArray();
    }

    private static final class Received {
        final List<String> requests = new ArrayList<>();
        final List<Integer> acks = new ArrayList<>();
        final ClientEventLoopTest.RecordingInterlock interlock = new ClientEventLoopTest.RecordingInterlock();
        final RsConnection connection = new RsConnection();
        final ServerRecorder recorder = new ServerRecorder(connection);
        final ByteArrayOutputStream answered = new ByteArrayOutputStream();

        Received() {
            connection.setLogger(null);
            connection.setInputOutputStreams(null, answered);
            connection.addInterlock(interlock);
        }

        List<String> drain() throws InterruptedException {
            Object o;
            while ((o = recorder.received.poll(0)) != null) {
                requests.add(describe(o));
            }
            Integer ack;
            while ((ack = interlock.closed.poll(0)) != null) {
                acks.add(ack);
            }
            return requests;
        }

        private String describe(Object o) {
            if (o instanceof RsBody) {
                return "body " + Arrays.toString(BodyCodec.encode((RsBody) o));
            }
            if (o instanceof RsTimeoutRequest) {
                return "timeout " + recorder.timeoutDuration;
            }
            return o instanceof RsRequest
                    ? Arrays.toString(RequestCodec.encode((RsRequest) o).toByteArray())
                    : String.valueOf(o);
        }
    }

    /** The reference: a connection reading the same bytes as a stream. */
    private static Received readAsStream(byte[] bytes) throws Exception {
        Received r = new Received();
        r.connection.setInputOutputStreams(new ByteArrayInputStream(bytes), r.answered);
        r.connection.exchangeIntroductions();
        r.connection.run();
        r.drain();
        return r;
    }

    private static Received fed(byte[] bytes, int... cuts) throws Exception {
        Received r = new Received();
        int from = 0;
        for (int cut : cuts) {
            r.connection.receive(bytes, from, cut - from);
            from = cut;
        }
        r.connection.receive(bytes, from, bytes.length - from);
        r.drain();
        return r;
    }

    @Test
    void bytesCutAtEveryPointGiveWhatTheStreamGives() throws Exception {
        byte[] bytes = clientSession();
        Received reference = readAsStream(bytes);
        assertEquals(5, reference.requests.size(), reference.requests.toString());
        for (int cut = 0; cut <= bytes.length; cut++) {
            Received r = fed(bytes, cut);
            assertEquals(reference.requests, r.requests, "cut at byte " + cut);
            assertEquals(List.of(ACK), r.acks, "cut at byte " + cut);
            assertArrayEquals(reference.answered.toByteArray(), r.answered.toByteArray(), "the ACCEPT, cut at " + cut);
        }
    }

    @Test
    void bytesArrivingOneAtATimeGiveWhatTheStreamGives() throws Exception {
        byte[] bytes = clientSession();
        Received r = new Received();
        for (int i = 0; i < bytes.length; i++) {
            r.connection.receive(bytes, i, 1);
            assertEquals(i >= 19, r.connection.hasIntroduced(), "introduced once the 20 bytes of CONNECT are in");
        }
        assertEquals(readAsStream(bytes).requests, r.drain());
    }

    @Test
    void garbageIsAProtocolErrorNamingTheField() throws Exception {
        Received r = new Received();
        byte[] connect = Arrays.copyOf(clientSession(), 20);
        r.connection.receive(connect, 0, connect.length);
        byte[] garbage = new WireOut().header(0, 0, 2, 99).toByteArray();
        RsProtocolException e = assertThrows(RsProtocolException.class,
                () -> r.connection.receive(garbage, 0, garbage.length));
        assertEquals("header transaction code", e.getField());
    }

    @Test
    void aMessageThatNeverEndsIsRefusedOnceItOutgrowsTheLimit() throws Exception {
        Received r = new Received();
        byte[] connect = Arrays.copyOf(clientSession(), 20);
        r.connection.receive(connect, 0, connect.length);
        WireOut body = new WireOut().header(0, 0, 2, RsProtocol.BODY_SPECIFICATION).str("huge").i32(4000);
        byte[] start = body.toByteArray();
        r.connection.receive(start, 0, start.length);
        byte[] filler = new byte[1 << 16];
        Arrays.fill(filler, (byte) 0x7f);
        assertThrows(RsProtocolException.class, () -> {
            for (int i = 0; i < 100; i++) {
                r.connection.receive(filler, 0, filler.length);
            }
        });
    }

    @Test
    void theEndOfInputInTheMiddleOfAMessageEndsTheSessionAndSaysSo() throws Exception {
        byte[] bytes = clientSession();
        List<String> log = new ArrayList<>();
        Received r = new Received();
        r.connection.setLogger(new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
                log.add(message);
            }
        });
        boolean[] shutDown = {false};
        r.connection.setProtocolShutdownHandler(() -> shutDown[0] = true);
        r.connection.receive(bytes, 0, 30);
        assertFalse(shutDown[0]);
        r.connection.endOfInput();
        assertTrue(shutDown[0]);
        assertTrue(log.get(log.size() - 1).endsWith(
                "terminating due to exception on input: header client key: stream ended in the middle of a message"),
                log.toString());
    }

    /** What the stream reading gives, without the placement (whose handler the tests below replace). */
    private static List<String> withoutThePlacement(List<String> requests) {
        List<String> rest = new ArrayList<>(requests);
        rest.remove(1);
        return rest;
    }

    private static Received withAFailingPlacementHandler(int[] calls) {
        Received r = new Received();
        r.connection.setPlacementRequestHandler(new RsPlacementRequestHandler() {
            @Override
            public void process(RsPlacementRequest request) {
                calls[0]++;
                throw new IllegalStateException("placement handler failed");
            }

            @Override
            public void processRequest(RsRequest request) {
                process((RsPlacementRequest) request);
            }
        });
        return r;
    }

    @Test
    void aMessageWhoseHandlerThrowsIsConsumedAndTheExceptionPropagates() throws Exception {
        byte[] bytes = clientSession();
        int[] placements = {0};
        Received r = withAFailingPlacementHandler(placements);
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> r.connection.receive(bytes, 0, bytes.length));
        assertEquals("placement handler failed", e.getMessage());
        assertEquals(1, placements[0]);
        assertEquals(1, r.drain().size(), "the body came before the placement; what follows it waits");
        r.connection.receive(bytes, 0, 0);
        assertEquals(1, placements[0], "the placement is not handled a second time");
        assertEquals(withoutThePlacement(readAsStream(bytes).requests), r.drain());
        assertEquals(List.of(ACK), r.acks);
    }

    @Test
    void theEndOfInputAfterAHandlerThrewDispatchesWhatWaitsButNotTheFailedMessageAgain() throws Exception {
        byte[] bytes = clientSession();
        int[] placements = {0};
        Received r = withAFailingPlacementHandler(placements);
        List<String> log = new ArrayList<>();
        r.connection.setLogger(new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
                log.add(message);
            }
        });
        assertThrows(IllegalStateException.class, () -> r.connection.receive(bytes, 0, bytes.length));
        r.connection.endOfInput();
        assertEquals(1, placements[0], "the placement is not handled a second time");
        assertEquals(withoutThePlacement(readAsStream(bytes).requests), r.drain());
        assertEquals("RsConnection: client 0 closed the connection", log.get(log.size() - 1), log.toString());
    }

    @Test
    void aMessageCutAcrossCallsDoesNotDependOnTheCallersArrayAfterwards() throws Exception {
        byte[] bytes = clientSession();
        Received reference = readAsStream(bytes);
        for (int cut = 1; cut < bytes.length; cut += 7) {
            Received r = new Received();
            byte[] first = Arrays.copyOf(bytes, cut);
            r.connection.receive(first, 0, first.length);
            Arrays.fill(first, (byte) 0x55);
            byte[] rest = Arrays.copyOfRange(bytes, cut, bytes.length);
            r.connection.receive(rest, 0, rest.length);
            Arrays.fill(rest, (byte) 0x55);
            assertEquals(reference.requests, r.drain(), "cut at byte " + cut);
        }
    }

    @Test
    void aMessageLargerThanTheBufferArrivesWholeAndTheBufferShrinksAfterwards() throws Exception {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsClient client = ClientEventLoopTest.quietClient();
        byte[] accept = new WireOut().header(0, 0, 1, RsProtocol.ACCEPT).toByteArray();
        client.setInputOutputStreams(new ByteArrayInputStream(accept), sent);
        client.exchangeIntroductions();
        RsBody body = new RsBody("big");
        for (int i = 0; i < 3000; i++) {
            body.addPart(new RsBodyCircle(i * 0.001, 0.0, 0.1));
        }
        client.sendBodySpecification(body);
        client.sendPositionRequest();
        byte[] bytes = sent.toByteArray();
        assertTrue(bytes.length > 3 * 64 * 1024, "bigger than one read: " + bytes.length);
        List<String> reference = readAsStream(bytes).requests;
        Received r = new Received();
        for (int from = 0; from < bytes.length; from += 64 * 1024) {
            r.connection.receive(bytes, from, Math.min(64 * 1024, bytes.length - from));
        }
        assertEquals(reference, r.drain());
        assertEquals(2, reference.size());
    }

    @Test
    void anEmptiedBufferGivesBackALargeArray() {
        FeedBuffer feed = new FeedBuffer();
        byte[] big = new byte[1 << 20];
        feed.append(big, 0, 100);
        feed.consume(40);
        assertEquals(60, feed.length);
        feed.append(big, 0, big.length);
        assertEquals(60 + big.length, feed.length);
        feed.consume(feed.length - 10);
        assertEquals(10, feed.length, "not empty: the array stays");
        assertTrue(feed.bytes.length > FeedBuffer.RETAINED_CAPACITY);
        feed.consume(10);
        assertEquals(0, feed.length);
        assertEquals(FeedBuffer.INITIAL_CAPACITY, feed.bytes.length, "empty: back to the initial size");
        feed.append(big, 0, 1000);
        feed.consume(1000);
        assertEquals(FeedBuffer.INITIAL_CAPACITY * 2, feed.bytes.length, "a small array is kept for reuse");
    }

    @Test
    void aReadingThreadAndAFeedLogTheSameLineForAProtocolError() throws Exception {
        byte[] connect = Arrays.copyOf(clientSession(), 20);
        byte[] garbage = new WireOut().header(0, 0, 2, 99).toByteArray();
        byte[] both = Arrays.copyOf(connect, 40);
        System.arraycopy(garbage, 0, both, 20, 20);

        List<String> streamLog = new ArrayList<>();
        Received stream = new Received();
        stream.connection.setLogger(into(streamLog));
        stream.connection.setInputOutputStreams(new ByteArrayInputStream(both), stream.answered);
        stream.connection.exchangeIntroductions();
        stream.connection.run();

        List<String> feedLog = new ArrayList<>();
        Received fed = new Received();
        fed.connection.setLogger(into(feedLog));
        boolean[] shutDown = {false};
        fed.connection.setProtocolShutdownHandler(() -> shutDown[0] = true);
        RsProtocolException e = assertThrows(RsProtocolException.class,
                () -> fed.connection.receive(both, 0, both.length));
        assertFalse(shutDown[0], "receive reports; the caller ends the session");
        fed.connection.inputFailed(e.getMessage());
        assertTrue(shutDown[0]);
        assertEquals(streamLog, feedLog);
        assertTrue(feedLog.get(0).startsWith(
                "RsConnection terminating due to exception on input: header transaction code: "), feedLog.toString());
    }

    private static RsLogAdapter into(List<String> log) {
        return new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
                log.add(message);
            }
        };
    }
}
