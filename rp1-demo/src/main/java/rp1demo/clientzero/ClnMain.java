package rp1demo.clientzero;

import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsClient;
import rp1.rossum.RsRunnable;
import rp1.rossum.request.RsMotionRequest;
import rp1demo.Standalone;
import rp1demo.navigation.NavNetwork;

/**
 * ClientZero's connection to the simulator, as the original's user's guide writes it: it sends the body,
 * registers one handler per event and asks for the floor plan and the "home" placement. Then a left
 * click in the simulator's window sends the robot to the clicked point and any other click turns it
 * to face the point; after running into a wall it backs away a little.
 *
 * <p>Runs on its own against a simulator listening on the host and port of {@code rossum.ini}
 * ({@link #main}), or loaded by the simulator ({@code dlcName=rp1demo.clientzero.ClnMain}).
 */
public class ClnMain extends RsClient implements RsRunnable {
    /** Driving speed towards a clicked point, metres per second. */
    public static final double SPEED = 0.25;
    /** How long to wait after a collision before backing off, seconds. */
    public static final double BACK_OFF_DELAY = 0.5;
    /** Speed when backing off, metres per second. */
    public static final double BACK_OFF_SPEED = 0.1;

    private final ClnNavigator navigator = new ClnNavigator();
    private RsBody body;
    private volatile NavNetwork navNetwork;
    private int backOffTimeout = -1;

    /**
     * Connects to a simulator on the network and runs until it goes away.
     * If it cannot be reached, says so in one line and exits with status 1.
     */
    public static void main(String[] args) {
        Standalone.run(new ClnMain());
    }

    /** The no-argument constructor the simulator uses to load the class. */
    public ClnMain() {
        super();
    }

    /**
     * Connects (unless the simulator gave us streams), sends the body, registers the handlers and
     * asks for the plan and the placement "home".
     */
    @Override
    public void initialize() throws IOException {
        super.initialize();
        body = ClientZero.build();
        sendBodySpecification(body);
        addMouseClickEventHandler(new ClnMouseClickEventHandler(this));
        addPositionEventHandler(new ClnPositionEventHandler(this));
        addPlacementEventHandler(new ClnPlacementEventHandler(this));
        addMotionHaltedEventHandler(new ClnMotionHaltedEventHandler(this));
        addTargetSensorEventHandler((RsBodyTargetSensor) body.getPartByName("head"),
                new ClnTargetSensorEventHandler(this));
        addTargetSelectionEventHandler(new ClnTargetSelectionEventHandler(this));
        addTimeoutEventHandler(new ClnTimeoutEventHandler(this));
        addPlanEventHandler(new ClnPlanEventHandler(this));
        sendPlanRequest();
        sendPlacementRequest("home");
    }

    /** The body sent to the simulator (null before {@link #initialize()}). */
    public RsBody getBody() {
        return body;
    }

    /** The robot logic the handlers consult. */
    public ClnNavigator getNavigator() {
        return navigator;
    }

    /** The floor plan's navigation network, once the plan has arrived (else null). */
    public NavNetwork getNavNetwork() {
        return navNetwork;
    }

    void setNavNetwork(NavNetwork network) {
        navNetwork = network;
    }

    /** Asks for the timeout at whose end the robot backs away from the wall it hit. */
    void scheduleBackOff() {
        backOffTimeout = sendTimeoutRequest(BACK_OFF_DELAY);
    }

    /**
     * Backs off if {@code timeoutIndex} is the back-off timeout; other timeouts (another part of
     * the program may ask for some, as DemoZero does) are not ours.
     *
     * @return whether it was ours
     */
    boolean backOffIfDue(int timeoutIndex) {
        if (timeoutIndex != backOffTimeout) {
            return false;
        }
        backOffTimeout = -1;
        double seconds = ClnNavigator.BACK_OFF_DISTANCE / BACK_OFF_SPEED;
        sendMotionRequest(new RsMotionRequest(-BACK_OFF_SPEED, 0.0, seconds));
        return true;
    }
}
