package org.triad.sim;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;

/**
 * A compact looping animated GIF of a trace: frames sampled every {@code frameSeconds} of virtual time
 * (or coarser, to stay under {@code maxFrames}), drawn with a 16-colour palette.
 */
public final class GifReplay {
    private static final Color TRAIL = new Color(150, 175, 235);
    private static final Color[] PALETTE = {Color.WHITE, PlanPainter.ROOM, PlanPainter.CORRIDOR, PlanPainter.WALL,
        PlanPainter.DOOR_OPEN, PlanPainter.DOOR_CLOSED, PlanPainter.GRAPH, PlanPainter.ROBOT, PlanPainter.PERSON,
        PlanPainter.ITEM, PlanPainter.TEXT, TRAIL, Color.BLACK, new Color(255, 230, 150), Color.GRAY, Color.LIGHT_GRAY};

    private GifReplay() {
    }

    /** One frame per 0.5 s of virtual time, at most 400 frames, 16 px/m, shown at 20 frames per second. */
    public static void write(Simulation sim, Path file) {
        write(sim, file, 0.5, 400, 16, 50);
    }

    /**
     * @param frameSeconds   virtual seconds between frames, &gt; 0
     * @param maxFrames      upper bound on frames, &gt;= 1
     * @param pixelsPerMetre scale, &gt; 0
     * @param frameDelayMs   display time of each frame, milliseconds (GIF resolution 10 ms), &gt;= 10
     * @throws IllegalArgumentException on bad parameters or an empty trace
     * @throws UncheckedIOException if the file cannot be written
     */
    public static void write(Simulation sim, Path file, double frameSeconds, int maxFrames, double pixelsPerMetre,
                             int frameDelayMs) {
        Checks.notNull("simulation", sim);
        Checks.notNull("file", file);
        Checks.positive("frame interval (s)", frameSeconds);
        if (maxFrames < 1) {
            throw new IllegalArgumentException("max frames must be >= 1, got " + maxFrames);
        }
        if (frameDelayMs < 10) {
            throw new IllegalArgumentException("frame delay must be >= 10 ms, got " + frameDelayMs);
        }
        List<TraceFrame> frames = sim.trace().frames();
        if (frames.isEmpty()) {
            throw new IllegalArgumentException("the simulation has no recorded frames (trace off or no step taken)");
        }
        PlanPainter painter = new PlanPainter(sim.plan(), pixelsPerMetre, 8);
        int stride = Math.max(1, (int) Math.round(frameSeconds / sim.stepSeconds()));
        stride = Math.max(stride, (int) Math.ceil(frames.size() / (double) maxFrames));
        IndexColorModel palette = palette();
        try {
            Path parent = file.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            Files.deleteIfExists(file);
            ImageWriter writer = ImageIO.getImageWritersByFormatName("gif").next();
            try (ImageOutputStream out = ImageIO.createImageOutputStream(file.toFile())) {
                writer.setOutput(out);
                writer.prepareWriteSequence(null);
                boolean first = true;
                for (int i = 0; i < frames.size(); i += stride) {
                    BufferedImage img = frame(sim, painter, palette, i);
                    ImageWriteParam param = writer.getDefaultWriteParam();
                    IIOMetadata meta = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(img),
                            param);
                    configure(meta, frameDelayMs / 10, first);
                    writer.writeToSequence(new IIOImage(img, null, meta), param);
                    first = false;
                }
                writer.endWriteSequence();
            } finally {
                writer.dispose();
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + file, e);
        }
    }

    private static IndexColorModel palette() {
        byte[] r = new byte[PALETTE.length];
        byte[] g = new byte[PALETTE.length];
        byte[] b = new byte[PALETTE.length];
        for (int i = 0; i < PALETTE.length; i++) {
            r[i] = (byte) PALETTE[i].getRed();
            g[i] = (byte) PALETTE[i].getGreen();
            b[i] = (byte) PALETTE[i].getBlue();
        }
        return new IndexColorModel(4, PALETTE.length, r, g, b);
    }

    private static BufferedImage frame(Simulation sim, PlanPainter p, IndexColorModel palette, int index) {
        Trace trace = sim.trace();
        TraceFrame f = trace.frames().get(index);
        BufferedImage img = new BufferedImage(p.width, p.height + 16, BufferedImage.TYPE_BYTE_INDEXED, palette);
        Graphics2D g = img.createGraphics();
        p.setup(g, false);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, img.getWidth(), img.getHeight());
        p.paintPlan(g, f.doorOpen(), false, false);
        g.setColor(TRAIL);
        g.setStroke(new BasicStroke(1.5f));
        for (int r = 0; r < f.robotX().length; r++) {
            Path2D.Double path = new Path2D.Double();
            boolean pen = false;
            for (int k = 0; k <= index; k += 6) {
                TraceFrame h = trace.frames().get(k);
                if (r < h.robotX().length) {
                    if (pen) {
                        path.lineTo(p.px(h.robotX()[r]), p.py(h.robotY()[r]));
                    } else {
                        path.moveTo(p.px(h.robotX()[r]), p.py(h.robotY()[r]));
                        pen = true;
                    }
                }
            }
            g.draw(path);
        }
        for (int i = 0; i < f.itemX().length; i++) {
            if (!Double.isNaN(f.itemX()[i])) {
                g.setColor(PlanPainter.ITEM);
                double s = Math.max(3, 0.2 * p.scale);
                g.fill(new Rectangle2D.Double(p.px(f.itemX()[i]) - s / 2, p.py(f.itemY()[i]) - s / 2, s, s));
            }
        }
        g.setColor(PlanPainter.PERSON);
        for (int i = 0; i < f.personX().length; i++) {
            if (!Double.isNaN(f.personX()[i])) {
                p.disc(g, new Vec2(f.personX()[i], f.personY()[i]), sim.person(trace.personNames().get(i)).radius());
            }
        }
        for (int r = 0; r < f.robotX().length; r++) {
            Vec2 c = new Vec2(f.robotX()[r], f.robotY()[r]);
            double radius = sim.robots().get(r).radius();
            g.setColor(PlanPainter.ROBOT);
            p.disc(g, c, radius);
            g.setColor(Color.WHITE);
            g.setStroke(new BasicStroke(2f));
            p.line(g, c, c.plus(new Vec2(Math.cos(f.robotHeading()[r]), Math.sin(f.robotHeading()[r])).times(radius)));
        }
        g.setColor(PlanPainter.TEXT);
        p.font(g, 11);
        String last = "";
        for (TraceEvent e : trace.events()) {
            if (e.time() <= f.time() + 1e-9) {
                last = (e.success() ? "" : "FAIL ") + e.action();
            }
        }
        // the battery first, so that a long action does not push it out of the caption
        int gauge = f.robotBattery().length == 1 ? 34 : 0;
        if (gauge > 0) {
            BatteryGauge.draw(g, 4, p.height + 4, 30, 9, f.robotBattery()[0]);
        }
        g.setColor(PlanPainter.TEXT);
        String caption = String.format(Locale.ROOT, "t=%6.1fs  %s  %s", f.time(), BatteryGauge.label(trace.robotNames(), f.robotBattery()), last);
        p.text(g, caption.length() > 90 ? caption.substring(0, 87) + "..." : caption, 4 + gauge, p.height + 12);
        g.dispose();
        return img;
    }

    private static void configure(IIOMetadata meta, int delayCentiseconds, boolean first) throws IOException {
        String format = meta.getNativeMetadataFormatName();
        IIOMetadataNode root = (IIOMetadataNode) meta.getAsTree(format);
        IIOMetadataNode gce = child(root, "GraphicControlExtension");
        gce.setAttribute("disposalMethod", "none");
        gce.setAttribute("userInputFlag", "FALSE");
        gce.setAttribute("transparentColorFlag", "FALSE");
        gce.setAttribute("delayTime", Integer.toString(delayCentiseconds));
        gce.setAttribute("transparentColorIndex", "0");
        // Without a local table the writer falls back to a generic 256-colour global table, which
        // maps our indices to the wrong colours.
        IIOMetadataNode table = child(root, "LocalColorTable");
        while (table.getFirstChild() != null) {
            table.removeChild(table.getFirstChild());
        }
        table.setAttribute("sizeOfLocalColorTable", Integer.toString(PALETTE.length));
        table.setAttribute("sortFlag", "FALSE");
        for (int i = 0; i < PALETTE.length; i++) {
            IIOMetadataNode entry = new IIOMetadataNode("ColorTableEntry");
            entry.setAttribute("index", Integer.toString(i));
            entry.setAttribute("red", Integer.toString(PALETTE[i].getRed()));
            entry.setAttribute("green", Integer.toString(PALETTE[i].getGreen()));
            entry.setAttribute("blue", Integer.toString(PALETTE[i].getBlue()));
            table.appendChild(entry);
        }
        if (first) {
            IIOMetadataNode apps = child(root, "ApplicationExtensions");
            IIOMetadataNode loop = new IIOMetadataNode("ApplicationExtension");
            loop.setAttribute("applicationID", "NETSCAPE");
            loop.setAttribute("authenticationCode", "2.0");
            loop.setUserObject(new byte[] {1, 0, 0});
            apps.appendChild(loop);
        }
        meta.setFromTree(format, root);
    }

    private static IIOMetadataNode child(IIOMetadataNode root, String name) {
        for (int i = 0; i < root.getLength(); i++) {
            if (root.item(i).getNodeName().equalsIgnoreCase(name)) {
                return (IIOMetadataNode) root.item(i);
            }
        }
        IIOMetadataNode node = new IIOMetadataNode(name);
        root.appendChild(node);
        return node;
    }
}
