package rp1.simulator.world;

import java.util.ArrayList;
import java.util.List;

import rp1.rossum.RsBodyContactSensor;
import rp1.rossum.RsBodySensor;

/**
 * Contact sensors of robots at rest that other robots ran into ({@link RobotContacts}), each waiting to
 * be pressed with the name of the robot touching it at the time that robot stops. Kept by robot number,
 * in the order the contacts were found.
 */
final class Touches {
    /** By robot number: the waiting touches, or null before the robot's first. */
    private final List<List<Touch>> byNumber = new ArrayList<>();

    /**
     * Another robot, named {@code name}, ran into {@code r}, which stands still: {@code sensors} touch
     * it and go hot with its name at {@code time}, when the other robot has stopped. Added to those of
     * any other robot that ran into {@code r} before they were pressed.
     */
    void add(Robot r, double time, List<RsBodyContactSensor> sensors, String name) {
        int n = r.getNumber();
        while (byNumber.size() <= n) {
            byNumber.add(null);
        }
        List<Touch> touched = byNumber.get(n);
        if (touched == null) {
            touched = new ArrayList<>();
            byNumber.set(n, touched);
        }
        for (RsBodyContactSensor s : sensors) {
            touched.add(new Touch(s, name, time));
        }
    }

    /**
     * Presses the robot's contact sensors other robots ran into whose time has come by {@code time}:
     * those not hot yet go hot with the name of the robot touching them (the earliest, if several; one
     * event each, in part order). They are released as any contact sensor, when the robot next starts
     * a motion. Sensors whose robot stops later keep waiting.
     *
     * @return the earliest time sensors still wait to be pressed at, or NaN if none wait
     */
    double press(Robot r, double time) {
        int n = r.getNumber();
        List<Touch> touched = n < byNumber.size() ? byNumber.get(n) : null;
        if (touched == null || touched.isEmpty()) {
            return Double.NaN;
        }
        for (RsBodySensor s : r.getBody().getBodySensors()) {
            Touch first = null;
            for (Touch t : touched) {
                if (t.sensor() == s && t.time() <= time && (first == null || t.time() < first.time())) {
                    first = t;
                }
            }
            if (first != null && !s.getHot()) {
                RsBodyContactSensor c = first.sensor();
                c.setCollision(true, first.by());
                c.setHot(true);
                r.events().sendIfSubscribed(c.getStateChangeEvent(time));
            }
        }
        touched.removeIf(t -> t.time() <= time);
        if (touched.isEmpty()) {
            return Double.NaN;
        }
        double next = Double.POSITIVE_INFINITY;
        for (Touch t : touched) {
            next = Math.min(next, t.time());
        }
        return next;
    }

    /** A contact sensor another robot ran into, pressed with its name at the time it stops. */
    private record Touch(RsBodyContactSensor sensor, String by, double time) {
    }
}
