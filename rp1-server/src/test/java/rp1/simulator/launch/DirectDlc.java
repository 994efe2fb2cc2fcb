package rp1.simulator.launch;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import rp1.rossum.RsClient;
import rp1.rossum.event.RsPositionEvent;

/**
 * A loaded client that keeps the library's event loop, so the server calls its handlers directly:
 * places its robot, beats every 0.1 s, and notes on which thread each beat arrived. After the tenth
 * beat it ends its session.
 */
public class DirectDlc extends RsClient {
    static volatile DirectDlc latest;
    final List<String> beatThreads = new CopyOnWriteArrayList<>();
    final List<RsPositionEvent> positions = new CopyOnWriteArrayList<>();

    public DirectDlc() {
        latest = this;
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(TestServer.roundBody("direct"));
        addPositionEventHandler(positions::add);
        addHeartbeatEventHandler(e -> {
            beatThreads.add(Thread.currentThread().getName());
            if (e.sequence == 10) {
                shutdown();
            }
        });
        sendPlacementRequest("p1");
        sendHeartbeatRequest(0.1);
    }
}
