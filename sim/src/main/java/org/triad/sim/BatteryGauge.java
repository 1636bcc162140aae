package org.triad.sim;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import java.util.Locale;

/**
 * How the pictures show a robot's battery: a bar filled to its state of charge (green, red below
 * {@value #LOW_PERCENT} %) beside the figure, in pixels of the picture.
 */
final class BatteryGauge {
    /** Below this charge the bar is red: a robot this low is sent to charge (the service's charging policy). */
    static final double LOW_PERCENT = 20;

    private BatteryGauge() {
    }

    /** The bar, {@code w} x {@code h} pixels with its top left corner at {@code x, y}, filled to {@code percent}. */
    static void draw(Graphics2D g, double x, double y, double w, double h, double percent) {
        double level = Double.isNaN(percent) ? 0 : Math.max(0, Math.min(100, percent));
        g.setColor(Color.WHITE);
        g.fill(new Rectangle2D.Double(x, y, w, h));
        g.setColor(level < LOW_PERCENT ? PlanPainter.DOOR_CLOSED : PlanPainter.DOOR_OPEN);
        g.fill(new Rectangle2D.Double(x, y, w * level / 100, h));
        g.setColor(PlanPainter.TEXT);
        g.setStroke(new BasicStroke(1f));
        g.draw(new Rectangle2D.Double(x, y, w, h));
    }

    /** {@code battery 87.2 %}, or {@code courier-1 87.2 %, courier-2 40.0 %} for several robots. */
    static String label(List<String> robots, double[] percent) {
        if (percent.length == 1) {
            return String.format(Locale.ROOT, "battery %.1f %%", percent[0]);
        }
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < percent.length && i < robots.size(); i++) {
            b.append(i > 0 ? ", " : "").append(robots.get(i)).append(String.format(Locale.ROOT, " %.1f %%", percent[i]));
        }
        return b.toString();
    }

    /** The charge of robot {@code robot} in the last frame at or before {@code time}, percent; NaN before its first. */
    static double at(Trace trace, int robot, double time) {
        List<TraceFrame> frames = trace.frames();
        int lo = 0;
        int hi = frames.size() - 1;
        int found = -1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            if (frames.get(mid).time() <= time + 1e-9) {
                found = mid;
                lo = mid + 1;
            } else {
                hi = mid - 1;
            }
        }
        if (found < 0 || robot < 0 || robot >= frames.get(found).robotBattery().length) {
            return Double.NaN;
        }
        return frames.get(found).robotBattery()[robot];
    }
}
