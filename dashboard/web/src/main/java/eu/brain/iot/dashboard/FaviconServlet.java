package eu.brain.iot.dashboard;

import java.io.IOException;
import java.io.InputStream;

import org.osgi.service.component.annotations.Component;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletName;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletPattern;

import jakarta.servlet.Servlet;
import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * {@code /favicon.ico}, which browsers and tools ask for at the server's root whatever the page declares: the
 * dashboard's icon (an SVG, which browsers show as an icon whatever the file name), so that a request for it is not a
 * 404 in the browser's console and the server's log. Stateless; container threads.
 */
@Component(service = Servlet.class)
@HttpWhiteboardServletName("eu.brain.iot.dashboard.favicon")
@HttpWhiteboardServletPattern(FaviconServlet.PATH)
public final class FaviconServlet extends HttpServlet {
    private static final long serialVersionUID = 1L;
    static final String PATH = "/favicon.ico";
    static final String ICON = "/web/favicon.svg";
    private static final String TYPE = "image/svg+xml";
    private static final long MAX_AGE_S = 86_400;

    @Override
    protected void service(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        if (!req.getMethod().equals("GET") && !req.getMethod().equals("HEAD")) {
            resp.setHeader("Allow", "GET, HEAD");
            Json.error(resp, 405, req.getMethod() + " is not allowed on " + PATH + "; use GET");
            return;
        }
        resp.setStatus(200);
        resp.setContentType(TYPE);
        resp.setHeader("Cache-Control", "max-age=" + MAX_AGE_S);
        resp.setHeader("X-Content-Type-Options", "nosniff");
        if (req.getMethod().equals("HEAD")) {
            return;
        }
        try (InputStream in = FaviconServlet.class.getResourceAsStream(ICON)) {
            in.transferTo(resp.getOutputStream());
        }
    }
}
