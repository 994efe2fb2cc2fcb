package rp1.rossum;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.IOException;

import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireLimits;
import rp1.rossum.wire.WireOut;

/**
 * The floor plan as the payload of a plan event (protocol.md section 9): an availability flag, the
 * caption, then every object in declaration order. Walls and obstacles travel as their polygon's
 * vertices, paint as its closed vertex list and fill colour, nodes as a point, label and colour, and
 * links by the names of their nodes. Region codes, units, line widths and the colours and labels of
 * walls, targets and placements are not part of the encoding, so a received plan has the defaults.
 *
 * <p>Socket-free: {@link #encode(RsPlan)} and {@link #decode(byte[])} work on byte arrays.
 */
final class PlanCodec {
    private PlanCodec() {
    }

    /**
     * The encoding of {@code plan} (null: "no plan available").
     *
     * @throws IllegalArgumentException if the plan holds an object of a type the protocol cannot carry
     *     or a string longer than the wire format allows
     */
    static byte[] encode(RsPlan plan) {
        WireOut out = new WireOut();
        encode(out, plan);
        return out.toByteArray();
    }

    /**
     * Decodes a complete encoding; the bytes must hold exactly one plan.
     *
     * @return the plan, or null if the sender had none
     * @throws RsProtocolException if the bytes are not a well-formed plan, naming the field
     */
    static RsPlan decode(byte[] bytes) throws IOException {
        ByteArrayInputStream buffer = new ByteArrayInputStream(bytes);
        RsPlan plan = decode(new WireIn(new DataInputStream(buffer)));
        if (buffer.available() > 0) {
            throw new RsProtocolException("plan", buffer.available() + " bytes left over after the last object");
        }
        return plan;
    }

    /**
     * The plan as a client receives it: encoded and decoded again, so it lacks exactly what the wire
     * leaves out (region codes, colours of walls, ...). Null stays null.
     */
    static RsPlan copy(RsPlan plan) {
        try {
            return decode(encode(plan));
        } catch (IOException e) {
            throw new IllegalStateException("a plan this library encoded cannot be decoded", e);
        }
    }

    /** Appends the encoding of {@code plan} (null: "no plan available") to {@code out}. */
    static void encode(WireOut out, RsPlan plan) {
        if (plan == null) {
            out.i32(0);
            return;
        }
        out.i32(1).str(plan.getCaption());
        out.i32(plan.getObjectCount());
        for (RsObject o : plan.getObjects()) {
            encodeObject(out, o);
        }
    }

    private static void encodeObject(WireOut out, RsObject o) {
        out.i32(typeOf(o)).str(o.getName());
        if (o instanceof RsNavNode) {
            RsNavNode node = (RsNavNode) o;
            out.f64(node.x).f64(node.y).str(node.label).color(node.lineColor);
        } else if (o instanceof RsNavLink) {
            RsNavLink link = (RsNavLink) o;
            out.str(nameOf(link.n0)).str(nameOf(link.n1)).str(link.label).color(link.lineColor);
        } else {
            geometry(out, o.getGeometry());
            if (o instanceof RsPaint) {
                out.color(o.fillColor);
            }
        }
    }

    private static int typeOf(RsObject o) {
        if (o instanceof RsWall) {
            return RsProtocol.PLAN_WALL;
        } else if (o instanceof RsTarget) {
            return RsProtocol.PLAN_TARGET;
        } else if (o instanceof RsPlacement) {
            return RsProtocol.PLAN_PLACEMENT;
        } else if (o instanceof RsNavNode) {
            return RsProtocol.PLAN_NAV_NODE;
        } else if (o instanceof RsNavLink) {
            return RsProtocol.PLAN_NAV_LINK;
        } else if (o instanceof RsPaint) {
            return RsProtocol.PLAN_PAINT;
        }
        throw new IllegalArgumentException("plan object " + o.getName() + " of " + o.getClass().getName()
                + " has no plan-event encoding");
    }

    private static String nameOf(RsObject o) {
        return o == null ? null : o.getName();
    }

    /** A GEOM: the number of doubles, then the doubles. */
    private static void geometry(WireOut out, double[] values) {
        out.i32(values.length);
        for (double v : values) {
            out.f64(v);
        }
    }

    /**
     * Reads one plan from {@code in}.
     *
     * @return the plan, or null if the sender had none (availability flag 0)
     * @throws RsProtocolException if the stream ends early or holds something that is not a plan
     */
    static RsPlan decode(WireIn in) throws IOException {
        if (in.i32("plan available") == 0) {
            return null;
        }
        RsPlan plan = new RsPlan();
        plan.setCaption(in.str("plan caption"));
        int n = in.count("plan object count", WireLimits.MAX_PLAN_OBJECTS);
        for (int i = 0; i < n; i++) {
            String field = "plan object[" + i + "]";
            RsObject o = decodeObject(in, plan, field);
            if (plan.getObjectByName(o.getName()) != null) {
                throw new RsProtocolException(field + " name", "duplicate object name \"" + o.getName() + "\"");
            }
            plan.addObject(o);
        }
        return plan;
    }

    private static RsObject decodeObject(WireIn in, RsPlan plan, String field) throws IOException {
        int type = in.i32(field + " type");
        String name = in.str(field + " name");
        switch (type) {
            case RsProtocol.PLAN_WALL:
                return withGeometry(new RsWall(name, plan), in, field);
            case RsProtocol.PLAN_TARGET:
                return withGeometry(new RsTarget(name, plan), in, field);
            case RsProtocol.PLAN_PLACEMENT:
                return withGeometry(new RsPlacement(name, plan), in, field);
            case RsProtocol.PLAN_NAV_NODE:
                return decodeNode(new RsNavNode(name, plan), in, field);
            case RsProtocol.PLAN_NAV_LINK:
                return decodeLink(new RsNavLink(name, plan), in, plan, field);
            case RsProtocol.PLAN_PAINT:
                RsObject paint = withGeometry(new RsPaint(name, plan), in, field);
                paint.setFillColor(in.color(field + " fill color"));
                return paint;
            default:
                throw new RsProtocolException(field + " type", "unknown plan object type " + type);
        }
    }

    /** Reads a GEOM into {@code o}; a count of 0 leaves the geometry unset. */
    private static RsObject withGeometry(RsObject o, WireIn in, String field) throws IOException {
        int n = in.count(field + " geometry count", WireLimits.MAX_GEOMETRY_DOUBLES);
        if (n == 0) {
            return o;
        }
        double[] values = new double[n];
        for (int k = 0; k < n; k++) {
            values[k] = in.f64(field + " geometry[" + k + "]");
        }
        o.setGeometry(values);
        return o;
    }

    private static RsObject decodeNode(RsNavNode node, WireIn in, String field) throws IOException {
        double x = in.f64(field + " x");
        double y = in.f64(field + " y");
        node.setGeometry(new double[] {x, y});
        node.setLabel(in.str(field + " label"));
        node.setColor(in.color(field + " color"));
        return node;
    }

    private static RsObject decodeLink(RsNavLink link, WireIn in, RsPlan plan, String field) throws IOException {
        RsNavNode n0 = node(plan, in.str(field + " node0"), field + " node0");
        RsNavNode n1 = node(plan, in.str(field + " node1"), field + " node1");
        link.setNodes(n0, n1);
        n0.addLink(link);
        n1.addLink(link);
        link.setLabel(in.str(field + " label"));
        link.setColor(in.color(field + " color"));
        return link;
    }

    /** The node called {@code name} among the objects received so far. */
    private static RsNavNode node(RsPlan plan, String name, String field) throws RsProtocolException {
        RsObject o = plan.getObjectByName(name);
        if (!(o instanceof RsNavNode)) {
            String problem = o == null ? "no node called \"" + name + "\" was received before this link"
                    : "\"" + name + "\" is a " + o.getClassName() + ", not a node";
            throw new RsProtocolException(field, problem);
        }
        return (RsNavNode) o;
    }
}
