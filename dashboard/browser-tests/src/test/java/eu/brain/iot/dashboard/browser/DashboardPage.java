package eu.brain.iot.dashboard.browser;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.openqa.selenium.OutputType;
import org.openqa.selenium.chrome.ChromeDriver;

/** The dashboard as the browser shows it: what the page drew where, its DOM, its connection; and screenshots. */
final class DashboardPage {

    static final Path SCREENSHOTS = Path.of(System.getProperty("dashboard.screenshots", "target/screenshots"));

    private final ChromeDriver driver;

    DashboardPage(ChromeDriver driver) {
        this.driver = driver;
    }

    void open(java.net.URI url) {
        driver.get(url.toString());
    }

    /** The robots as last drawn: {id, x, y, heading, state, detect, cart, status}. */
    @SuppressWarnings("unchecked")
    List<Map<String, Object>> robots() {
        Object r = driver.executeScript("return window.dashboard ? window.dashboard.scene().robots : [];");
        return (List<Map<String, Object>>) r;
    }

    @SuppressWarnings("unchecked")
    List<Map<String, Object>> doors() {
        return (List<Map<String, Object>>) driver.executeScript(
                "return window.dashboard ? window.dashboard.scene().doors : [];");
    }

    Optional<Map<String, Object>> robot(String id) {
        return robots().stream().filter(r -> id.equals(r.get("id"))).findFirst();
    }

    Optional<Map<String, Object>> door(String id) {
        return doors().stream().filter(r -> id.equals(r.get("id"))).findFirst();
    }

    /** A counter as the page shows it, or -1 before it is shown. */
    long counter(String name) {
        // read in one script: the page redraws its elements, so an element found by one call may be gone by the next
        Object text = driver.executeScript("const e = document.getElementById(arguments[0]);"
                + " return e ? e.textContent : null;", "counter-" + name);
        if (text == null || text.toString().isBlank()) {
            return -1;
        }
        return Long.parseLong(text.toString().trim());
    }

    /** {@code live}, {@code connecting} or {@code reconnecting}. */
    String connection() {
        return (String) driver.executeScript("const e = document.getElementById('connection');"
                + " return e ? e.getAttribute('data-state') : null;");
    }

    String eventId() {
        return (String) driver.executeScript("return window.dashboard ? window.dashboard.model.eventId : null;");
    }

    /** The status a device's row in the device table shows, or empty. */
    Optional<String> rowStatus(String device) {
        Object status = driver.executeScript("const r = Array.from(document.querySelectorAll('#devices tr'))"
                + ".find(r => r.getAttribute('data-device') === arguments[0]);"
                + " return r ? r.getAttribute('data-status') : null;", device);
        return Optional.ofNullable((String) status);
    }

    /** The outcomes of the decisions in the log, newest first (read in one script, as the counters). */
    @SuppressWarnings("unchecked")
    List<String> decisionOutcomes() {
        return (List<String>) driver.executeScript("return Array.from(document.querySelectorAll("
                + "'#decisions tbody tr')).map(r => r.getAttribute('data-outcome'));");
    }

    Object script(String js) {
        return driver.executeScript(js);
    }

    Path screenshot(String name) throws IOException {
        Files.createDirectories(SCREENSHOTS);
        Path file = SCREENSHOTS.resolve(name + ".png");
        Files.write(file, driver.getScreenshotAs(OutputType.BYTES));
        return file;
    }
}
