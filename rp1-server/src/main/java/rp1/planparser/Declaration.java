package rp1.planparser;

import java.io.IOException;
import java.util.List;

import rp1.rossum.RsObject;

/**
 * The body of one object declaration being read: collects its specifications and, at the closing
 * brace, checks them and yields the finished object. The generic specifications ({@code color},
 * {@code lineColor}, {@code fillColor}, {@code label}) are handled here; each object type adds its own.
 */
abstract class Declaration {
    /** The object being declared, named already. */
    protected final RsObject object;
    private final boolean strict;
    private final String specificItems;

    /**
     * @param strict whether the body's syntax is checked strictly: walls, obstacles and paint reject a
     *     stray token where a specification should start; targets, placements, nodes and links skip
     *     it, as the original does, and their messages are worded differently
     * @param specificItems the specifications this type accepts besides the generic ones, for messages
     */
    Declaration(RsObject object, boolean strict, String specificItems) {
        this.object = object;
        this.strict = strict;
        this.specificItems = specificItems;
    }

    /** Whether the body's syntax is checked strictly (see the constructor). */
    final boolean strict() {
        return strict;
    }

    /**
     * Reads the value of specification {@code item} (its name and colon are consumed).
     *
     * @return false if this type has no such specification (nothing is consumed then)
     */
    final boolean item(Token item, ValueReader in) throws IOException, RsParsingException {
        switch (item.text()) {
            case "color":
                object.setColor(in.color());
                return true;
            case "lineColor":
                object.setLineColor(in.color());
                return true;
            case "fillColor":
                object.setFillColor(in.color());
                return true;
            case "label":
                object.setLabel(in.string());
                return true;
            default:
                return specificItem(item, in);
        }
    }

    /** Reads the value of a specification particular to this type; false if there is none called so. */
    protected abstract boolean specificItem(Token item, ValueReader in) throws IOException, RsParsingException;

    /**
     * Checks the collected specifications and completes the object.
     *
     * @param close the closing brace, where missing specifications are reported
     */
    abstract RsObject finish(Token close, PlanLexer lexer) throws RsParsingException;

    /**
     * The objects the declaration adds to the plan, in order: the one {@link #finish} completes, or
     * for a {@code bitmap} the walls of its image.
     *
     * @param close the closing brace, where missing specifications are reported
     */
    List<RsObject> objects(Token close, PlanLexer lexer) throws RsParsingException {
        return List.of(finish(close, lexer));
    }

    /** The keyword that declares this type. */
    String keyword() {
        return object.getClassName();
    }

    /** All specifications this type accepts, for messages. */
    final String acceptedItems() {
        return specificItems + ", color, lineColor, fillColor, label";
    }
}
