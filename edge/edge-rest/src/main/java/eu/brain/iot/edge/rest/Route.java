package eu.brain.iot.edge.rest;

/**
 * A request path under {@code /sensinact}, parsed: which kind of thing it names and the ids in it. Knows which
 * methods each kind accepts, so that a known path with the wrong method answers 405 and an unknown one 404.
 *
 * @param kind     what the path names
 * @param path     the full path, for messages
 * @param provider the provider id, or {@code null}
 * @param service  the service name, or {@code null}
 * @param resource the resource (or action) name, or {@code null}
 */
record Route(Kind kind, String path, String provider, String service, String resource) {

    static final String ROOT = "/sensinact";

    enum Kind {
        INDEX, PROVIDERS, PROVIDER, SERVICES, SERVICE, RESOURCES, RESOURCE, ACT
    }

    /** The paths that exist, for the index and for 404 messages. */
    static final String SHAPES = "/sensinact/providers, /sensinact/providers/{p}, /sensinact/providers/{p}/services, "
            + "/sensinact/providers/{p}/services/{s}, /sensinact/providers/{p}/services/{s}/resources, "
            + "/sensinact/providers/{p}/services/{s}/resources/{r}, POST .../resources/{action}/act, "
            + "/sensinact/subscribe?provider=&service=, POST|DELETE /sensinact/session";

    /**
     * @param pathInfo the servlet's path info (after {@code /sensinact}), already URL-decoded; may be {@code null}
     * @throws HttpError 404 when the path has no meaning here
     */
    static Route parse(String pathInfo) {
        String rest = pathInfo == null ? "" : pathInfo;
        String path = ROOT + rest;
        if (rest.endsWith("/") && rest.length() > 1) {
            rest = rest.substring(0, rest.length() - 1); // a trailing slash names the same thing
        }
        if (rest.isEmpty() || rest.equals("/")) {
            return new Route(Kind.INDEX, path, null, null, null);
        }
        String[] s = rest.substring(1).split("/", -1);
        for (String segment : s) {
            if (segment.isEmpty()) {
                throw unknown(path);
            }
        }
        boolean ok = s[0].equals("providers") && (s.length < 3 || s[2].equals("services"))
                && (s.length < 5 || s[4].equals("resources")) && (s.length < 7 || s[6].equals("act"))
                && s.length <= 7;
        if (!ok) {
            throw unknown(path);
        }
        Kind kind = switch (s.length) {
            case 1 -> Kind.PROVIDERS;
            case 2 -> Kind.PROVIDER;
            case 3 -> Kind.SERVICES;
            case 4 -> Kind.SERVICE;
            case 5 -> Kind.RESOURCES;
            case 6 -> Kind.RESOURCE;
            default -> Kind.ACT;
        };
        return new Route(kind, path, s.length > 1 ? s[1] : null, s.length > 3 ? s[3] : null,
                s.length > 5 ? s[5] : null);
    }

    private static HttpError unknown(String path) {
        return HttpError.notFound("no such path: " + Echo.cut(path) + "; paths: " + SHAPES);
    }

    /** @throws HttpError 405 when this kind of path does not take the method */
    void checkMethod(String method) {
        boolean read = method.equals("GET") || method.equals("HEAD");
        if (kind == Kind.ACT && !method.equals("POST")) {
            throw HttpError.methodNotAllowed(method, Echo.cut(path), "POST",
                    "ACT: POST a JSON object of the action's parameters, e.g. {\"x\":9,\"y\":7} for goTo");
        }
        if (kind != Kind.ACT && !read) {
            throw HttpError.methodNotAllowed(method, Echo.cut(path), "GET", kind == Kind.RESOURCE
                    ? "to run an action, POST to " + path + "/act" : "this is a read-only view of the device model");
        }
    }
}
