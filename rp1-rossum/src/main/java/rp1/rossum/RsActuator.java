package rp1.rossum;

import java.awt.Graphics;
import java.util.ArrayList;

/**
 * A body part that makes the robot act, with sub-parts of its own (a wheel system and its wheels).
 * The sub-parts are drawn with it. A bare actuator does nothing and cannot be transmitted.
 */
public class RsActuator extends RsBodyPart {
    private static final long serialVersionUID = 1L;

    /** The sub-parts, in the order added (a copy of {@link #partsList}). */
    protected RsBodyPart[] partsArray = new RsBodyPart[0];
    /** The sub-parts, in the order added. */
    protected ArrayList<RsBodyPart> partsList = new ArrayList<>();

    /** An actuator without sub-parts, named "Actuator". */
    public RsActuator() {
        name = "Actuator";
    }

    /** Adds a sub-part (drawn after those added before it). */
    void addSubPart(RsBodyPart part) {
        partsList.add(part);
        part.joined(this);
        partsArray = partsList.toArray(new RsBodyPart[0]);
    }

    /** The sub-parts, in the order they were added. */
    public RsBodyPart[] getPartsArray() {
        return partsArray.clone();
    }

    /** Draws the sub-parts in order. */
    @Override
    public void paint(Graphics g, RsTransform t) {
        for (RsBodyPart p : partsArray) {
            p.paint(g, t);
        }
    }
}
