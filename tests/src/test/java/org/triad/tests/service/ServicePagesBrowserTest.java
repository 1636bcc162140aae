package org.triad.tests.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.StaleElementReferenceException;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.support.ui.Select;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.triad.service.AccessTokens;
import org.triad.service.TriadService;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The staff and operator pages in headless Chromium, on the hospital with one simulated courier
 * (sim-1, 20x real time) and one dry-run robot whose first four picks fail (dry-1): a task submitted on
 * the staff page completes while the operator page draws the courier on its floor map; an aborted task
 * arrives on the operator page with its cause and is retried from there until it completes.
 */
class ServicePagesBrowserTest {
    static final Path HOSPITAL = Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize();
    static final Path PICTURES = Path.of("target/pictures");
    static final String SUBMIT = "browser-test-submit";
    static final String OPERATOR = "browser-test-operator";

    @TempDir
    static Path dir;
    static TriadService service;
    static ChromeDriver browser;
    static ApiClient api;

    @BeforeAll
    static void start() throws Exception {
        service = TriadService.start(new TriadService.Options(HOSPITAL, List.of("sim:1@20", "dry:1,state=Morning,delay=150,fail=pick*4"), null,
                dir.resolve("db"), null, "127.0.0.1", 0, Map.of(AccessTokens.SUBMIT_ENV, SUBMIT, AccessTokens.OPERATOR_ENV, OPERATOR)));
        api = new ApiClient(service.url(), OPERATOR);
        api.post("/api/robots/dry-1/offline", "");
        browser = HeadlessChromium.start(dir.resolve("chromium-profile"));
        Files.createDirectories(PICTURES);
    }

    @AfterAll
    static void stop() {
        if (browser != null) {
            browser.quit();
        }
        if (service != null) {
            service.close();
        }
    }

    private static WebDriverWait waitUpTo(int seconds) {
        // rows and requests are re-rendered on every live event: an element found a moment ago may be gone
        WebDriverWait wait = new WebDriverWait(browser, Duration.ofSeconds(seconds), Duration.ofMillis(100));
        wait.ignoring(StaleElementReferenceException.class);
        return wait;
    }

    private static void screenshot(String name) throws Exception {
        Files.write(PICTURES.resolve(name), browser.getScreenshotAs(OutputType.BYTES));
    }

    @Test
    void staffSubmitAndFollowATaskWhileTheOperatorWatchesTheRobotOnTheMap() throws Exception {
        browser.get(service.url() + "/#token=" + SUBMIT);
        waitUpTo(20).until(d -> d.findElements(By.cssSelector("#task-select option")).size() == 8);
        new Select(browser.findElement(By.id("task-select"))).selectByValue("CollectAndDeliver");
        new Select(browser.findElement(By.id("arg-i"))).selectByValue("syringe");
        new Select(browser.findElement(By.id("arg-from"))).selectByValue("storage");
        new Select(browser.findElement(By.id("arg-to"))).selectByValue("ward3");
        browser.findElement(By.id("submit")).click();
        WebElement row = waitUpTo(10).until(d -> d.findElements(By.cssSelector("#tasks tr[data-task-id]")).stream()
                .filter(r -> r.getText().contains("CollectAndDeliver(syringe, storage, ward3)")).findFirst().orElse(null));
        String id = row.getAttribute("data-task-id");
        waitUpTo(20).until(d -> d.findElement(By.cssSelector("#tasks tr[data-task-id='" + id + "'] .state")).getText().equals("running"));

        // meanwhile on the operator page: the courier with its task, its plan, and a floor map being drawn
        String staffTab = browser.getWindowHandle();
        browser.switchTo().newWindow(org.openqa.selenium.WindowType.TAB);
        browser.get(service.url() + "/operator.html#token=" + OPERATOR);
        waitUpTo(20).until(d -> d.findElement(By.cssSelector("[data-robot='sim-1'] .robot-task")).getText().contains("CollectAndDeliver"));
        waitUpTo(10).until(d -> !d.findElements(By.cssSelector("[data-robot='sim-1'] .plan li")).isEmpty());
        long painted = waitUpTo(10).until(d -> {
            Object n = browser.executeScript("const c = document.querySelector(\"[data-robot='sim-1'] canvas\");"
                    + "const p = c.getContext('2d').getImageData(0, 0, c.width, c.height).data; let n = 0;"
                    + "for (let i = 0; i < p.length; i += 4) { if (p[i] === 28 && p[i + 1] === 95 && p[i + 2] === 184) n++; } return n;");
            return ((Number) n).longValue() > 20 ? (Long) ((Number) n).longValue() : null;
        });
        assertTrue(painted > 20, "the robot's blue disc is on the map");
        screenshot("operator-page-running.png");

        browser.switchTo().window(staffTab);
        waitUpTo(90).until(d -> d.findElement(By.cssSelector("#tasks tr[data-task-id='" + id + "'] .state")).getText().equals("completed"));
        browser.findElement(By.cssSelector("#tasks tr[data-task-id='" + id + "'] a")).click();
        waitUpTo(10).until(d -> d.findElement(By.id("detail-events")).getText().contains("task CollectAndDeliver(syringe, storage, ward3) completed"));
        assertTrue(browser.findElement(By.id("detail-events")).getText().contains("Courier.pick(syringe, storage) succeeded"));
        screenshot("staff-page-completed.png");
    }

    @Test
    void anAbortArrivesOnTheOperatorPageWithItsCauseAndTheOperatorRetriesIt() throws Exception {
        api.post("/api/robots/sim-1/offline", "");
        api.post("/api/robots/dry-1/online", "");
        try {
            browser.get(service.url() + "/operator.html#token=" + OPERATOR);
            waitUpTo(20).until(d -> d.findElement(By.id("connection")).getText().equals("live"));
            long id = new ObjectMapper().readTree(api.post("/api/tasks",
                    "{\"task\": \"Fetch\", \"args\": {\"i\": \"bandage\", \"from\": \"storage\", \"to\": \"xray\"}}")).get("id").asLong();
            waitUpTo(30).until(d -> d.findElements(By.cssSelector("#requests li[data-task-id='" + id + "']")).stream().findFirst().orElse(null));
            String cause = waitUpTo(10).until(d -> d.findElement(By.cssSelector("#requests li[data-task-id='" + id + "'] .cause")).getText());
            assertTrue(cause.startsWith("goal Holds(bandage): "), cause);
            assertTrue(cause.contains("injected failure"), cause);
            screenshot("operator-page-request.png");

            waitUpTo(10).until(d -> {
                d.findElement(By.cssSelector("#requests li[data-task-id='" + id + "'] .retry")).click();
                return true;
            });
            waitUpTo(30).until(d -> d.findElements(By.cssSelector("#requests li[data-task-id='" + id + "']")).isEmpty());
            waitUpTo(30).until(d -> {
                try {
                    return api.get("/api/tasks/" + id).contains("\"state\":\"completed\"");
                } catch (Exception e) {
                    return false;
                }
            });
            assertTrue(api.get("/api/tasks/" + id).contains("retried by the operator on dry-1"));
            assertEquals("None open.", browser.findElement(By.id("no-requests")).getText());
            // the audit log on the page names who retried (issue 25)
            waitUpTo(20).until(d -> d.findElement(By.id("audit")).getText().contains("retry"));
            assertTrue(browser.findElement(By.id("audit")).getText().contains("operator-token (operator) retry task " + id),
                    browser.findElement(By.id("audit")).getText());
            // one session per role: following the staff link does not turn the operator page into a staff one
            browser.get(service.url() + "/#token=" + SUBMIT);
            browser.get(service.url() + "/operator.html");
            assertEquals(OPERATOR, browser.executeScript("return localStorage.getItem('triad-token-operator')"));
            assertEquals(SUBMIT, browser.executeScript("return localStorage.getItem('triad-token-staff')"));
        } finally {
            api.post("/api/robots/dry-1/offline", "");
            api.post("/api/robots/sim-1/online", "");
        }
    }
}
