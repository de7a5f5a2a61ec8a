package eu.brain.iot.bis.impl.repo;

/** What reading a URL gave: new bytes (with what identifies them for the next conditional read), or no change. */
public sealed interface Fetch {

    /** The content has not changed since the validators given. */
    record Unchanged() implements Fetch {
    }

    /**
     * New content.
     *
     * @param etag HTTP ETag, or null
     * @param lastModified HTTP Last-Modified, or null
     * @param mtime a file's modification time in milliseconds, or 0
     */
    record Content(byte[] bytes, String etag, String lastModified, long mtime) implements Fetch {
        Validators validators() {
            return new Validators(etag, lastModified, mtime);
        }
    }

    /** What a conditional read sends: the ETag / Last-Modified of HTTP, the modification time of a file. */
    record Validators(String etag, String lastModified, long mtime) {
        static final Validators NONE = new Validators(null, null, 0);
    }
}
