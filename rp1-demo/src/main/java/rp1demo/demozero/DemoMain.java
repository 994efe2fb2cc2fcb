package rp1demo.demozero;

import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;

import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsRunnable;
import rp1demo.clientzero.ClnMain;

/**
 * DemoZero: a {@link ClnMain} (ClientZero) plus a window showing the robot's status, what its head
 * sees and the simulation clock, with buttons to send it home or halt it. The {@code RsRunnable}
 * methods pass straight through to the ClientZero inside. Without a display there is no window and
 * DemoZero behaves exactly as ClientZero.
 */
public class DemoMain implements RsRunnable {
    /** Simulated seconds between updates of the window's clock. */
    public static final double CLOCK_PERIOD = 0.5;

    private final ClnMain client;

    /**
     * Connects to a simulator on the network and runs until it goes away.
     *
     * @throws IOException if the simulator cannot be reached
     */
    public static void main(String[] args) throws IOException {
        DemoMain demo = new DemoMain();
        demo.initialize();
        demo.run();
    }

    /** The no-argument constructor the simulator uses to load the class. */
    public DemoMain() {
        client = new ClnMain();
    }

    @Override
    public void setInputOutputStreams(InputStream input, OutputStream output) {
        client.setInputOutputStreams(input, output);
    }

    @Override
    public void setLogger(RsLogInterface logger) {
        client.setLogger(logger);
    }

    /** Initializes ClientZero, then opens the window and adds the handlers that keep it up to date. */
    @Override
    public void initialize() throws IOException {
        client.initialize();
        if (GraphicsEnvironment.isHeadless()) {
            client.log("DemoZero: no display, so no window; running as ClientZero");
            return;
        }
        DemoFrame frame = DemoFrame.open(client);
        DemoEventHandlers handlers = new DemoEventHandlers(client, frame, CLOCK_PERIOD);
        client.setProtocolShutdownHandler(frame::showDisconnected);
        client.addMotionStartedEventHandler(handlers);
        client.addMotionHaltedEventHandler(handlers);
        client.addPositionEventHandler(handlers);
        client.addPlacementEventHandler(handlers);
        client.addTimeoutEventHandler(handlers);
        client.addTargetSensorEventHandler((RsBodyTargetSensor) client.getBody().getPartByName("head"), handlers);
        handlers.startClock();
    }

    /** ClientZero's event loop. */
    @Override
    public void run() {
        client.run();
    }

    /** The ClientZero inside. */
    public ClnMain getClient() {
        return client;
    }
}
