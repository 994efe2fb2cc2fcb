package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;
import java.util.concurrent.atomic.AtomicLong;

/**
 * One component of a robot body: a shape, a sensor, a painter, a wheel system or its wheels, or
 * decorative art. Every part has a name, four colours (fill and line, plus the "hot" variants used
 * while a sensor detects something or a painter is active) and a part id, which identifies sensors,
 * painters, wheel systems and encoders on the wire (protocol.md section 8.6).
 *
 * <p>Ids belong to the body: a body numbers its parts 1, 2, ... in the order they were constructed,
 * the first time one of their ids is needed (the body is sent, or {@link #getID()} is called), and
 * they keep those ids from then on. A part in no body numbers itself and its sub-parts the same way.
 * So a client's one body gets the ids RP1 0.60's process-wide counter gave it, and every body of a
 * process, of a simulation or of several simulations in one process, is numbered alike.
 */
public abstract class RsBodyPart extends RsComponent {
    private static final long serialVersionUID = 1L;

    /** Light gray, the default fill and line colour of every part. */
    static final Color DEFAULT_COLOR = new Color(192, 192, 192);
    /** Orange, the default hot fill colour (and hot line colour of non-sensors). */
    static final Color DEFAULT_HOT_COLOR = new Color(255, 200, 0);

    /**
     * Stamps parts in the order they are constructed. Only ever compared between parts of one body,
     * so its value never reaches the wire and nothing needs to reset it.
     */
    private static final AtomicLong CONSTRUCTED = new AtomicLong();

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

    private final long constructed = CONSTRUCTED.incrementAndGet();
    private volatile int partID;
    /** Whether {@link #partID} holds the part's id (any int may be an id on the wire, 0 included). */
    private volatile boolean numbered;
    /** The body or actuator this part was added to last, or null: whose numbering it takes part in. */
    private RsComponent owner;
    /**
     * The collision outline where the last motion searched started, kept to be filled anew by the
     * next search instead of allocating a copy of every edge for each.
     */
    private transient RsSegment[] startOutline;

    /** A part, numbered with its body (see the class comment). */
    public RsBodyPart() {
    }

    /**
     * RP1 0.60 set its process-wide part counter with this. Parts are numbered per body now, so there
     * is no such counter and the call has no effect (docs/differences.md); to give a part a chosen id
     * the library's decoder and tests use {@code assignID}.
     */
    protected static void setNextPartSerialNumber(int next) {
    }

    /** Gives this part {@code id} for good (decoding reproduces the sender's ids this way). */
    void assignID(int id) {
        partID = id;
        numbered = true;
    }

    /** Whether the part has its id yet. */
    boolean isNumbered() {
        return numbered;
    }

    /** Construction order: a part built earlier has a smaller value. */
    long constructionOrder() {
        return constructed;
    }

    /** Records that the part was added to {@code body} or to an actuator. */
    void joined(RsComponent body) {
        owner = body;
    }

    /** The body or actuator this part was added to last, or null. */
    RsComponent owner() {
        return owner;
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
        if (walls == null || motion == null || outline == null || outline.length == 0) {
            return false;
        }
        RsSegment[] body = BodyOutline.mapInto(outline, motion.transform0, startOutline);
        startOutline = body;
        return searchForCollisions(body, walls, nearestFirst(walls, motion), motion);
    }

    /**
     * The collision search of {@code body} (edges at the motion's start, in world coordinates) against
     * {@code walls} in {@code order}, recording the earliest contact in {@code motion}. Whether a
     * contact was found. A body searches all its parts' outlines in one array: the contact time is
     * the least over every pair of a part's edge and a wall's, however the parts are grouped.
     */
    static boolean searchForCollisions(RsSegment[] body, RsWall[] walls, int[] order, RsMotion motion) {
        boolean hit = false;
        double[] prepared = motion.prepare(body, body.length);
        for (int k = 0; k < walls.length; k++) {
            RsSegment[] edges = walls[order[k]].getSegmentArray();
            // Once there is a contact, a wall that can only be met later changes nothing.
            if (hit && motion.cannotMeetBefore(body, body.length, edges, edges.length, motion.collisionTime, prepared)) {
                continue;
            }
            if (motion.processCollision(body, body.length, edges, edges.length, prepared)) {
                hit = true;
            }
        }
        return hit;
    }

    /**
     * The walls' indexes, the wall whose box is nearest where the motion starts first. The contact
     * time is the least over all walls whatever the order, and a wall wholly beyond a contact already
     * found is passed over: trying the near walls first finds the contact that lets most of the others
     * be passed over (a robot driving on for ever has walls all across the plan ahead of it).
     */
    static int[] nearestFirst(RsWall[] walls, RsMotion motion) {
        double x = motion.transform0.m13;
        double y = motion.transform0.m23;
        int n = walls.length;
        int[] order = new int[n];
        double[] away = new double[n];
        for (int i = 0; i < n; i++) {
            double d = boxDistanceSquared(walls[i].getSegmentArray(), x, y);
            // Insertion: walls are few, and equally near ones keep their order.
            int k = i;
            while (k > 0 && away[k - 1] > d) {
                order[k] = order[k - 1];
                away[k] = away[k - 1];
                k--;
            }
            order[k] = i;
            away[k] = d;
        }
        return order;
    }

    /** The squared distance from (x, y) to the box of the edges (infinite for none). */
    private static double boxDistanceSquared(RsSegment[] edges, double x, double y) {
        if (edges.length == 0) {
            return Double.POSITIVE_INFINITY;
        }
        double x0 = Double.POSITIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (RsSegment e : edges) {
            x0 = Math.min(x0, Math.min(e.x, e.x + e.v.x));
            y0 = Math.min(y0, Math.min(e.y, e.y + e.v.y));
            x1 = Math.max(x1, Math.max(e.x, e.x + e.v.x));
            y1 = Math.max(y1, Math.max(e.y, e.y + e.v.y));
        }
        double dx = x < x0 ? x0 - x : (x > x1 ? x - x1 : 0.0);
        double dy = y < y0 ? y0 - y : (y > y1 ? y - y1 : 0.0);
        return dx * dx + dy * dy;
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

    /**
     * The part id (also the encoder id of a wheel). The first call on any part of a body numbers the
     * whole body (see the class comment).
     */
    public int getID() {
        if (!numbered) {
            PartNumbering.number(this);
        }
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
