package eu.brain.iot.federation.impl;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.time.temporal.TemporalAccessor;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.module.SimpleModule;
import com.fasterxml.jackson.databind.ser.std.ToStringSerializer;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;

/**
 * The fabric's wire format, JSON through Jackson. Events travel in the form untyped behaviours get them (a map of
 * fields; nested data objects as maps, arrays and collections as lists); {@code java.time} values as their ISO-8601
 * text, which the receiving bus converts back for a typed behaviour (OSGi Converter), byte arrays as Base64.
 * <p>
 * A batch of events of {@value Compression#MIN_BYTES} bytes or more travels deflated ({@link Compression}).
 * <p>
 * Thread-safe: Jackson's mapper is, and {@link Compression} keeps its state under locks.
 */
final class Wire {

    /** Most events accepted in one message; a bigger batch is refused as malformed. */
    static final int MAX_BATCH_EVENTS = 10_000;

    private final ObjectMapper mapper = new ObjectMapper().registerModule(new SimpleModule("fabric-wire")
            .addSerializer(TemporalAccessor.class, ToStringSerializer.instance))
            .configure(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES, false); // newer nodes may say more
    private final Compression compression = new Compression();

    /** One event as its publisher keeps it (journal) and sends it: {"seq","type","types","data"}. */
    byte[] event(long seq, String type, List<String> types, Map<String, Object> data) {
        Map<String, Object> e = new LinkedHashMap<>();
        e.put("seq", seq);
        e.put("type", type);
        e.put("types", types);
        e.put("data", data);
        return write(e);
    }

    /** A batch of events already encoded by {@link #event}; deflated when large. */
    byte[] batch(String from, String to, String epoch, long sent, List<byte[]> events) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(64 + events.size() * 256);
        out.writeBytes(("{\"from\":" + quote(from) + ",\"to\":" + quote(to) + ",\"epoch\":" + quote(epoch)
                + ",\"sent\":" + sent + ",\"events\":[").getBytes(StandardCharsets.UTF_8));
        for (int i = 0; i < events.size(); i++) {
            if (i > 0) {
                out.write(',');
            }
            out.writeBytes(events.get(i));
        }
        out.writeBytes("]}".getBytes(StandardCharsets.UTF_8));
        return compression.deflateIfLarge(out.toByteArray());
    }

    /** A received batch. */
    record Batch(String from, String to, String epoch, long sent, List<Event> events) {
    }

    /** A received event. */
    record Event(long seq, String type, List<String> types, Map<String, Object> data) {
    }

    /**
     * Reads a batch in one pass of the parser, straight into the maps behaviours get (no tree in between: a batch's
     * parse is most of what the inbound thread does for an event).
     */
    Batch readBatch(byte[] payload) throws MalformedException {
        BatchIn in;
        try {
            in = mapper.readValue(compression.inflateIfDeflated(payload), BatchIn.class);
        } catch (IOException e) {
            throw new MalformedException("not a batch: " + e.getMessage());
        }
        if (in == null || in.events() == null || in.events().size() > MAX_BATCH_EVENTS) {
            throw new MalformedException("a batch needs an 'events' array of at most " + MAX_BATCH_EVENTS);
        }
        List<Event> list = new ArrayList<>(in.events().size());
        for (EventIn e : in.events()) {
            list.add(checked(e));
        }
        return new Batch(required(in.from(), "from"), required(in.to(), "to"), required(in.epoch(), "epoch"),
                requiredNumber(in.sent(), "sent"), list);
    }

    /** One event as {@link #event} wrote it (an outbox's journal keeps them so). */
    Event readEvent(byte[] json) throws MalformedException {
        EventIn e;
        try {
            e = mapper.readValue(json, EventIn.class);
        } catch (IOException x) {
            throw new MalformedException("not an event: " + x.getMessage());
        }
        return checked(e);
    }

    private static Event checked(EventIn e) throws MalformedException {
        if (e == null || e.seq() == null || e.type() == null || e.type().isEmpty() || e.data() == null) {
            throw new MalformedException("an event needs 'seq', 'type' and an object 'data'");
        }
        List<String> types = e.types() == null ? new ArrayList<>() : new ArrayList<>(e.types());
        types.removeIf(Objects::isNull);
        return new Event(e.seq(), e.type(), types, e.data());
    }

    /** A batch as the parser reads it, before its checks. */
    private record BatchIn(String from, String to, String epoch, Long sent, List<EventIn> events) {
    }

    /** An event as the parser reads it, before its checks. */
    private record EventIn(Long seq, String type, List<String> types, Map<String, Object> data) {
    }

    private static String required(String value, String field) throws MalformedException {
        if (value == null || value.isEmpty()) {
            throw new MalformedException("field '" + field + "' (text) is missing");
        }
        return value;
    }

    private static long requiredNumber(Long value, String field) throws MalformedException {
        if (value == null) {
            throw new MalformedException("field '" + field + "' (number) is missing");
        }
        return value;
    }

    /** An acknowledgement: the receiver {@code from} took every event of {@code epoch} up to {@code through}. */
    record Ack(String from, String to, String epoch, long through, long sent) {
    }

    byte[] ack(Ack ack) {
        return write(ack);
    }

    Ack readAck(byte[] payload) throws MalformedException {
        JsonNode root = tree(payload);
        return new Ack(text(root, "from"), text(root, "to"), text(root, "epoch"), number(root, "through"),
                number(root, "sent"));
    }

    /** What a node's behaviours consume, retained under its interest topic. */
    record Interest(String node, long sent, List<InterestEntry> entries) {
    }

    byte[] interest(Interest interest) {
        return write(interest);
    }

    Interest readInterest(byte[] payload) throws MalformedException {
        JsonNode root = tree(payload);
        List<InterestEntry> entries = new ArrayList<>();
        for (JsonNode e : root.path("entries")) {
            List<String> types = new ArrayList<>();
            e.path("types").forEach(t -> types.add(t.asText()));
            if (types.isEmpty()) {
                throw new MalformedException("an interest entry needs 'types'");
            }
            String filter = e.path("filter").asText("");
            entries.add(new InterestEntry(types, filter.isEmpty() ? null : filter));
        }
        return new Interest(text(root, "node"), number(root, "sent"), entries);
    }

    /**
     * A node's presence, retained under its status topic; the broker publishes the offline one as Last Will.
     * {@code since} names the connection it is about (the time it began): the online status and the Last Will of one
     * connection share it, so a receiver applies a status only when it is about the newest connection it knows (a
     * broker restarted with its sessions may publish the Last Will of a connection that was replaced already).
     */
    record Status(String node, String state, long sent, long since) {
        static final String ONLINE = "online";
        static final String OFFLINE = "offline";
    }

    byte[] status(Status status) {
        return write(status);
    }

    Status readStatus(byte[] payload) throws MalformedException {
        JsonNode root = tree(payload);
        return new Status(text(root, "node"), text(root, "state"), number(root, "sent"),
                root.path("since").asLong(0));
    }

    /**
     * A message about installing a behaviour, for node {@code to} from node {@code from} (see {@link FabricInstaller}):
     * {@code op} is {@link #BID} (which candidates do you offer for {@code types}, and what is your load?),
     * {@link #OFFER} (the answer: {@code candidates}, {@code load}), {@link #ORDER} (install {@code request}) or
     * {@link #RESULT} ({@code ok} and {@code installed}, or {@code problem} and {@code message}). {@code id} pairs an
     * answer with its question. A bid names the {@code devices} the event names, and an offer says which of them
     * the node {@code owns}; both may be missing (a node that does not say owns none).
     */
    record Install(String op, String from, String to, long sent, String id, List<String> types,
            List<BehaviourCandidate> candidates, int load, InstallRequest request, boolean ok, String problem,
            String message, InstalledBehaviour installed, List<String> devices, List<String> owns) {
        static final String BID = "bid";
        static final String OFFER = "offer";
        static final String ORDER = "order";
        static final String RESULT = "result";
    }

    byte[] install(Install message) {
        return write(message);
    }

    Install readInstall(byte[] payload) throws MalformedException {
        JsonNode root = tree(payload);
        String op = text(root, "op");
        text(root, "from");
        text(root, "to");
        text(root, "id");
        number(root, "sent");
        if (!List.of(Install.BID, Install.OFFER, Install.ORDER, Install.RESULT).contains(op)) {
            throw new MalformedException("unknown install message '" + op + "'");
        }
        if (Install.ORDER.equals(op) && !root.path("request").isObject()) {
            throw new MalformedException("an install order needs a 'request'");
        }
        try {
            return mapper.treeToValue(root, Install.class);
        } catch (JsonProcessingException | IllegalArgumentException e) {
            throw new MalformedException("not an install message: " + e.getMessage());
        }
    }

    private JsonNode tree(byte[] payload) throws MalformedException {
        try {
            JsonNode root = mapper.readTree(payload);
            if (root == null || !root.isObject()) {
                throw new MalformedException("a JSON object is expected");
            }
            return root;
        } catch (IOException e) {
            throw new MalformedException("not JSON: " + e.getMessage());
        }
    }

    private static String text(JsonNode root, String field) throws MalformedException {
        JsonNode n = root.path(field);
        if (!n.isTextual() || n.asText().isEmpty()) {
            throw new MalformedException("field '" + field + "' (text) is missing");
        }
        return n.asText();
    }

    private static long number(JsonNode root, String field) throws MalformedException {
        JsonNode n = root.path(field);
        if (!n.canConvertToLong()) {
            throw new MalformedException("field '" + field + "' (number) is missing");
        }
        return n.asLong();
    }

    private String quote(String s) {
        try {
            return mapper.writeValueAsString(s);
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException(e);
        }
    }

    private byte[] write(Object value) {
        try {
            return mapper.writeValueAsBytes(value);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException("an event field cannot be written as JSON: " + e.getOriginalMessage(),
                    e);
        }
    }

    /** A message that is not in the wire format. */
    static final class MalformedException extends Exception {
        private static final long serialVersionUID = 1L;

        MalformedException(String message) {
            super(message);
        }
    }
}
