package eu.brain.iot.dashboard.browser;

import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import org.openqa.selenium.By;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.chrome.ChromeDriver;
import org.awaitility.core.ConditionFactory;
import org.awaitility.core.ConditionTimeoutException;

/**
 * Saves a screenshot of a running node's live dashboard, once the page has loaded its snapshot, follows the stream
 * and has drawn it: for a person to look at what a run showed (the scenario calls it through
 * {@code dashboard/screenshot.sh}). Headless Chromium with the browser tests' set-up ({@link Chromium}).
 * <p>
 * {@code Screenshot URL OUT.png [--token-file FILE] [--timeout-s N]}: with a token file (a node exposed beyond
 * loopback) it logs in through the page's form, as a person does, the token never in a URL. Exit 0 with the file
 * written; 1 when the page did not get live within the timeout (a screenshot of what it showed is written anyway,
 * for a person to see why); 2 for wrong arguments; 3 when Chromium is not installed.
 * <p>
 * Threads: the main thread alone.
 */
public final class Screenshot {

    /** Selenium's warnings (no DevTools binding for this Chromium's version: none is used) are noise here. */
    private static final java.util.logging.Logger SELENIUM = java.util.logging.Logger.getLogger("org.openqa.selenium");

    private Screenshot() {
    }

    public static void main(String[] args) throws Exception {
        int status;
        try {
            status = run(args);
        } catch (Usage e) {
            if (e.getMessage() != null) {
                System.err.println("screenshot: " + e.getMessage());
            }
            System.err.println("usage: dashboard/screenshot.sh URL OUT.png [--token-file FILE] [--timeout-s N]\n"
                    + "  e.g. dashboard/screenshot.sh http://127.0.0.1:8181/dashboard/ target/run/dashboard-1.png");
            status = e.status;
        }
        System.exit(status);
    }

    /** The exit status (see above); a test calls it without exiting. */
    static int run(String[] args) throws Exception {
        SELENIUM.setLevel(java.util.logging.Level.SEVERE);
        List<String> positional = new ArrayList<>();
        Path tokenFile = null;
        long timeoutS = 60;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
            case "--token-file" -> tokenFile = Path.of(value(args, ++i, "--token-file"));
            case "--timeout-s" -> timeoutS = seconds(value(args, ++i, "--timeout-s"));
            case "-h", "--help" -> throw new Usage(null, 0);
            default -> positional.add(args[i]);
            }
        }
        if (positional.size() != 2) {
            throw new Usage("expected a URL and a file to write, found " + positional, 2);
        }
        URI url = URI.create(positional.get(0));
        Path out = Path.of(positional.get(1)).toAbsolutePath();
        if (!Files.isExecutable(Chromium.BROWSER) || !Files.isExecutable(Chromium.DRIVER)) {
            System.err.println("screenshot: needs Debian's chromium and chromium-driver (" + Chromium.BROWSER + ", "
                    + Chromium.DRIVER + "): apt-get install -y chromium chromium-driver");
            return 3;
        }
        Path profile = Files.createTempDirectory("dashboard-screenshot");
        ChromeDriver driver = Chromium.start(profile);
        int status;
        try {
            status = shoot(driver, url, out, tokenFile, Duration.ofSeconds(timeoutS));
        } finally {
            driver.quit();
            try (var files = Files.walk(profile)) {
                files.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
        return status;
    }

    private static int shoot(ChromeDriver driver, URI url, Path out, Path tokenFile, Duration timeout)
            throws Exception {
        DashboardPage page = new DashboardPage(driver);
        page.open(url);
        ConditionFactory wait = org.awaitility.Awaitility.await().atMost(timeout).pollInterval(Duration.ofMillis(200))
                .ignoreExceptions();
        String state;
        try {
            wait.until(() -> List.of("live", "login").contains(connection(page)));
            if ("login".equals(connection(page))) {
                if (tokenFile == null) {
                    return written(driver, out, "the node requires its API token: give --token-file", 1);
                }
                driver.findElement(By.id("login-token")).sendKeys(Files.readString(tokenFile).strip());
                driver.findElement(By.cssSelector("#login button")).click();
            }
            // live, with a snapshot applied, then two animation frames: what the page drew is on the screen
            wait.until(() -> "live".equals(connection(page)) && page.eventId() != null);
            driver.executeAsyncScript("const done = arguments[arguments.length - 1];"
                    + "requestAnimationFrame(() => requestAnimationFrame(() => done(true)));");
            state = "live at event " + page.eventId() + ", " + page.robots().size() + " robots drawn";
        } catch (ConditionTimeoutException e) {
            return written(driver, out, "the page did not get live within " + timeout.toSeconds() + " s (it shows '"
                    + connection(page) + "')", 1);
        }
        return written(driver, out, state, 0);
    }

    private static String connection(DashboardPage page) {
        try {
            return page.connection();
        } catch (org.openqa.selenium.WebDriverException e) {
            return "not loaded";
        }
    }

    private static int written(ChromeDriver driver, Path out, String state, int status) throws Exception {
        if (out.getParent() != null) {
            Files.createDirectories(out.getParent());
        }
        Files.write(out, driver.getScreenshotAs(OutputType.BYTES));
        System.out.println("screenshot: " + out + " (" + state + ")");
        return status;
    }

    private static String value(String[] args, int i, String option) {
        if (i >= args.length) {
            throw new Usage(option + " needs a value", 2);
        }
        return args[i];
    }

    private static long seconds(String text) {
        try {
            return Long.parseLong(text.strip());
        } catch (NumberFormatException e) {
            throw new Usage("--timeout-s takes a number of seconds, found '" + text + "'", 2);
        }
    }

    /** Wrong arguments: a message (or none, for --help) and the exit status. */
    private static final class Usage extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final int status;

        Usage(String message, int status) {
            super(message, null, false, false);
            this.status = status;
        }
    }
}
