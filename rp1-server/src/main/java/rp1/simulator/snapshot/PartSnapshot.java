package rp1.simulator.snapshot;

import rp1.rossum.RsBodyPart;
import rp1.rossum.RsWheel;

/**
 * One body part at snapshot time: the part itself for its geometry and colours (which never change
 * once the body has arrived) and the state that does change.
 *
 * @param part     the part
 * @param hot      whether it was hot (a sensor detecting, a painter painting)
 * @param steering for a wheel, its steering or caster angle relative to the body, radians; else 0
 */
public record PartSnapshot(RsBodyPart part, boolean hot, double steering) {

    /** The part's state now; call on the thread running the simulation's tasks, which changes it. */
    public static PartSnapshot of(RsBodyPart part) {
        double steering = part instanceof RsWheel ? ((RsWheel) part).getSteeringAngle() : 0.0;
        return new PartSnapshot(part, part.getHot(), steering);
    }
}
