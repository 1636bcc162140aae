package org.triad.tests.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.StaleElementReferenceException;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.triad.examples.hospital.vda5050.SimulatedAgv;
import org.triad.service.AccessTokens;
import org.triad.service.TriadService;
import org.triad.vda5050.broker.MosquittoBroker;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The operator page in Debian's Chromium shows every robot of the building on one live map per floor: two
 * couriers speaking VDA 5050 on a real Mosquitto, drawn where their states put them on floor 0's layout (floor 1's
 * drawn beside, empty), the map redrawn from the event stream while one of them drives, with each robot's battery.
 */
class BuildingMapBrowserTest {
    private static final Path HOSPITAL = Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize();
    private static final String OPERATOR = "building-map-operator";

    @TempDir
    Path dir;

    @Test
    void theOperatorSeesEveryRobotOfTheBuildingOnOneLiveMap() throws Exception {
        ChromeDriver browser = null;
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                SimulatedAgv c1 = new SimulatedAgv(broker.url(), "courier-1", 42, 5, null, line -> { }).start();
                SimulatedAgv c2 = new SimulatedAgv(broker.url(), "courier-2", 43, 5, null, line -> { }).start();
                TriadService s = TriadService.start(new TriadService.Options(HOSPITAL, List.of("vda5050:" + broker.url() + ",wait=1,silence=30"), null,
                        dir.resolve("db"), null, "127.0.0.1", 0, Map.of(AccessTokens.SUBMIT_ENV, "building-map-submit", AccessTokens.OPERATOR_ENV, OPERATOR)))) {
            browser = HeadlessChromium.start(dir.resolve("chromium-profile"));
            check(s, browser);
        } finally {
            if (browser != null) {
                browser.quit();
            }
        }
    }

    private void check(TriadService s, ChromeDriver browser) throws Exception {
        {
            browser.get(s.url() + "/operator.html#token=" + OPERATOR);
            WebDriverWait wait = new WebDriverWait(browser, Duration.ofSeconds(60), Duration.ofMillis(100));
            wait.ignoring(StaleElementReferenceException.class);
            String map = "#building canvas[data-map='" + SimulatedAgv.MAP_ID + "']";
            wait.until(d -> d.findElements(By.cssSelector(map)).stream().anyMatch(c -> "courier-1 courier-2".equals(c.getAttribute("data-robots"))));
            // one map per floor: both couriers on floor 0's (the map id they report), floor 1's drawn without robots
            assertEquals(2, browser.findElements(By.cssSelector("#building canvas")).size(), "one map per floor");
            String upstairs = "#building canvas[data-map='" + SimulatedAgv.mapId(1) + "']";
            assertEquals("", browser.findElement(By.cssSelector(upstairs)).getAttribute("data-robots"), "nobody upstairs");
            assertTrue(browser.findElement(By.cssSelector(upstairs)).findElement(By.xpath("..")).getText().contains(SimulatedAgv.mapId(1)),
                    "floor 1's map is captioned with its map id");
            assertTrue(blueDiscPixels(browser, map) > 40, "two robot discs are drawn");
            wait.until(d -> d.findElement(By.cssSelector("[data-robot='courier-1'] .robot-battery")).getText().startsWith("battery "));

            int before = updates(browser, map);
            long id = s.fleet().submit(new ObjectMapper().createObjectNode().put("task", "GoTo").set("args", new ObjectMapper().createObjectNode().put("dst", "ward3"))).id();
            wait.until(d -> s.fleet().task(id).orElseThrow().state().equals("completed") || s.fleet().task(id).orElseThrow().state().equals("aborted"));
            assertEquals("completed", s.fleet().task(id).orElseThrow().state(), s.fleet().task(id).orElseThrow().toString());
            wait.until(d -> updates(browser, map) > before + 1);
            Files.createDirectories(ServicePagesBrowserTest.PICTURES);
            Files.write(ServicePagesBrowserTest.PICTURES.resolve("operator-building-map.png"), browser.getScreenshotAs(OutputType.BYTES));
        }
    }

    private static int updates(ChromeDriver browser, String canvas) {
        return Integer.parseInt(browser.findElement(By.cssSelector(canvas)).getAttribute("data-updates"));
    }

    /** Pixels of the robots' blue (#1c5fb8) on the canvas. */
    private static long blueDiscPixels(ChromeDriver browser, String canvas) {
        Object n = browser.executeScript("const c = document.querySelector(arguments[0]);"
                + "const p = c.getContext('2d').getImageData(0, 0, c.width, c.height).data; let n = 0;"
                + "for (let i = 0; i < p.length; i += 4) { if (p[i] === 28 && p[i + 1] === 95 && p[i + 2] === 184) n++; } return n;", canvas);
        return ((Number) n).longValue();
    }
}
