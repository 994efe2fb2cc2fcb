package rp1.rossum.request;

/**
 * Change which targets of the floor plan are selected (visible to target sensors): one by name, all
 * ("*"), a random one, optionally deselecting all others first (exclusive).
 */
public class RsTargetSelectionRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** Target name, "*" for all, empty for none (with {@code random}). */
    public final String name;
    /** Select one target chosen at random. */
    public final boolean random;
    /** Selected (true) or deselected. */
    public final boolean status;
    /** Deselect every target first. */
    public final boolean exclusive;

    /** A request with these values (the fields say what each one is). */
    public RsTargetSelectionRequest(boolean random, String name, boolean status, boolean exclusive) {
        super(REQ_TARGET_SELECTION);
        this.random = random;
        this.name = name;
        this.status = status;
        this.exclusive = exclusive;
    }
}
