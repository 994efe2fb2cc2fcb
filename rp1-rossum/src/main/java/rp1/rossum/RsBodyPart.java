package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;

/**
 * One component of a robot body: a shape, a sensor, a painter, a wheel system or its wheels, or
 * decorative art. Every part has a name, four colours (fill and line, plus the "hot" variants used
 * while a sensor detects something or a painter is active) and a part id. The id is taken in the
 * constructor from one process-wide counter that starts at 1, so ids follow construction order; they
 * identify sensors, painters, wheel systems and encoders on the wire (protocol.md section 8.6).
 */
public abstract class RsBodyPart extends RsComponent {
    private static final long serialVersionUID = 1L;

    /** Light gray, the default fill and line colour of every part. */
    static final Color DEFAULT_COLOR = new Color(192, 192, 192);
    /** Orange, the default hot fill colour (and hot line colour of non-sensors). */
    static final Color DEFAULT_HOT_COLOR = new Color(255, 200, 0);

    private static final Object COUNTER_LOCK = new Object();
    private static int nextPartSerialNumber = 1;
    /**
     * While a body specification is decoded, the ids to give the parts being built on this thread.
     * Decoding must reproduce the sender's ids without rewinding the process-wide counter, which an
     * in-process client sharing this JVM keeps using.
     */
    private static final ThreadLocal<int[]> DECODING_IDS = new ThreadLocal<>();

    /** The part's name ({@link #getName()}). */
    protected String name = "Unnamed";
    /** Bounding box in body coordinates. */
    protected RsRectangle refBounds = new RsRectangle();
    /** Bounding box in world coordinates at the last pose computed. */
    protected RsRectangle bounds = new RsRectangle();
    /** Whether the part is hot: a sensor detecting something, a painter painting. */
    protected boolean hot;
    /** Fill colour; null means "not filled". */
    protected Color fillColor = DEFAULT_COLOR;
    /** Line colour; null means "not drawn". */
    protected Color lineColor = DEFAULT_COLOR;
    /** Fill colour while hot. */
    protected Color hotFillColor = DEFAULT_HOT_COLOR;
    /** Line colour while hot. */
    protected Color hotLineColor = DEFAULT_HOT_COLOR;

    private final int partID;

    /** A part with the next id. */
    public RsBodyPart() {
        partID = takeNextId();
    }

    private static int takeNextId() {
        int[] decoding = DECODING_IDS.get();
        if (decoding != null) {
            return decoding[0]++;
        }
        synchronized (COUNTER_LOCK) {
            return nextPartSerialNumber++;
        }
    }

    /** Sets the id the next constructed part (on any thread) will get. */
    protected static void setNextPartSerialNumber(int next) {
        synchronized (COUNTER_LOCK) {
            nextPartSerialNumber = next;
        }
    }

    /** The id the next constructed part will get from the process-wide counter. */
    static int peekNextPartSerialNumber() {
        synchronized (COUNTER_LOCK) {
            return nextPartSerialNumber;
        }
    }

    /**
     * Until {@link #endDecodingIds()}, parts constructed on this thread get {@code firstId},
     * {@code firstId + 1}, ... instead of ids from the process-wide counter.
     */
    static void beginDecodingIds(int firstId) {
        DECODING_IDS.set(new int[] {firstId});
    }

    /** Returns this thread to the process-wide counter. */
    static void endDecodingIds() {
        DECODING_IDS.remove();
    }

    /** The fill colour used while cold; null = not filled. */
    public void setFillColor(Color color) {
        fillColor = color;
    }

    /** The outline colour used while cold; null = no outline. */
    public void setLineColor(Color color) {
        lineColor = color;
    }

    /** The fill colour used while the part is hot. */
    public void setHotFillColor(Color color) {
        hotFillColor = color;
    }

    /** The line colour used while the part is hot. */
    public void setHotLineColor(Color color) {
        hotLineColor = color;
    }

    /** The line colour to draw with now: the hot line colour while hot. Null means "not drawn". */
    public Color getLineColor() {
        return hot ? hotLineColor : lineColor;
    }

    /** The fill colour to draw with now: the hot fill colour while hot. Null means "not drawn". */
    public Color getFillColor() {
        return hot ? hotFillColor : fillColor;
    }

    /** The fill colour used while cold, whatever the current state. */
    public Color getColdFillColor() {
        return fillColor;
    }

    /** The line colour used while cold, whatever the current state. */
    public Color getColdLineColor() {
        return lineColor;
    }

    /** The fill colour used while hot. */
    public Color getHotFillColor() {
        return hotFillColor;
    }

    /** The line colour used while hot. */
    public Color getHotLineColor() {
        return hotLineColor;
    }

    /** Whether this part is a sensor (its state is reported in sensor events). */
    public boolean isASensor() {
        return false;
    }

    /**
     * Whether this part would strike a wall of {@code plan} during {@code motion}, searched over the
     * whole motion from its start pose. A hit is recorded in the motion ({@link RsMotion#collision},
     * {@link RsMotion#collisionTime}, keeping the earliest contact). Parts without an outline never
     * collide.
     */
    public boolean searchForCollisions(RsPlan plan, RsMotion motion) {
        return plan != null && searchForCollisions(plan.getWallArray(), motion);
    }

    /**
     * As {@link #searchForCollisions(RsPlan, RsMotion)}, against the given obstacles (the simulator
     * adds other robots to the plan's walls).
     */
    public boolean searchForCollisions(RsWall[] walls, RsMotion motion) {
        RsSegment[] outline = collisionOutline();
        if (outline == null || outline.length == 0 || walls == null || motion == null) {
            return false;
        }
        RsSegment[] body = BodyOutline.map(outline, motion.transform0);
        boolean hit = false;
        for (RsWall wall : walls) {
            RsSegment[] edges = wall.getSegmentArray();
            if (motion.processCollision(body, body.length, edges, edges.length)) {
                hit = true;
            }
        }
        return hit;
    }

    /** The outline (body coordinates) that takes part in collisions, or null for none. */
    RsSegment[] collisionOutline() {
        return null;
    }

    /** Draws the part; {@code t} maps body coordinates to pixels. The base part draws nothing. */
    public void paint(Graphics g, RsTransform t) {
    }

    /** Sets the name; null is kept and transmitted as an empty string. */
    public void setName(String name) {
        this.name = name;
    }

    /** The name (may be null on the client; never null after transmission). */
    public String getName() {
        return name;
    }

    /** The part id (also the encoder id of a wheel). */
    public int getID() {
        return partID;
    }

    /** The bounding box in body coordinates. */
    public RsRectangle getRefBounds() {
        return new RsRectangle(refBounds);
    }

    /** The bounding box in world coordinates at pose {@code t}; also remembered in {@link #bounds}. */
    public RsRectangle computeBounds(RsTransform t) {
        RsRectangle r = new RsRectangle(refBounds);
        r.transform(t);
        bounds = r;
        return new RsRectangle(r);
    }

    /**
     * Copies the changing state (hot flag, and in subclasses the sensor readings, encoder counts,
     * steering) from the corresponding part of another copy of the same body.
     */
    public void copyStateData(RsBodyPart source) {
        hot = source.hot;
    }

    /**
     * Resets the state a new placement resets. The base part has none: sensor, contact and encoder
     * states survive a placement (behavior.md section 7).
     */
    public void resetStateData() {
    }

    /** Marks the part hot (detecting, or painting) or cold. */
    public void setHot(boolean hot) {
        this.hot = hot;
    }

    /** Whether the part is hot. */
    public boolean getHot() {
        return hot;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[id=" + partID + ", name=" + name + "]";
    }
}
