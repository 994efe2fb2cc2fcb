package rp1demo.demozero;

import java.awt.GraphicsEnvironment;
import java.io.IOException;

import rp1.rossum.RsBodyTargetSensor;
import rp1demo.Standalone;
import rp1demo.clientzero.ClnMain;

/**
 * DemoZero: a {@link ClnMain} (ClientZero) plus a window showing the robot's status, what its head
 * sees and the simulation clock, with buttons to send it home or halt it. It keeps the library's event
 * loop, so the simulator loads it with direct delivery: its handlers run on the simulation's thread,
 * and the window's buttons send their requests from Swing's thread (requests are safe from any thread
 * and take effect at the simulation's next step). Without a display there is no window and DemoZero
 * behaves exactly as ClientZero.
 */
public class DemoMain extends ClnMain {
    /** Simulated seconds between updates of the window's clock. */
    public static final double CLOCK_PERIOD = 0.5;

    /**
     * Connects to a simulator on the network and runs until it goes away.
     * If it cannot be reached, says so in one line and exits with status 1.
     */
    public static void main(String[] args) {
        Standalone.run(new DemoMain());
    }

    /** The no-argument constructor the simulator uses to load the class. */
    public DemoMain() {
        super();
    }

    /** Initializes ClientZero, then opens the window and adds the handlers that keep it up to date. */
    @Override
    public void initialize() throws IOException {
        super.initialize();
        if (GraphicsEnvironment.isHeadless()) {
            log("DemoZero: no display, so no window; running as ClientZero");
            return;
        }
        DemoFrame frame = DemoFrame.open(this);
        DemoEventHandlers handlers = new DemoEventHandlers(this, frame, CLOCK_PERIOD);
        setProtocolShutdownHandler(frame::showDisconnected);
        addMotionStartedEventHandler(handlers);
        addMotionHaltedEventHandler(handlers);
        addPositionEventHandler(handlers);
        addPlacementEventHandler(handlers);
        addTimeoutEventHandler(handlers);
        addTargetSensorEventHandler((RsBodyTargetSensor) getBody().getPartByName("head"), handlers);
        handlers.startClock();
    }

    /** The ClientZero this demo is (kept for callers that ask for it). */
    public ClnMain getClient() {
        return this;
    }
}
