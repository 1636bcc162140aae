package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

class PicturesTest {
    private static final Path OUT = Path.of("target", "pictures");
    private static Simulation sim;

    @BeforeAll
    static void deliverWithADetour() {
        sim = Scenes.sim(5);
        Robot robot = sim.addRobot("robot", "corridorWest", RobotSpec.defaults());
        robot.setBattery(new Battery(360_000, 50, 500, 0.5)); // half full: the gauges are half green, half white
        sim.addPerson("nurse", "room5", PersonSpec.defaults()).wander();
        sim.closeDoor("room1-room2");
        robot.moveTo("storage");
        robot.pick("item1");
        robot.moveTo("room2");
        robot.moveTo("room2");
        robot.place("item1");
    }

    @Test
    void pngIsWrittenAndDecodable() throws IOException {
        Path file = OUT.resolve("delivery.png");
        TracePicture.writePng(sim, file, 30);
        BufferedImage img = ImageIO.read(file.toFile());
        assertNotNull(img, "ImageIO can decode the PNG");
        PlanPainter p = new PlanPainter(sim.plan(), 30, 20);
        assertEquals(Math.max(p.width, TracePicture.MIN_WIDTH), img.getWidth());
        int events = sim.trace().events().size();
        assertEquals(p.height + 10 + 16 * (events + 1), img.getHeight(), "map plus one legend line per event");
        assertTrue(events >= 5, "events recorded: " + sim.trace().events());
        int robotPixels = 0;
        for (int x = 0; x < p.width; x++) {
            for (int y = 0; y < p.height; y++) {
                robotPixels += (img.getRGB(x, y) & 0xffffff) == (PlanPainter.ROBOT.getRGB() & 0xffffff) ? 1 : 0;
            }
        }
        assertTrue(robotPixels > 500, "the trajectory is drawn in robot colour, pixels: " + robotPixels);
    }

    @Test
    void gifIsAnimatedLoopingAndDecodable() throws IOException {
        Path file = OUT.resolve("delivery.gif");
        GifReplay.write(sim, file, 0.5, 120, 12, 40);
        ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            reader.setInput(in);
            int frames = reader.getNumImages(true);
            assertTrue(frames > 10 && frames <= 120, "frames: " + frames);
            BufferedImage first = reader.read(0);
            PlanPainter p = new PlanPainter(sim.plan(), 12, 8);
            assertEquals(p.width, first.getWidth());
            assertEquals(p.height + 16, first.getHeight());
            int roomPixel = first.getRGB((int) p.px(0.5), (int) p.py(0.5)) & 0xffffff;
            assertEquals(PlanPainter.ROOM.getRGB() & 0xffffff, roomPixel, "palette colours survive the GIF round trip");
            IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(0).getAsTree("javax_imageio_gif_image_1.0");
            IIOMetadataNode gce = (IIOMetadataNode) root.getElementsByTagName("GraphicControlExtension").item(0);
            assertEquals("4", gce.getAttribute("delayTime"));
            IIOMetadataNode app = (IIOMetadataNode) root.getElementsByTagName("ApplicationExtension").item(0);
            assertEquals("NETSCAPE", app.getAttribute("applicationID"));
            assertFalse(java.util.Arrays.equals(pixels(first), pixels(reader.read(frames - 1))), "the robot moved");
        } finally {
            reader.dispose();
        }
    }

    @Test
    void htmlReplayIsSelfContained() throws IOException {
        Path file = OUT.resolve("delivery.html");
        HtmlReplay.write(sim, file);
        String html = Files.readString(file);
        assertTrue(html.startsWith("<!DOCTYPE html>"));
        assertFalse(html.contains("/*DATA*/"));
        assertFalse(html.contains("src=\"http") || html.contains("href=\"http"), "no external resources");
        assertTrue(html.contains("\"room1-room2\"") && html.contains("pick(item1)"), "plan and events inlined");
        long frames = java.util.regex.Pattern.compile("\\[\\d+\\.\\d{3},\\[").matcher(html).results().count();
        int stride = (int) Math.round(0.1 / sim.stepSeconds());
        assertEquals((sim.trace().frames().size() + stride - 1) / stride, frames, "one frame per 0.1 s");
        assertEquals(html.chars().filter(c -> c == '[').count(), html.chars().filter(c -> c == ']').count(),
                "balanced data");
    }

    @Test
    void everyPictureShowsTheBattery() throws IOException {
        Robot robot = sim.robots().get(0);
        double end = robot.battery().percent();
        assertTrue(end < 50 && end > 45, "it drove from half full: " + end);
        // HTML: the charge at every frame, beside the time and as a gauge
        String html = Files.readString(writeHtml());
        java.util.List<Double> levels = java.util.regex.Pattern.compile(",\\[(\\d+\\.\\d)\\]\\]").matcher(html).results()
                .map(m -> Double.parseDouble(m.group(1))).toList();
        long frames = java.util.regex.Pattern.compile("\\[\\d+\\.\\d{3},\\[").matcher(html).results().count();
        assertEquals(frames, levels.size(), "one battery level per frame");
        assertEquals(50.0, levels.get(0), 0.1);
        assertEquals(end, levels.get(levels.size() - 1), 0.1);
        for (int i = 1; i < levels.size(); i++) {
            assertTrue(levels.get(i) <= levels.get(i - 1), "driving only draws it down: " + levels);
        }
        assertTrue(html.contains("'battery '+f[5][0].toFixed(1)"), "the figure beside the time");
        // PNG: a gauge beside the robot where it ends, filled to its charge; the legend gives it per action
        BufferedImage png = TracePicture.render(sim, 30);
        PlanPainter p = new PlanPainter(sim.plan(), 30, 20);
        double right = p.px(robot.position().x()) + robot.radius() * p.scale + 4;
        double top = p.py(robot.position().y()) - 4;
        assertEquals(PlanPainter.DOOR_OPEN.getRGB(), png.getRGB((int) right + 3, (int) top + 4), "the charged part");
        assertEquals(java.awt.Color.WHITE.getRGB(), png.getRGB((int) right + 27, (int) top + 4), "the spent part");
        // GIF: the gauge in the caption of every frame
        Path gif = OUT.resolve("battery.gif");
        GifReplay.write(sim, gif, 0.5, 120, 12, 40);
        ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            reader.setInput(in);
            BufferedImage last = reader.read(reader.getNumImages(true) - 1);
            PlanPainter q = new PlanPainter(sim.plan(), 12, 8);
            assertEquals(PlanPainter.DOOR_OPEN.getRGB() & 0xffffff, last.getRGB(7, q.height + 8) & 0xffffff, "the charged part");
            assertEquals(0xffffff, last.getRGB(31, q.height + 8) & 0xffffff, "the spent part");
        } finally {
            reader.dispose();
        }
    }

    private static Path writeHtml() {
        Path file = OUT.resolve("battery.html");
        HtmlReplay.write(sim, file);
        return file;
    }

    @Test
    void picturesRejectBadParameters() {
        assertThrows(IllegalArgumentException.class, () -> TracePicture.writePng(sim, OUT.resolve("x.png"), -1));
        assertThrows(IllegalArgumentException.class, () -> GifReplay.write(sim, OUT.resolve("x.gif"), 0, 10, 10, 50));
        Simulation empty = Simulation.builder(Scenes.PLAN).build();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TracePicture.writePng(empty, OUT.resolve("x.png")));
        assertTrue(e.getMessage().contains("no recorded frames"));
    }

    private static int[] pixels(BufferedImage img) {
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }
}
