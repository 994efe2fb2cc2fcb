package rp1.view;

import java.util.function.Supplier;

import rp1.rossum.RsFeet;
import rp1.rossum.RsInches;
import rp1.rossum.RsMeters;
import rp1.rossum.RsUnits;

/** The units the window can show coordinates in: the View → Units menu, in the original's order. */
enum DisplayUnits {
    INCHES("Inches", RsInches::new),
    FEET("Feet", RsFeet::new),
    METERS("Meters", RsMeters::new);

    private final String label;
    private final Supplier<RsUnits> factory;

    DisplayUnits(String label, Supplier<RsUnits> factory) {
        this.label = label;
        this.factory = factory;
    }

    /** The menu item's text. */
    String label() {
        return label;
    }

    /** A formatter for these units. */
    RsUnits units() {
        return factory.get();
    }

    /**
     * The choice matching a plan's units, checked when the window opens (RP1 0.60 checked none).
     * Plans in kilometres are shown in metres.
     */
    static DisplayUnits of(RsUnits planUnits) {
        if (planUnits instanceof RsInches) {
            return INCHES;
        }
        return planUnits instanceof RsFeet ? FEET : METERS;
    }
}
