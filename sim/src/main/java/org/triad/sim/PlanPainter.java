package org.triad.sim;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.util.List;

/** Draws a floor plan and agents with y pointing up, at a fixed scale in pixels per metre. */
final class PlanPainter {
    static final Color ROOM = new Color(245, 245, 240);
    static final Color CORRIDOR = new Color(225, 232, 240);
    static final Color WALL = new Color(40, 40, 40);
    static final Color DOOR_OPEN = new Color(60, 170, 60);
    static final Color DOOR_CLOSED = new Color(210, 40, 40);
    static final Color GRAPH = new Color(190, 190, 205);
    static final Color ROBOT = new Color(30, 80, 200);
    static final Color PERSON = new Color(240, 140, 20);
    static final Color ITEM = new Color(140, 60, 170);
    static final Color TEXT = new Color(20, 20, 20);

    static {
        if (System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
    }

    final FloorPlan plan;
    final double scale;
    final int margin;
    final int width;
    final int height;
    private boolean textWorks = true;

    PlanPainter(FloorPlan plan, double pixelsPerMetre, int margin) {
        Checks.positive("pixels per metre", pixelsPerMetre);
        this.plan = plan;
        this.scale = pixelsPerMetre;
        this.margin = margin;
        this.width = (int) Math.ceil(plan.bounds().width() * scale) + 2 * margin;
        this.height = (int) Math.ceil(plan.bounds().height() * scale) + 2 * margin;
    }

    double px(double x) {
        return margin + (x - plan.bounds().minX()) * scale;
    }

    double py(double y) {
        return margin + (plan.bounds().maxY() - y) * scale;
    }

    void setup(Graphics2D g, boolean antialias) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING,
                antialias ? RenderingHints.VALUE_ANTIALIAS_ON : RenderingHints.VALUE_ANTIALIAS_OFF);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING,
                antialias ? RenderingHints.VALUE_TEXT_ANTIALIAS_ON : RenderingHints.VALUE_TEXT_ANTIALIAS_OFF);
    }

    void paintPlan(Graphics2D g, boolean[] doorOpen, boolean graph, boolean labels) {
        for (Room r : plan.rooms()) {
            Rect b = r.bounds();
            g.setColor(r.corridor() ? CORRIDOR : ROOM);
            g.fill(new Rectangle2D.Double(px(b.minX()), py(b.maxY()), b.width() * scale, b.height() * scale));
        }
        if (graph) {
            g.setColor(GRAPH);
            g.setStroke(new BasicStroke(1f));
            for (GraphEdge e : plan.edges()) {
                line(g, plan.waypoint(e.from()).position(), plan.waypoint(e.to()).position());
            }
            for (Waypoint w : plan.waypoints()) {
                disc(g, w.position(), 0.06);
            }
        }
        g.setColor(WALL);
        g.setStroke(new BasicStroke((float) Math.max(1, plan.wallThickness() * scale), BasicStroke.CAP_SQUARE,
                BasicStroke.JOIN_MITER));
        for (Wall w : plan.walls()) {
            line(g, w.a(), w.b());
        }
        List<Doorway> doors = plan.doorways();
        g.setStroke(new BasicStroke((float) Math.max(2, plan.wallThickness() * scale * 0.8)));
        for (int i = 0; i < doors.size(); i++) {
            boolean open = doorOpen == null || i >= doorOpen.length || doorOpen[i];
            g.setColor(open ? DOOR_OPEN : DOOR_CLOSED);
            if (open) {
                Doorway d = doors.get(i);
                double s = d.width() * 0.15;
                Vec2 tick = d.horizontal() ? new Vec2(0, s) : new Vec2(s, 0);
                line(g, d.end1().minus(tick), d.end1().plus(tick));
                line(g, d.end2().minus(tick), d.end2().plus(tick));
            } else {
                line(g, doors.get(i).end1(), doors.get(i).end2());
            }
        }
        if (labels) {
            g.setColor(TEXT);
            font(g, Math.max(9, (int) (scale * 0.35)));
            for (Room r : plan.rooms()) {
                text(g, r.name(), px(r.bounds().minX()) + 3, py(r.bounds().maxY()) + Math.max(10, scale * 0.4));
            }
        }
    }

    void line(Graphics2D g, Vec2 a, Vec2 b) {
        g.draw(new Line2D.Double(px(a.x()), py(a.y()), px(b.x()), py(b.y())));
    }

    void disc(Graphics2D g, Vec2 c, double radius) {
        double r = Math.max(1.5, radius * scale);
        g.fill(new Ellipse2D.Double(px(c.x()) - r, py(c.y()) - r, 2 * r, 2 * r));
    }

    void font(Graphics2D g, int size) {
        if (textWorks) {
            try {
                g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, size));
            } catch (RuntimeException | Error e) {
                if (e instanceof VirtualMachineError fatal) {
                    throw fatal;
                }
                textWorks = false;
            }
        }
    }

    /** Draws text unless the JRE has no usable fonts (minimal images): pictures stay useful without labels. */
    void text(Graphics2D g, String s, double x, double y) {
        if (textWorks) {
            try {
                g.drawString(s, (float) x, (float) y);
            } catch (RuntimeException | Error e) {
                if (e instanceof VirtualMachineError fatal) {
                    throw fatal;
                }
                textWorks = false;
            }
        }
    }
}
