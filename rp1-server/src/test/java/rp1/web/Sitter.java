package rp1.web;

/** A {@link Wanderer} that stays at home until a mouse click sends it forward. */
public class Sitter extends Wanderer {
    @Override
    protected int legs() {
        return 0;
    }
}
