package eu.brain.iot.bis.impl.install;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.impl.repo.BehaviourResource;
import eu.brain.iot.bis.impl.repo.Errors;
import eu.brain.iot.bis.impl.repo.Transfer;
import eu.brain.iot.bis.impl.repo.UrlReader;

/**
 * Downloads the bundles an install needs into files of a folder (the installer's data area), each read up to the
 * size its index states (or {@code maxBytes} when it states none), within the reader's deadline, and checked against
 * the index's size and SHA-256 before anything is installed from it. Never holds a bundle in memory.
 * <p>
 * Threads: {@link #fetch} runs on the installer's download threads, several at once (one per install); the transfers
 * under way are in a concurrent map, read by anyone asking what the installer is doing.
 */
final class Downloads {

    private final UrlReader reader;
    private final Path folder;
    private final long maxBytes;
    private final Map<Transfer, String> current = new ConcurrentHashMap<>();

    Downloads(UrlReader reader, Path folder, long maxBytes) {
        this.reader = reader;
        this.folder = folder;
        this.maxBytes = maxBytes;
    }

    /** The key of a verified file: the same URL with the same hash is the same bundle. */
    static String key(BehaviourResource r) {
        return r.url() + "#" + r.sha256();
    }

    /**
     * Downloads and verifies each resource into a file, adding it to {@code files} under {@link #key}; a failure
     * throws before the next one starts (the files already there are the caller's to delete).
     */
    void fetch(BehaviourResource behaviour, List<BehaviourResource> resources, Map<String, Path> files)
            throws InstallException, InterruptedException {
        for (BehaviourResource r : resources) {
            files.put(key(r), fetch(behaviour, r));
        }
    }

    private Path fetch(BehaviourResource behaviour, BehaviourResource r) throws InstallException,
            InterruptedException {
        long limit = r.size() >= 0 ? r.size() : maxBytes;
        Transfer transfer = new Transfer(r.url(), r.size());
        current.put(transfer, "downloading " + r + (r == behaviour ? "" : " for " + behaviour) + " from ");
        UrlReader.Downloaded file;
        try {
            Files.createDirectories(folder);
            Path target = Files.createTempFile(folder, r.symbolicName() + "-", ".jar");
            file = reader.download(r.url(), target, limit, transfer);
        } catch (UrlReader.TooLong e) {
            if (r.size() < 0) {
                throw new InstallException(Problem.DOWNLOAD_FAILED, "cannot download " + r + needed(behaviour, r) + ": "
                        + withUrl(e.getMessage(), r) + " (bundle.max.bytes). Nothing was installed", e);
            }
            throw new InstallException(Problem.HASH_MISMATCH, r + " from " + r.url() + " does not match its index "
                    + r.repository() + needed(behaviour, r) + ": " + withUrl(e.getMessage(), r) + ", the index says "
                    + r.size() + " bytes of SHA-256 " + r.sha256() + ". Nothing was installed. The file was changed"
                    + " after the index was made: restore the file, or rebuild and re-sign the index if the change is"
                    + " wanted", e);
        } catch (IOException e) {
            throw new InstallException(Problem.DOWNLOAD_FAILED, "cannot download " + r + needed(behaviour, r) + ": "
                    + withUrl(Errors.describe(e), r) + ". Nothing was installed; check that the repository "
                    + r.repository() + " is reachable and holds the file (of " + (r.size() >= 0 ? r.size() + " bytes,"
                            + " as its index says" : "at most " + maxBytes + " bytes, bundle.max.bytes")
                    + "), then try again", e);
        } finally {
            current.remove(transfer);
        }
        if (!file.sha256().equalsIgnoreCase(r.sha256()) || r.size() >= 0 && r.size() != file.size()) {
            delete(file.file());
            throw new InstallException(Problem.HASH_MISMATCH, r + " from " + r.url() + " does not match its index "
                    + r.repository() + needed(behaviour, r) + ": SHA-256 " + file.sha256() + " (" + file.size()
                    + " bytes), the index says " + r.sha256() + " (" + r.size() + " bytes). Nothing was installed."
                    + " The file was changed after the index was made: restore the file, or rebuild and re-sign the"
                    + " index if the change is wanted");
        }
        return file.file();
    }

    /** What is being downloaded now: one line per transfer, with its URL and progress. */
    List<String> activities() {
        List<String> lines = new ArrayList<>();
        current.forEach((transfer, what) -> lines.add(what + transfer.describe()));
        return lines;
    }

    static void delete(Path file) {
        try {
            Files.deleteIfExists(file);
        } catch (IOException e) {
            // in the framework's data area, which a node wipes at its next start
        }
    }

    private static String withUrl(String problem, BehaviourResource r) {
        return problem.contains(r.url().toString()) ? problem : r.url() + ": " + problem;
    }

    private static String needed(BehaviourResource behaviour, BehaviourResource r) {
        return r == behaviour ? "" : " (needed by " + behaviour + ")";
    }
}
