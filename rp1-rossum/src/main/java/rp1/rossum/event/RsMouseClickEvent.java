package rp1.rossum.event;

/**
 * A mouse button was pressed on the simulator's floor-plan view. Delivered to every robot client subscribed to it; the demos use it to steer the robot.
 */
public class RsMouseClickEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** 0 for the primary (left) button, 1 for the secondary button or primary with Alt/Meta. */
    public final int button;
    /** 1 for a single press, 2 for the second press of a double click. */
    public final int clickCount;
    /** Clicked point, world metres. */
    public final double x;
    /** Clicked point, world metres. */
    public final double y;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsMouseClickEvent(double simTime, int button, int clickCount, double x, double y) {
        super(EVT_MOUSE_CLICK, simTime);
        this.button = button;
        this.clickCount = clickCount;
        this.x = x;
        this.y = y;
    }
}
