package org.triad.sim;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import javax.imageio.ImageIO;

/**
 * A PNG of the floor plan with the waypoint graph, each robot's trajectory, people's paths, final
 * positions of people and items, and a numbered marker where each action ended (green success, red
 * failure), explained in a legend under the map with the acting robot's battery when the action ended. Door colours
 * show the final state (red closed); a gauge beside each robot shows its final battery.
 */
public final class TracePicture {
    private static final int MAX_LEGEND_LINES = 40;
    /** Minimum picture width in pixels, so legend lines of ~140 characters fit. */
    static final int MIN_WIDTH = 1000;

    private TracePicture() {
    }

    /** Writes the picture at 40 pixels per metre; creates parent directories. */
    public static void writePng(Simulation sim, Path file) {
        writePng(sim, file, 40);
    }

    /**
     * @param pixelsPerMetre map scale, &gt; 0
     * @throws IllegalArgumentException for a bad scale or a simulation without a recorded trace
     * @throws UncheckedIOException if the file cannot be written
     */
    public static void writePng(Simulation sim, Path file, double pixelsPerMetre) {
        Checks.notNull("simulation", sim);
        Checks.notNull("file", file);
        BufferedImage img = render(sim, pixelsPerMetre);
        write(img, "png", file);
    }

    static BufferedImage render(Simulation sim, double pixelsPerMetre) {
        Trace trace = sim.trace();
        if (trace.frames().isEmpty()) {
            throw new IllegalArgumentException("the simulation has no recorded frames (trace off or no step taken)");
        }
        PlanPainter p = new PlanPainter(sim.plan(), pixelsPerMetre, 20);
        List<TraceEvent> events = new ArrayList<>();
        for (TraceEvent e : trace.events()) {
            if (events.size() < MAX_LEGEND_LINES) {
                events.add(e);
            }
        }
        int lineHeight = 16;
        int legendLines = events.size() + 1 + (trace.events().size() > events.size() ? 1 : 0);
        BufferedImage img = new BufferedImage(Math.max(p.width, MIN_WIDTH), p.height + 10 + lineHeight * legendLines,
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        p.setup(g, true);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, img.getWidth(), img.getHeight());
        TraceFrame last = trace.frames().get(trace.frames().size() - 1);
        p.paintPlan(g, last.doorOpen(), true, true);

        g.setStroke(new BasicStroke(1.2f));
        g.setColor(new Color(240, 140, 20, 140));
        for (int i = 0; i < trace.personNames().size(); i++) {
            g.draw(path(p, trace, i, false));
        }
        g.setStroke(new BasicStroke(2.2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.setColor(PlanPainter.ROBOT);
        for (int i = 0; i < trace.robotNames().size(); i++) {
            g.draw(path(p, trace, i, true));
        }
        for (int i = 0; i < last.personX().length; i++) {
            if (!Double.isNaN(last.personX()[i])) {
                g.setColor(PlanPainter.PERSON);
                p.disc(g, new Vec2(last.personX()[i], last.personY()[i]), 0.25);
            }
        }
        for (int i = 0; i < last.itemX().length; i++) {
            if (!Double.isNaN(last.itemX()[i])) {
                g.setColor(PlanPainter.ITEM);
                double s = Math.max(4, 0.2 * p.scale);
                g.fill(new Rectangle2D.Double(p.px(last.itemX()[i]) - s / 2, p.py(last.itemY()[i]) - s / 2, s, s));
                g.setColor(PlanPainter.TEXT);
                p.font(g, 10);
                p.text(g, trace.itemNames().get(i), p.px(last.itemX()[i]) + s, p.py(last.itemY()[i]) - s / 2);
            }
        }
        for (int i = 0; i < last.robotX().length; i++) {
            g.setColor(PlanPainter.ROBOT);
            p.disc(g, new Vec2(last.robotX()[i], last.robotY()[i]), sim.robots().get(i).radius());
            double right = p.px(last.robotX()[i]) + sim.robots().get(i).radius() * p.scale + 4;
            double top = p.py(last.robotY()[i]) - 4;
            BatteryGauge.draw(g, right, top, 30, 8, last.robotBattery()[i]);
            g.setColor(PlanPainter.TEXT);
            p.font(g, 10);
            p.text(g, String.format(Locale.ROOT, "%.0f %%", last.robotBattery()[i]), right + 33, top + 8);
        }
        p.font(g, 11);
        for (int i = 0; i < events.size(); i++) {
            TraceEvent e = events.get(i);
            g.setColor(e.success() ? new Color(0, 140, 60) : new Color(210, 30, 30));
            p.disc(g, e.position(), 0.13);
            g.setColor(PlanPainter.TEXT);
            p.text(g, Integer.toString(i + 1), p.px(e.position().x()) + 6, p.py(e.position().y()) - 6);
        }
        int y = p.height + 10;
        p.font(g, 12);
        g.setColor(PlanPainter.TEXT);
        int omitted = trace.events().size() - events.size();
        if (omitted > 0) {
            p.text(g, "(" + omitted + " later events not shown)", 10, y + lineHeight * (events.size() + 1));
        }
        for (int i = 0; i < events.size(); i++) {
            TraceEvent e = events.get(i);
            double battery = BatteryGauge.at(trace, trace.robotNames().indexOf(e.actor()), e.time());
            String line = String.format(Locale.ROOT, "%2d  t=%7.2fs  %-8s %s %s%s%s", i + 1, e.time(), e.actor(),
                    e.success() ? "ok  " : "FAIL", Double.isNaN(battery) ? "" : String.format(Locale.ROOT, "[%5.1f %%] ", battery),
                    e.action(), e.success() || e.detail().isEmpty() ? "" : " - " + e.detail());
            p.text(g, line.length() > 140 ? line.substring(0, 137) + "..." : line, 10, y + lineHeight * (i + 1));
        }
        g.dispose();
        return img;
    }

    private static Path2D path(PlanPainter p, Trace trace, int index, boolean robot) {
        Path2D.Double path = new Path2D.Double();
        boolean pen = false;
        for (TraceFrame f : trace.frames()) {
            double[] xs = robot ? f.robotX() : f.personX();
            double[] ys = robot ? f.robotY() : f.personY();
            if (index >= xs.length || Double.isNaN(xs[index])) {
                pen = false;
                continue;
            }
            if (pen) {
                path.lineTo(p.px(xs[index]), p.py(ys[index]));
            } else {
                path.moveTo(p.px(xs[index]), p.py(ys[index]));
                pen = true;
            }
        }
        return path;
    }

    static void write(BufferedImage img, String format, Path file) {
        try {
            Path parent = file.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            if (!ImageIO.write(img, format, file.toFile())) {
                throw new IllegalStateException("no ImageIO writer for " + format);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + file, e);
        }
    }
}
