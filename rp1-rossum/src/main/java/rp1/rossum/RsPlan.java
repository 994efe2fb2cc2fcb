package rp1.rossum;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.request.RsTargetSelectionRequest;

/**
 * A floor plan: the simulated world's walls, obstacles, targets, placements, floor paint and
 * navigation network, in declaration order, with a caption and the units the plan was written in.
 * The server parses it from a floor-plan file; clients receive it in a plan event.
 *
 * <p>Object names are unique within a plan (one namespace for all object types). Unnamed objects
 * get synthesized names ({@link #synthesizeName()}).
 */
public class RsPlan {
    private final List<RsObject> objects = new ArrayList<>();
    private final Map<String, RsObject> byName = new HashMap<>();
    private final Map<Class<?>, List<? extends RsObject>> byType = new HashMap<>();
    private String fileName;
    private String caption;
    private RsUnits units = new RsMeters();
    private int serialNumber;
    private Random random = new Random(0);

    /** An empty plan in metres. */
    public RsPlan() {
    }

    /** An empty plan read from (or to be read from) {@code fileName}. */
    public RsPlan(String fileName) {
        this.fileName = fileName;
    }

    /** The object with exactly this name, or null. */
    public RsObject getObjectByName(String name) {
        return name == null ? null : byName.get(name);
    }

    /** A fresh name for an unnamed object: the serial counter is incremented and its name returned. */
    public String synthesizeName() {
        serialNumber++;
        return synthesizeName(serialNumber);
    }

    /**
     * The synthesized name for serial number {@code n}: "0x" and eight characters, character i
     * being {@code t = (n >>> 4*(7-i)) & 0xFF} written as '0'+t below 10, else 'a'+(t-10). This is RP1
     * 0.60's rule, byte mask included, so 1 is "0x00000001" but 16 is "0x0000001g"; floor plans that
     * declare objects by number get the same names as in the original.
     */
    public String synthesizeName(int n) {
        StringBuilder b = new StringBuilder("0x");
        for (int i = 0; i < 8; i++) {
            int t = (n >>> (4 * (7 - i))) & 0xFF;
            b.append((char) (t < 10 ? '0' + t : 'a' + (t - 10)));
        }
        return b.toString();
    }

    /** Raises the serial counter to at least {@code n} (after an object declared with number n). */
    public void maximizeSerialNumber(int n) {
        serialNumber = Math.max(serialNumber, n);
    }

    /**
     * The name of the file the plan was read from.
     *
     * @return the file name, or null
     */
    public String getFileName() {
        return fileName;
    }

    /**
     * Records the name of the file the plan was read from.
     *
     * @param fileName the file name
     */
    public void setFileName(String fileName) {
        this.fileName = fileName;
    }

    /** The units the plan was written in (its values are stored in metres regardless). */
    public void setUnits(RsUnits units) {
        this.units = units;
    }

    /**
     * The units the plan was written in (its values are stored in metres regardless).
     *
     * @return the units, or null if none were set
     */
    public RsUnits getUnits() {
        return units;
    }

    /**
     * Appends an object. An unnamed object is given a synthesized name; the object is attached to
     * this plan.
     *
     * @throws IllegalArgumentException if another object already has the object's name
     */
    public synchronized void addObject(RsObject object) {
        if (object.getName() == null) {
            object.setName(synthesizeName());
        }
        RsObject previous = byName.get(object.getName());
        if (previous != null && previous != object) {
            throw new IllegalArgumentException("duplicate object name " + object.getName());
        }
        object.plan = this;
        objects.add(object);
        byType.clear();
        byName.put(object.getName(), object);
    }

    /** All objects in declaration order. */
    public RsObject[] getObjectArray() {
        return objects.toArray(new RsObject[0]);
    }

    /** All objects in declaration order, unmodifiable. */
    public List<RsObject> getObjects() {
        return Collections.unmodifiableList(objects);
    }

    /** The number of objects. */
    public int getObjectCount() {
        return objects.size();
    }

    /**
     * The navigation links, in declaration order.
     *
     * @return a new array
     */
    public RsNavLink[] getNavLinkArray() {
        return objectsOf(RsNavLink.class).toArray(new RsNavLink[0]);
    }

    /**
     * The navigation nodes, in declaration order.
     *
     * @return a new array
     */
    public RsNavNode[] getNavNodeArray() {
        return objectsOf(RsNavNode.class).toArray(new RsNavNode[0]);
    }

    /** Walls and obstacles, in declaration order. */
    public RsWall[] getWallArray() {
        return objectsOf(RsWall.class).toArray(new RsWall[0]);
    }

    /**
     * The targets, in declaration order.
     *
     * @return a new array
     */
    public RsTarget[] getTargetArray() {
        return objectsOf(RsTarget.class).toArray(new RsTarget[0]);
    }

    /** The targets, in declaration order, as the list kept for them: for those that look at every step. */
    List<RsTarget> targets() {
        return objectsOf(RsTarget.class);
    }

    /**
     * The placements, in declaration order.
     *
     * @return a new array
     */
    public RsPlacement[] getPlacementArray() {
        return objectsOf(RsPlacement.class).toArray(new RsPlacement[0]);
    }

    /** Floor paint, in declaration order (the last one lies on top). */
    public RsPaint[] getPaintArray() {
        return objectsOf(RsPaint.class).toArray(new RsPaint[0]);
    }

    /**
     * The objects of one type in declaration order. Sensors and collision searches ask for the walls
     * at every motion step, so the lists are kept until an object is added.
     */
    @SuppressWarnings("unchecked")
    private synchronized <T extends RsObject> List<T> objectsOf(Class<T> type) {
        List<? extends RsObject> cached = byType.get(type);
        if (cached == null) {
            List<T> list = new ArrayList<>();
            for (RsObject o : objects) {
                if (type.isInstance(o)) {
                    list.add(type.cast(o));
                }
            }
            cached = Collections.unmodifiableList(list);
            byType.put(type, cached);
        }
        return (List<T>) cached;
    }

    /**
     * A copy of this plan that shares nothing a run changes: the same objects in the same order, with
     * the same names, numbers (to the bit), colours, labels and selection, the navigation network's
     * links joining the copied nodes, and a random source started anew as a parsed plan's is. A sweep
     * parses each floor plan once and gives every run a copy, since a run selects targets and sets
     * the random source of its own plan. The units are shared (they are constants).
     *
     * @return the copy
     * @throws IllegalStateException if the plan holds an object of a class other than the plan's
     *         own types (a subclass may hold fields a copy cannot know of)
     */
    public synchronized RsPlan copy() {
        RsPlan copy = new RsPlan(fileName);
        copy.caption = caption;
        copy.units = units;
        copy.serialNumber = serialNumber;
        PlanCopy objects = new PlanCopy(copy);
        for (RsObject o : this.objects) {
            copy.addObject(objects.of(o));
        }
        return copy;
    }

    /**
     * The random source used for random target selection. The simulator sets its seeded source so
     * that runs are repeatable.
     */
    public void setRandom(Random random) {
        this.random = random;
    }

    /**
     * Applies a target-selection request (behavior.md section 8.7): exclusive deselects every target;
     * random selects one target chosen uniformly; name "*" sets every target to the status; another
     * non-empty name sets the first target of that name. Returns one event per target touched, in
     * plan order, carrying its final state, stamped {@code simTime}; empty if nothing was touched.
     */
    public RsTargetSelectionEvent[] processTargetSelectionRequest(double simTime, RsTargetSelectionRequest request) {
        List<RsTarget> targets = objectsOf(RsTarget.class);
        boolean[] touched = new boolean[targets.size()];
        if (request.exclusive) {
            for (int i = 0; i < targets.size(); i++) {
                targets.get(i).setSelected(false);
                touched[i] = true;
            }
        }
        if (request.random && !targets.isEmpty()) {
            int i = random.nextInt(targets.size());
            targets.get(i).setSelected(true);
            touched[i] = true;
        }
        String name = request.name;
        if ("*".equals(name)) {
            for (int i = 0; i < targets.size(); i++) {
                targets.get(i).setSelected(request.status);
                touched[i] = true;
            }
        } else if (name != null && !name.isEmpty()) {
            for (int i = 0; i < targets.size(); i++) {
                if (name.equals(targets.get(i).getName())) {
                    targets.get(i).setSelected(request.status);
                    touched[i] = true;
                    break;
                }
            }
        }
        List<RsTargetSelectionEvent> events = new ArrayList<>();
        for (int i = 0; i < targets.size(); i++) {
            if (touched[i]) {
                RsTarget t = targets.get(i);
                events.add(new RsTargetSelectionEvent(simTime, t.getName(), t.getSelected()));
            }
        }
        return events.toArray(new RsTargetSelectionEvent[0]);
    }

    /** Client side: records a target's selection state reported by the server. */
    public void applyTargetSelectionEvent(RsTargetSelectionEvent event) {
        RsObject o = getObjectByName(event.targetName);
        if (o instanceof RsTarget) {
            o.setSelected(event.status);
        }
    }

    /** The caption (window title), or null. */
    public String getCaption() {
        return caption;
    }

    /**
     * Sets the caption (the window title).
     *
     * @param caption the caption, or null
     */
    public void setCaption(String caption) {
        this.caption = caption;
    }

    /** The union of all objects' bounds; empty for a plan without objects. */
    public RsRectangle getBounds() {
        RsRectangle r = new RsRectangle();
        for (RsObject o : objects) {
            r.union(o.getBounds());
        }
        return r;
    }
}
