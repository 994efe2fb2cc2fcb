package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;

/**
 * An object of the floor plan: a wall or obstacle, a target, a placement, floor paint, or a node or
 * link of the navigation network. Every object has a name unique within its plan, colours, an
 * optional label, and a geometry in metres.
 */
public abstract class RsObject {
    /** True once {@link #setGeometry} has been given a usable geometry. */
    public boolean isGeometrySet;
    /** The plan this object belongs to. */
    public RsPlan plan;
    /** Whether the object is selected ({@link #getSelected()}). */
    protected boolean selected = true;
    /** The colour the object is filled with when drawn. */
    public Color fillColor;
    /** The colour of the object's outline when drawn. */
    public Color lineColor;
    /** Text drawn next to targets, placements and nodes; null for none. */
    public String label;

    private String name;
    private RsRectangle explicitBounds;

    /** An object called {@code name} (may be null until named) belonging to {@code plan}. */
    public RsObject(String name, RsPlan plan) {
        this.name = name;
        this.plan = plan;
    }

    /**
     * Names the object; names are unique within a plan ({@link RsPlan#addObject}).
     *
     * @param name the name
     */
    public void setName(String name) {
        this.name = name;
    }

    /**
     * The object's name in the plan.
     *
     * @return the name, or null if not yet named
     */
    public String getName() {
        return name;
    }

    /**
     * The axis-aligned box the object covers (used for the plan's extent), or an empty rectangle if
     * it has no geometry yet.
     */
    public RsRectangle getBounds() {
        if (explicitBounds != null) {
            return new RsRectangle(explicitBounds);
        }
        return isGeometrySet ? computeBounds() : new RsRectangle();
    }

    /**
     * Gives {@code copy} what every object has (name, colours, label, selection, bounds given, whether
     * its geometry is set), for {@link RsPlan#copy()}.
     */
    void copyCommonTo(RsObject copy) {
        copy.name = name;
        copy.isGeometrySet = isGeometrySet;
        copy.selected = selected;
        copy.fillColor = fillColor;
        copy.lineColor = lineColor;
        copy.label = label;
        copy.explicitBounds = explicitBounds == null ? null : new RsRectangle(explicitBounds);
    }

    /** Overrides the bounds computed from the geometry; null restores them. */
    public void setBounds(RsRectangle bounds) {
        explicitBounds = bounds == null ? null : new RsRectangle(bounds);
    }

    /** The bounding box of the current geometry (only called when the geometry is set). */
    protected RsRectangle computeBounds() {
        return new RsRectangle();
    }

    /** Whether the object is selected; only selected targets are sensed and drawn. */
    public boolean getSelected() {
        return selected;
    }

    /**
     * Selects or deselects the object; only selected targets are sensed and drawn.
     *
     * @param selected whether it is selected
     */
    public void setSelected(boolean selected) {
        this.selected = selected;
    }

    /** Sets both the fill and the line colour. */
    public void setColor(Color color) {
        fillColor = color;
        lineColor = color;
    }

    /**
     * Sets the fill colour.
     *
     * @param color the colour
     */
    public void setFillColor(Color color) {
        fillColor = color;
    }

    /**
     * Sets the outline colour.
     *
     * @param color the colour
     */
    public void setLineColor(Color color) {
        lineColor = color;
    }

    /**
     * Sets the text drawn next to targets, placements and nodes.
     *
     * @param label the text, or null for none
     */
    public void setLabel(String label) {
        this.label = label;
    }

    /** The floor-plan keyword for this kind of object ("wall", "target", ...). */
    public abstract String getClassName();

    /** Sets the geometry from the values of the floor plan's {@code geometry} specification, in metres. */
    public abstract void setGeometry(double[] geometry);

    /** The geometry in the form the plan event transmits (see each subclass). */
    public abstract double[] getGeometry();

    /** Draws the object; {@code t} maps world metres to device pixels. */
    public abstract void paint(Graphics g, RsTransform t);

    @Override
    public String toString() {
        return getClassName() + " " + name;
    }
}
