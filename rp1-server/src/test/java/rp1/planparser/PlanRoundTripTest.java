package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import rp1.rossum.RsNavLink;
import rp1.rossum.RsNavNode;
import rp1.rossum.RsObject;
import rp1.rossum.RsClient;
import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsConnection;
import rp1.rossum.RsPaint;
import rp1.rossum.RsPipe;
import rp1.rossum.RsPlan;
import rp1.rossum.event.RsPlanEvent;

/**
 * Every plan, parsed and sent as a plan event by a server connection, reaches the client's plan
 * handler with the same objects: type, name, geometry, and the labels and colours the protocol
 * carries. Client and connection are joined by in-memory pipes, as the simulator joins an
 * in-process client, so the whole public path is exercised: event framing and plan encoding.
 */
class PlanRoundTripTest {
    private static final double EPS = 1e-12;

    static List<Path> plans() {
        return TestPlans.all();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("plans")
    void clientReceivesTheSameObjects(Path file) throws IOException {
        TestPlans.assumePresent(file);
        RsPlan sent = TestPlans.parse(file);
        RsPlan got = sendToClient(sent);
        assertEquals(Objects.toString(sent.getCaption(), ""), got.getCaption());
        assertEquals(sent.getObjectCount(), got.getObjectCount());
        for (int i = 0; i < sent.getObjectCount(); i++) {
            assertSameObject(sent.getObjects().get(i), got.getObjects().get(i));
        }
    }

    /** Sends {@code plan} from a server connection to a client over pipes; what the client's handler got. */
    private static RsPlan sendToClient(RsPlan plan) {
        RsPipe toClient = new RsPipe();
        RsPipe toServer = new RsPipe();
        RsConnection connection = new RsConnection();
        connection.setLogger(null);
        connection.setInputOutputStreams(toServer.getInputStream(), toClient.getOutputStream());
        RsClient client = new RsClient();
        client.setLogger(new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
                // the notice that the session ended when the test closes it
            }
        });
        client.setInputOutputStreams(toClient.getInputStream(), toServer.getOutputStream());
        BlockingQueue<RsPlanEvent> received = new LinkedBlockingQueue<>();
        client.addPlanEventHandler(received::add);
        Thread loop = new Thread(client, "plan-round-trip client");
        loop.setDaemon(true);
        loop.start();
        try {
            connection.sendPlanEvent(new RsPlanEvent(0.0, plan));
            RsPlanEvent e = received.poll(10, TimeUnit.SECONDS);
            assertNotNull(e, "no plan event reached the client within 10 s");
            return (RsPlan) e.plan;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted", e);
        } finally {
            endClientLoop(toClient);
        }
    }

    /** Ends the client's event loop: it sees the end of its input stream. */
    private static void endClientLoop(RsPipe pipe) {
        try {
            pipe.getOutputStream().close();
        } catch (IOException e) {
            throw new AssertionError("closing an in-memory pipe failed", e);
        }
    }

    private static void assertSameObject(RsObject s, RsObject g) {
        String name = s.getName();
        assertSame(s.getClass(), g.getClass(), name);
        assertEquals(name, g.getName());
        assertArrayEquals(s.getGeometry(), g.getGeometry(), EPS, name);
        if (s instanceof RsNavNode || s instanceof RsNavLink) {
            assertEquals(Objects.toString(s.label, ""), g.label, name);
            assertEquals(s.lineColor, g.lineColor, name);
            assertEquals(s.lineColor, g.fillColor, name);
        }
        if (s instanceof RsNavLink) {
            assertEquals(((RsNavLink) s).n0.getName(), ((RsNavLink) g).n0.getName(), name);
            assertEquals(((RsNavLink) s).n1.getName(), ((RsNavLink) g).n1.getName(), name);
        }
        if (s instanceof RsNavNode) {
            assertEquals(((RsNavNode) s).link.length, ((RsNavNode) g).link.length, name);
        }
        if (s instanceof RsPaint) {
            assertEquals(s.fillColor, g.fillColor, name);
        }
    }
}
