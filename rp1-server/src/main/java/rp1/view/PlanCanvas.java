package rp1.view;

import java.awt.Color;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.function.Consumer;

import javax.swing.JComponent;

import rp1.rossum.RsPoint;
import rp1.simulator.Simulation;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * The white drawing area of the window: shows the latest snapshot fitted to its size (and zoomed),
 * turns mouse presses into mouse-click events for the clients (behavior.md section 8.8), and reports
 * the floor point under the pointer for the coordinate read-out. Used on the event thread only.
 */
final class PlanCanvas extends JComponent {
    private static final long serialVersionUID = 1L;
    /** Each zoom step magnifies or shrinks by this factor. */
    static final double ZOOM_STEP = 1.25;

    private final transient Renderer renderer;
    private transient WorldSnapshot snapshot;
    private double zoom = 1.0;

    /**
     * @param renderer   draws the snapshots
     * @param first      the snapshot shown until the first {@link #show}
     * @param simulation where mouse presses go
     * @param pointer    told the floor point under the pointer, or null when it leaves the canvas
     */
    PlanCanvas(Renderer renderer, WorldSnapshot first, Simulation simulation, Consumer<RsPoint> pointer) {
        this.renderer = renderer;
        this.snapshot = first;
        setOpaque(true);
        setBackground(Color.white);
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                RsPoint p = toWorld(e.getX(), e.getY());
                simulation.mouseClick(MouseButtons.codeOf(e), e.getClickCount(), p.x, p.y);
            }

            @Override
            public void mouseMoved(MouseEvent e) {
                pointer.accept(toWorld(e.getX(), e.getY()));
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                mouseMoved(e);
            }

            @Override
            public void mouseExited(MouseEvent e) {
                pointer.accept(null);
            }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
    }

    /** Shows {@code s} from the next repaint on, and asks for one. */
    void show(WorldSnapshot s) {
        snapshot = s;
        repaint();
    }

    /** The snapshot shown. */
    WorldSnapshot shown() {
        return snapshot;
    }

    /** How the world is mapped onto the canvas at its current size and zoom. */
    ViewTransform view() {
        ViewTransform fitted = ViewTransform.fit(renderer.getPlan().getBounds(), Math.max(1, getWidth()),
                Math.max(1, getHeight()));
        return zoom == 1.0 ? fitted : fitted.zoomed(zoom);
    }

    /** The floor point (metres) under canvas pixel (px, py). */
    RsPoint toWorld(int px, int py) {
        ViewTransform v = view();
        return new RsPoint(v.worldX(px), v.worldY(py));
    }

    void zoomIn() {
        setZoom(zoom * ZOOM_STEP);
    }

    void zoomOut() {
        setZoom(zoom / ZOOM_STEP);
    }

    /** Back to the whole plan fitted into the canvas. */
    void fit() {
        setZoom(1.0);
    }

    private void setZoom(double z) {
        zoom = z;
        repaint();
    }

    @Override
    protected void paintComponent(Graphics g) {
        renderer.render(snapshot, (Graphics2D) g, view());
    }
}
