package guidestyle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsBody;
import rp1.rossum.RsConnection;
import rp1.rossum.RsConnectionBodyHandler;
import rp1.rossum.RsPipe;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsMotionRequestHandler;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlacementRequestHandler;
import rp1.rossum.request.RsPlanRequest;
import rp1.rossum.request.RsPlanRequestHandler;
import rp1.rossum.request.RsPositionRequestHandler;
import rp1.rossum.request.RsRequest;

/**
 * A client written in the user's guide's style, in a package of its own, compiles against the library
 * and runs in-process against a server connection: its body and requests arrive, and a mouse click
 * turns into a motion request towards the clicked point.
 */
@Timeout(30)
class GuideStyleClientTest {

    @Test
    void aGuideStyleClientTalksToAServerConnection() throws Exception {
        BlockingQueue<Object> received = new LinkedBlockingQueue<>();
        RsConnection server = new RsConnection();
        Recorder recorder = new Recorder(received);
        server.setBodyHandler(recorder.bodies);
        server.setPlanRequestHandler(recorder);
        server.setPlacementRequestHandler(recorder);
        server.setPositionRequestHandler(recorder);
        server.setMotionRequestHandler(recorder);

        RsPipe toServer = new RsPipe();
        RsPipe toClient = new RsPipe();
        server.setInputOutputStreams(toServer.getInputStream(), toClient.getOutputStream());
        GuideStyleClient client = new GuideStyleClient();
        client.setInputOutputStreams(toClient.getInputStream(), toServer.getOutputStream());
        client.setLogger(rp1.rossum.QuietLog.INSTANCE);
        new Thread(server).start();
        client.initialize();
        Thread loop = new Thread(client);
        loop.start();

        RsBody body = (RsBody) next(received);
        assertEquals("GuideStyle", body.getName());
        assertTrue(body.getPartByName("head") != null);
        assertEquals("plan", next(received));
        assertEquals("placement home", next(received));

        server.sendPlacementEvent(new RsPlacementEvent(0.1, true, "home", 2.5, 2.5, Math.PI));
        assertEquals("position", next(received));
        server.sendPositionEvent(new RsPositionEvent(0.2, 2.5, 2.5, Math.PI, 0, 0));
        server.sendMouseClickEvent(new RsMouseClickEvent(0.3, 0, 1, 1.5, 2.5));
        RsMotionRequest r = (RsMotionRequest) next(received);
        assertEquals(0.3, r.linearVelocity, 1e-12, "straight ahead at the requested speed");
        assertEquals(0.0, r.rotationalVelocity, 1e-12);
        assertEquals(1.0 / 0.3, r.duration, 1e-9, "one metre to the clicked point");

        toClient.getOutputStream().close();
        loop.join(10_000);
        assertTrue(!loop.isAlive(), "the event loop ends when the server goes away");
    }

    /** Records the requests the client sends. */
    private static final class Recorder implements RsPlanRequestHandler, RsPlacementRequestHandler,
            RsPositionRequestHandler, RsMotionRequestHandler {
        private final BlockingQueue<Object> received;
        final RsConnectionBodyHandler bodies = new RsConnectionBodyHandler() {
            @Override
            public void process(RsBody body) {
                received.add(body);
            }
        };

        Recorder(BlockingQueue<Object> received) {
            this.received = received;
        }

        @Override
        public void processRequest(RsRequest r) {
            received.add(r);
        }

        @Override
        public void process(RsPlanRequest r) {
            received.add("plan");
        }

        @Override
        public void process(RsPlacementRequest r) {
            received.add("placement " + r.name);
        }

        @Override
        public void process() {
            received.add("position");
        }

        @Override
        public void process(RsMotionRequest r) {
            received.add(r);
        }
    }

    private static Object next(BlockingQueue<Object> q) throws InterruptedException {
        Object o = q.poll(10, TimeUnit.SECONDS);
        if (o == null) {
            throw new AssertionError("nothing arrived");
        }
        return o;
    }
}
