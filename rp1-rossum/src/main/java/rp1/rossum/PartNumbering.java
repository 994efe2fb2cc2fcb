package rp1.rossum;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Gives parts their ids (protocol.md section 8.6): the parts of one body, or of one part in no body
 * with its sub-parts, that have no id yet get the ids after the largest one already given there
 * (1, 2, ... for a fresh body) in the order they were constructed. Parts that have an id keep it, so an
 * id once read never changes.
 *
 * <p>The body is the unit because a part id only has to name a part within its robot: the server
 * keeps each robot's ids as its client sent them. Numbering at first need rather than in the
 * constructor keeps the numbering out of any process-wide counter, and construction order keeps
 * RP1 0.60's ids for a client's one body (wheels built right after their wheel system still follow
 * its id, as the decoder assumes).
 */
final class PartNumbering {
    private PartNumbering() {
    }

    /** Numbers the body (or the part tree) {@code part} belongs to, if the part has no id yet. */
    static void number(RsBodyPart part) {
        Object root = root(part);
        if (root instanceof RsBody) {
            number((RsBody) root);
            return;
        }
        RsBodyPart top = (RsBodyPart) root;
        synchronized (top) {
            numberAll(treeOf(top));
        }
    }

    /** Numbers every part of {@code body} that has no id yet. */
    static void number(RsBody body) {
        synchronized (body) {
            numberAll(body.allParts());
        }
    }

    /** The body the part is in, else the top of its part tree (itself, or the actuator it belongs to). */
    private static Object root(RsBodyPart part) {
        RsBodyPart p = part;
        while (true) {
            RsComponent owner = p.owner();
            if (owner instanceof RsBody) {
                return owner;
            } else if (owner instanceof RsBodyPart) {
                p = (RsBodyPart) owner;
            } else {
                return p;
            }
        }
    }

    private static List<RsBodyPart> treeOf(RsBodyPart top) {
        List<RsBodyPart> tree = new ArrayList<>();
        tree.add(top);
        if (top instanceof RsActuator) {
            for (RsBodyPart sub : ((RsActuator) top).partsArray) {
                tree.add(sub);
            }
        }
        return tree;
    }

    private static void numberAll(List<RsBodyPart> parts) {
        int largest = 0;
        List<RsBodyPart> fresh = new ArrayList<>();
        for (RsBodyPart p : parts) {
            if (p.isNumbered()) {
                largest = Math.max(largest, p.getID());
            } else {
                fresh.add(p);
            }
        }
        fresh.sort(Comparator.comparingLong(RsBodyPart::constructionOrder));
        int next = largest + 1;
        for (RsBodyPart p : fresh) {
            if (!p.isNumbered()) {
                p.assignID(next++);
            }
        }
    }
}
