package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.Arrays;

import org.junit.jupiter.api.Test;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;

/** The worked hex examples of protocol.md section 13, byte for byte, both ways. */
class HexExamplesTest {
    private static final String CONNECT = "00000000 00000000 00000000 00000000 00000001";
    private static final String ACCEPT = "00000000 00000000 00000000 00000001 00000002";

    @Test
    void clientHandshakeSendsConnectWithSequenceZeroAndAdoptsTheAcceptIdentity() throws Exception {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsClient client = new RsClient();
        client.setLogger(QuietLog.INSTANCE);
        client.setInputOutputStreams(new ByteArrayInputStream(Hex.bytes("00000000 00000007 0000002a 00000001 00000002")), sent);
        client.exchangeIntroductions();
        assertEquals(Hex.of(Hex.bytes(CONNECT)), Hex.of(sent.toByteArray()));
        assertEquals(7, client.clientID);
        assertEquals(42, client.clientKey);
    }

    @Test
    void serverHandshakeEchoesTheClientIdentityInAcceptWithSequenceOne() throws Exception {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsConnection connection = new RsConnection();
        connection.setInputOutputStreams(new ByteArrayInputStream(Hex.bytes(CONNECT)), sent);
        connection.exchangeIntroductions();
        assertEquals(Hex.of(Hex.bytes(ACCEPT)), Hex.of(sent.toByteArray()));
    }

    @Test
    void placementRequestForHomeIs38BytesWithTwoLengths() throws Exception {
        byte[] sent = afterHandshake(c -> {
            c.sendPlanRequest();
            c.sendPlacementRequest("home");
        });
        byte[] placement = Arrays.copyOfRange(sent, sent.length - 38, sent.length);
        assertEquals(Hex.of(Hex.bytes("00000000 00000000 00000000 00000003 00000004 00000007 00000000 00000004 0004 686f6d65")),
                Hex.of(placement));
    }

    @Test
    void namelessPlacementRequestEndsAfterTheZeroFlag() {
        assertEquals("00000007 00000000 00000000", Hex.of(RequestCodec.placement(null).toByteArray()));
        assertEquals("00000007 00000000 00000000", Hex.of(RequestCodec.placement("").toByteArray()));
        assertEquals("00000007 00000000 00000007 00072472 616e646f 6d", Hex.of(RequestCodec.placement("$random").toByteArray()));
    }

    @Test
    void subscriptionForTargetSensorFiveDecodesBack() throws Exception {
        byte[] payload = RequestCodec.subscription(4, 5, true).toByteArray();
        assertEquals("00000001 00000000 00000004 00000005 01", Hex.of(payload));
        RecordingSink sink = new RecordingSink();
        RequestCodec.decode(WireIn.of(payload), sink);
        RsSubscriptionRequest r = (RsSubscriptionRequest) sink.last;
        assertEquals(4, r.eventCode);
        assertEquals(5, r.eventIndex);
        assertTrue(r.eventEnable);
    }

    @Test
    void timeoutEventIs44BytesAndDecodesBack() throws Exception {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsConnection connection = new RsConnection();
        connection.setInputOutputStreams(new ByteArrayInputStream(new byte[0]), sent);
        connection.sequence = 4;
        connection.sendTimeoutEvent(new RsTimeoutEvent(2.5, 1));
        byte[] expected = Hex.bytes("00000000 00000000 00000000 00000005 00000003 00000005 00000000 4004000000000000 00000000 00000001");
        assertEquals(Hex.of(expected), Hex.of(sent.toByteArray()));

        RsTimeoutEvent back = (RsTimeoutEvent) decodeEvent(expected).event;
        assertEquals(2.5, back.simTime);
        assertEquals(1, back.timeoutIndex);
    }

    @Test
    void interlockedTimeoutEventIsAcknowledgedWithA24ByteInterlockTransaction() throws Exception {
        byte[] event = Hex.bytes("00000000 00000000 00000000 00000005 00000003 00000005 00000000 4004000000000000 00000002 00000001");
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsClient client = new RsClient();
        client.setLogger(QuietLog.INSTANCE);
        client.setInputOutputStreams(new ByteArrayInputStream(event), sent);
        client.run();
        assertEquals(Hex.of(Hex.bytes("00000000 00000000 00000000 00000001 00000006 00000002")), Hex.of(sent.toByteArray()));
    }

    @Test
    void placementEventIs71BytesWithTheOrientationUnnormalized() throws Exception {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsConnection connection = new RsConnection();
        connection.setInputOutputStreams(new ByteArrayInputStream(new byte[0]), sent);
        connection.sequence = 5;
        double orientation = 225 * Math.PI / 180;
        connection.sendPlacementEvent(new RsPlacementEvent(1.25, true, "home", 2.5, 2.5, orientation));
        byte[] expected = Hex.bytes("00000000 00000000 00000000 00000006 00000003 00000008 00000000 3ff4000000000000 00000000"
                + " 01 0004 686f6d65 4004000000000000 4004000000000000 400f6a7a2955385e");
        assertEquals(71, expected.length);
        assertEquals(Hex.of(expected), Hex.of(sent.toByteArray()));

        RsPlacementEvent back = (RsPlacementEvent) decodeEvent(expected).event;
        assertTrue(back.valid);
        assertEquals("home", back.name);
        assertEquals(3.9269908169872414, back.orientation);
    }

    @Test
    void invalidPlacementForANamelessRequestCarriesAnEmptyNameAndZeroPose() throws Exception {
        WireOut out = new WireOut();
        EventCodec.encode(out, new RsPlacementEvent(0.0, false, null, 0, 0, 0), 0);
        byte[] b = out.toByteArray();
        String tail = Hex.of(Arrays.copyOfRange(b, 20, b.length)).replace(" ", "");
        assertEquals("000000000000000000000000000000000000000000000000000000", tail);
        RsPlacementEvent back = (RsPlacementEvent) EventCodec.decode(WireIn.of(b)).event;
        assertFalse(back.valid);
        assertEquals("", back.name);
    }

    private interface ClientAction {
        void run(RsClient c) throws Exception;
    }

    /** What a socket client sends after its handshake (so sequence numbers start at 2). */
    private static byte[] afterHandshake(ClientAction action) throws Exception {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsClient client = new RsClient();
        client.setLogger(QuietLog.INSTANCE);
        client.setInputOutputStreams(new ByteArrayInputStream(Hex.bytes(ACCEPT)), sent);
        client.exchangeIntroductions();
        action.run(client);
        return sent.toByteArray();
    }

    private static EventCodec.Decoded decodeEvent(byte[] message) throws Exception {
        WireIn in = WireIn.of(Arrays.copyOfRange(message, 20, message.length));
        return EventCodec.decode(in);
    }
}
