package eu.brain.iot.dashboard;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.util.Map;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletName;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletPattern;

import jakarta.servlet.Filter;
import jakarta.servlet.Servlet;
import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * The page itself: the bundle's {@code /web} folder under {@code /dashboard/} ({@code /dashboard/} is
 * {@code index.html}; {@code /dashboard} redirects there). A path that is not a file of the page gets a JSON 404;
 * nothing but GET and HEAD is accepted.
 */
@Component(service = Servlet.class)
@HttpWhiteboardServletName("eu.brain.iot.dashboard.page")
@HttpWhiteboardServletPattern({ "/dashboard", "/dashboard/*" })
public final class PageServlet extends HttpServlet {
    private static final long serialVersionUID = 1L;
    private static final Map<String, String> TYPES = Map.of("html", "text/html", "js", "text/javascript",
            "css", "text/css", "svg", "image/svg+xml", "png", "image/png", "json", "application/json");

    /** The page starts behind its gate ({@link Gate}): the files are read from this bundle's class loader. */
    @Activate
    public PageServlet(@Reference(target = Gate.TARGET) Filter gate) {
        // the reference only orders the start
    }

    @Override
    protected void service(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        if (!req.getMethod().equals("GET") && !req.getMethod().equals("HEAD")) {
            resp.setHeader("Allow", "GET, HEAD");
            Json.error(resp, 405, req.getMethod() + " is not allowed on " + Json.echo(req.getRequestURI())
                    + "; the page is read-only: use GET");
            return;
        }
        String path = req.getPathInfo();
        if (path == null) {
            resp.sendRedirect(req.getContextPath() + "/dashboard/");
            return;
        }
        if (path.equals("/")) {
            path = "/index.html";
        }
        String ext = path.substring(path.lastIndexOf('.') + 1);
        URL file = path.contains("..") || !TYPES.containsKey(ext) ? null : PageServlet.class.getResource("/web" + path);
        if (file == null) {
            Json.error(resp, 404, "no " + Json.echo(req.getRequestURI()) + "; the dashboard is at /dashboard/");
            return;
        }
        resp.setStatus(200);
        resp.setContentType(TYPES.get(ext));
        resp.setCharacterEncoding("UTF-8");
        resp.setHeader("Cache-Control", "no-cache"); // a new bundle's page must replace the old one at once
        resp.setHeader("X-Content-Type-Options", "nosniff");
        if (req.getMethod().equals("HEAD")) {
            return;
        }
        try (InputStream in = file.openStream()) {
            in.transferTo(resp.getOutputStream());
        }
    }
}
