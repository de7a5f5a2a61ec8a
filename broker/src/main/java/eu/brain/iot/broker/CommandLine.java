package eu.brain.iot.broker;

import java.util.Locale;

/** Reads the broker's flags ({@code --port N} or {@code --port=N}, ...) into {@link BrokerOptions}. */
final class CommandLine {
    static final String USAGE = """
            Usage: java -jar broker.jar [options]     an MQTT 3.1.1 and 5 broker (HiveMQ Community Edition, embedded)
            Options:
              --port N          MQTT port (default 1883)
              --bind ADDR       address to listen on (default 127.0.0.1; 0.0.0.0 for every interface)
              --data DIR        state folder: sessions, queued and retained messages, the generated config.xml
                                (default ~/.local/state/brain-iot/broker)
              --in-memory       keep sessions and queued messages in memory only (lost when the broker stops)
              --max-queued N    messages kept per offline client with a persistent session (default 100000)
              --help            show this help
            It prints 'broker listening on ADDR:PORT ...' once clients can connect, and stops on SIGTERM or Ctrl-C.
            """;

    /** Whether the arguments ask for help (then nothing else is checked). */
    static boolean wantsHelp(String[] args) {
        for (String a : args) {
            if (a.equals("--help") || a.equals("-h")) {
                return true;
            }
        }
        return false;
    }

    private CommandLine() {
    }

    static BrokerOptions parse(String[] args) throws UsageException {
        BrokerOptions options = BrokerOptions.defaults();
        for (int i = 0; i < args.length; i++) {
            String arg = args[i];
            String flag = arg;
            String value = null;
            int eq = arg.indexOf('=');
            if (arg.startsWith("--") && eq > 0) {
                flag = arg.substring(0, eq);
                value = arg.substring(eq + 1);
            }
            switch (flag) {
                case "--in-memory" -> {
                    if (value != null) {
                        throw new UsageException("--in-memory takes no value, found '" + arg + "'");
                    }
                    options = options.withPersistence(BrokerOptions.Persistence.IN_MEMORY);
                }
                case "--port", "--bind", "--data", "--max-queued" -> {
                    if (value == null) {
                        if (i + 1 >= args.length) {
                            throw new UsageException(flag + " needs a value");
                        }
                        value = args[++i];
                    }
                    options = apply(options, flag, value);
                }
                default -> throw new UsageException("unknown argument '" + arg + "'");
            }
        }
        return options;
    }

    private static BrokerOptions apply(BrokerOptions options, String flag, String value) throws UsageException {
        return switch (flag) {
            case "--port" -> options.withPort((int) number(flag, value, 1, 65535));
            case "--bind" -> {
                if (value.isBlank() || !value.matches("[0-9A-Za-z.:\\-\\[\\]]+")) {
                    throw new UsageException("--bind needs an address or host name, found '" + value + "'");
                }
                yield options.withBind(value.toLowerCase(Locale.ROOT));
            }
            case "--data" -> options.withDataDir(BrokerOptions.path(flag, value));
            case "--max-queued" -> options.withMaxQueued(number(flag, value, 1, Long.MAX_VALUE));
            default -> throw new IllegalStateException("unhandled flag " + flag);
        };
    }

    private static long number(String flag, String value, long min, long max) throws UsageException {
        try {
            long n = Long.parseLong(value);
            if (n >= min && n <= max) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new UsageException(flag + " needs a whole number " + min + ".." + max + ", found '" + value + "'");
    }
}
