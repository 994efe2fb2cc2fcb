package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsContactSensorEventHandler;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsMouseClickEventHandler;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.event.RsTimeoutEventHandler;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.WireIn;

/** The client's event loop as a client programmer sees it: handler order, consume, subscriptions, interlock, shutdown. */
@Timeout(30)
class ClientEventLoopTest {

    @Test
    void handlersRunInRegistrationOrderUntilOneConsumes() throws Exception {
        try (Link link = Link.piped(quietClient(), new RsConnection())) {
            List<String> calls = new ArrayList<>();
            Capture<Boolean> done = new Capture<>();
            RsClient c = link.client;
            c.addTimeoutEventHandler(e -> calls.add("first " + e.timeoutIndex));
            c.addTimeoutEventHandler(e -> {
                calls.add("second " + e.timeoutIndex);
                if (e.timeoutIndex == 2) {
                    e.consume();
                }
            });
            c.addTimeoutEventHandler(e -> {
                calls.add("third " + e.timeoutIndex);
                if (e.timeoutIndex == 2) {
                    done.add(true);
                }
            });
            c.addTimeoutEventHandler(e -> done.add(true));
            link.startServer().startClientLoop();
            link.connection.sendTimeoutEvent(new RsTimeoutEvent(1.0, 1));
            done.next();
            link.connection.sendTimeoutEvent(new RsTimeoutEvent(2.0, 2));
            link.connection.sendTimeoutEvent(new RsTimeoutEvent(3.0, 3));
            done.next();
            assertEquals(Arrays.asList("first 1", "second 1", "third 1", "first 2", "second 2", "first 3", "second 3",
                    "third 3"), calls);
        }
    }

    @Test
    void aHandlerThatThrowsDoesNotStopTheOthersOrTheLoop() throws Exception {
        try (Link link = Link.piped(quietClient(), new RsConnection())) {
            Capture<Integer> seen = new Capture<>();
            link.client.addTimeoutEventHandler(e -> {
                throw new IllegalStateException("robot brain bug");
            });
            link.client.addTimeoutEventHandler(e -> seen.add(e.timeoutIndex));
            link.startServer().startClientLoop();
            link.connection.sendTimeoutEvent(new RsTimeoutEvent(1.0, 1));
            link.connection.sendTimeoutEvent(new RsTimeoutEvent(2.0, 2));
            assertEquals(1, seen.next());
            assertEquals(2, seen.next());
        }
    }

    @Test
    void subscriptionsFollowTheOriginalBookkeeping() throws Exception {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsClient c = quietClient();
        RsMouseClickEventHandler early = e -> { };
        c.addMouseClickEventHandler(early);
        c.setInputOutputStreams(new ByteArrayInputStream(new byte[0]), sent);
        RsMouseClickEventHandler h1 = e -> { };
        RsMouseClickEventHandler h2 = e -> { };
        c.addMouseClickEventHandler(h1);
        c.addMotionStartedEventHandler(e -> { });
        c.addMotionStartedEventHandler(e -> { });
        RsTimeoutEventHandler t = e -> { };
        c.addTimeoutEventHandler(t);
        c.removeTimeoutEventHandler(t);
        c.removeMotionStartedEventHandler();
        c.addMotionStartedEventHandler(e -> { });
        c.removeMouseClickEventHandler(h2);

        List<String> subscriptions = subscriptionsIn(sent.toByteArray());
        assertEquals(Arrays.asList(
                "6/0 on",
                "6/0 off",
                "6/0 on",
                "1/0 off"), subscriptions,
                "a handler added before the connection is never subscribed, later adds for that key send nothing; "
                        + "only the first handler of a key subscribes; every removal unsubscribes; the no-argument "
                        + "removal drops every handler of the key, so the next add subscribes again");
    }

    @Test
    void theNoArgumentRemovalDropsEveryHandlerOfItsKind() throws Exception {
        try (Link link = Link.piped(quietClient(), new RsConnection())) {
            List<Integer> removed = new ArrayList<>();
            Capture<Integer> added = new Capture<>();
            link.client.addTimeoutEventHandler(e -> removed.add(e.timeoutIndex));
            link.client.addTimeoutEventHandler(e -> removed.add(e.timeoutIndex));
            link.client.removeTimeoutEventHandler();
            link.client.addTimeoutEventHandler(e -> added.add(e.timeoutIndex));
            link.startServer().startClientLoop();
            link.connection.sendTimeoutEvent(new RsTimeoutEvent(1.0, 1));
            assertEquals(1, added.next());
            assertEquals(List.of(), removed, "RP1 0.60 kept these handlers (a defect: docs/differences.md)");
        }
    }

    @Test
    void removingAHandlerAddedTwiceRemovesItEntirelySoTheNextAddSubscribesAgain() throws Exception {
        try (Link link = Link.piped(quietClient(), new RsConnection())) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer().startClientLoop();
            RsClient c = link.client;
            RsBodyContactSensor bumper = new RsBodyContactSensor(new double[] {0, 0, 0.1, 0, 0.1, 0.1}, 3);
            int id = bumper.getID();
            Capture<Double> calls = new Capture<>();
            RsContactSensorEventHandler h = e -> calls.add(e.simTime);
            c.addContactSensorEventHandler(bumper, h);
            c.addContactSensorEventHandler(bumper, h);
            c.removeContactSensorEventHandler(bumper, h);
            c.addContactSensorEventHandler(bumper, h);
            assertSubscription(server.received.next(), id, true);
            assertSubscription(server.received.next(), id, false);
            assertSubscription(server.received.next(), id, true);
            assertTrue(link.connection.isClientSubscribedToEvent(RsEvent.EVT_CONTACT_SENSOR, id),
                    "the sensor's events reach the client again");

            link.connection.sendContactSensorEvent(new RsContactSensorEvent(1.0, id, true, "wall"));
            link.connection.sendContactSensorEvent(new RsContactSensorEvent(2.0, id, false, ""));
            assertEquals(1.0, calls.next());
            assertEquals(2.0, calls.next(), "the handler is registered once, so it runs once per event");
            assertNull(calls.poll(100));
        }
    }

    private static void assertSubscription(Object received, int index, boolean enable) {
        RsSubscriptionRequest r = (RsSubscriptionRequest) received;
        assertEquals(RsEvent.EVT_CONTACT_SENSOR + "/" + index + " " + enable, r.eventCode + "/" + r.eventIndex + " " + r.eventEnable);
    }

    @Test
    void aLocalHandlerAddedTwiceIsGoneAfterOneRemoval() throws Exception {
        try (Link link = Link.piped(quietClient(), new RsConnection())) {
            List<Integer> removed = new ArrayList<>();
            Capture<Integer> kept = new Capture<>();
            RsTimeoutEventHandler h = e -> removed.add(e.timeoutIndex);
            link.client.addTimeoutEventHandler(h);
            link.client.addTimeoutEventHandler(h);
            link.client.addTimeoutEventHandler(e -> kept.add(e.timeoutIndex));
            link.client.removeTimeoutEventHandler(h);
            link.startServer().startClientLoop();
            link.connection.sendTimeoutEvent(new RsTimeoutEvent(1.0, 1));
            assertEquals(1, kept.next());
            assertEquals(List.of(), removed);
        }
    }

    /** Decodes a stream of subscription requests (37 bytes each: header, prefix, code, index, flag). */
    private static List<String> subscriptionsIn(byte[] stream) throws Exception {
        final int size = 37;
        assertEquals(0, stream.length % size, "only subscription requests were sent");
        List<String> out = new ArrayList<>();
        RecordingSink sink = new RecordingSink();
        for (int offset = 0; offset < stream.length; offset += size) {
            RequestCodec.decode(WireIn.of(Arrays.copyOfRange(stream, offset + 20, offset + size)), sink);
            RsSubscriptionRequest r = (RsSubscriptionRequest) sink.last;
            out.add(r.eventCode + "/" + r.eventIndex + (r.eventEnable ? " on" : " off"));
        }
        return out;
    }

    @Test
    void registeringANullHandlerIsANullPointerExceptionNamingTheArgument() {
        RsClient c = quietClient();
        assertEquals("handler", assertThrows(NullPointerException.class, () -> c.addTimeoutEventHandler(null)).getMessage());
        assertEquals("handler", assertThrows(NullPointerException.class, () -> c.addMouseClickEventHandler(null)).getMessage());
    }

    @Test
    void theInterlockIsAcknowledgedOnlyAfterTheLastHandlerReturns() throws Exception {
        try (Link link = Link.piped(quietClient(), new RsConnection())) {
            RecordingInterlock interlock = new RecordingInterlock();
            link.connection.addInterlock(interlock);
            CountDownLatch release = new CountDownLatch(1);
            Capture<Boolean> inHandler = new Capture<>();
            link.client.addTimeoutEventHandler(e -> { });
            link.client.addTimeoutEventHandler(e -> {
                inHandler.add(true);
                try {
                    release.await(10, TimeUnit.SECONDS);
                } catch (InterruptedException ex) {
                    Thread.currentThread().interrupt();
                }
            });
            link.startServer().startClientLoop();
            link.connection.sendTimeoutEvent(new RsTimeoutEvent(1.0, 1));
            inHandler.next();
            assertNull(interlock.closed.poll(300), "no acknowledgement while a handler is still running");
            release.countDown();
            assertEquals(1, interlock.closed.next());
            assertEquals(1, link.connection.getMaxInterlockSent());
        }
    }

    @Test
    void eventsWithoutHandlersAreStillAcknowledged() throws Exception {
        try (Link link = Link.piped(quietClient(), new RsConnection())) {
            RecordingInterlock interlock = new RecordingInterlock();
            link.connection.addInterlock(interlock);
            link.startServer().startClientLoop();
            link.connection.sendTimeoutEvent(new RsTimeoutEvent(1.0, 1));
            link.connection.sendHeartbeatEvent(2.0, 1);
            assertEquals(1, interlock.closed.next());
            assertEquals(2, interlock.closed.next());
        }
    }

    @Test
    void theShutdownHandlerRunsAndTheLoopReturnsWhenTheServerGoesAway() throws Exception {
        Link link = Link.piped(quietClient(), new RsConnection());
        link.startServer().startClientLoop();
        link.connection.shutdown();
        assertTrue(link.clientShutdown.next());
        link.awaitClientLoopEnd();
        assertNull(link.clientShutdown.poll(100), "the shutdown handler runs once");
        link.client.sendPositionRequest();
        link.client.sendTimeoutRequest(1.0);
    }

    @Test
    void theServerNoticesWhenTheClientGoesAway() throws Exception {
        Link link = Link.piped(quietClient(), new RsConnection());
        link.startServer();
        link.client.shutdown();
        assertTrue(link.connectionShutdown.next());
    }

    @Test
    void sendingBeforeConnectingIsAnError() {
        RsClient c = quietClient();
        assertThrows(IllegalStateException.class, c::sendPositionRequest);
    }

    static RsClient quietClient() {
        RsClient c = new RsClient();
        c.setLogger(QuietLog.INSTANCE);
        return c;
    }

    /** An interlock that hands out 1, 2, 3, ... and records acknowledgements. */
    static final class RecordingInterlock implements RsInterlock {
        final Capture<Integer> closed = new Capture<>();
        private final AtomicInteger counter = new AtomicInteger();

        @Override
        public int openInterlock() {
            return counter.incrementAndGet();
        }

        @Override
        public boolean closeInterlock(int interlock) {
            closed.add(interlock);
            return interlock >= counter.get();
        }

        @Override
        public int getMaximumInterlockIndex() {
            return counter.get();
        }
    }
}
