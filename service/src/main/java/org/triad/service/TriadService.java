package org.triad.service;

import java.net.BindException;
import java.nio.file.Path;
import java.time.Clock;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.Set;

import org.triad.building.BuildingContext;
import org.triad.building.traffic.TrafficBoard;
import org.triad.building.SharedWorld;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.fleet.RobotPlatformProvider;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.GoalSolver;
import org.triad.service.store.Database;
import org.triad.service.store.TaskStore;
import org.triad.service.auth.AuditLog;
import org.triad.service.auth.UserStore;

import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A running Triad service: the application's models, the task database, the fleet and the HTTP
 * server, started together and stopped together ({@link #close()}).
 */
public final class TriadService implements AutoCloseable {
    public static final String VERSION = "0.1.0";
    /** The database's default name, in the models folder, to which {@code .db} is added. */
    public static final String DEFAULT_DB = "triad-service";

    /**
     * What to start.
     *
     * @param robots    {@code SCHEME:ARGUMENT} each; empty: the application's own {@code sim:1} if it has one, else {@code dry:1}
     * @param situation the situation dry-run robots start in ({@code null}: the application's first)
     * @param db        the database: a file ({@code null}: {@value #DEFAULT_DB}.db in the models folder) or
     *                  {@code postgresql://USER:PASSWORD@HOST:PORT/DB}
     * @param config    a properties file with {@code submit-token}/{@code operator-token}, or {@code null}
     * @param port      0 for a free port
     */
    public record Options(Path models, List<String> robots, String situation, String db, Path config, String host, int port, Map<String, String> env) {
        public Options {
            robots = List.copyOf(robots);
            env = Map.copyOf(env);
        }

        /** The database as a file path. */
        public Options(Path models, List<String> robots, String situation, Path db, Path config, String host, int port, Map<String, String> env) {
            this(models, robots, situation, db == null ? null : db.toString(), config, host, port, env);
        }
    }

    private final ApplicationModels models;
    private final TaskStore store;
    private final AccessTokens tokens;
    private final FleetService fleet;
    private final HttpApi http;
    private final int port;
    private final String host;
    private final boolean secure;
    private TrafficBoard traffic = new TrafficBoard();

    private TriadService(ApplicationModels models, TaskStore store, AccessTokens tokens, FleetService fleet, HttpApi http, String host, int port,
            boolean secure) {
        this.secure = secure;
        this.models = models;
        this.store = store;
        this.tokens = tokens;
        this.fleet = fleet;
        this.http = http;
        this.host = host;
        this.port = port;
    }

    /**
     * Starts the service.
     *
     * @throws ServiceError a start-up error (bad models, robots, database, port) with a one-line message
     */
    public static TriadService start(Options o) {
        HttpsSettings https = HttpsSettings.from(o.env()); // a certificate that cannot be used stops the start before anything else
        ApplicationModels models = ApplicationModels.load(o.models());
        TaskStore store = TaskStore.open(Database.of(o.db() != null ? o.db() : o.models().resolve(DEFAULT_DB).toString()));
        if (store.notice() != null) {
            System.err.println("triad serve: " + store.notice());
        }
        List<FleetRobot> robots = List.of();
        FleetService fleet = null;
        TrafficBoard traffic = new TrafficBoard(); // the robots' traffic controls show their waits here (operator page)
        org.triad.building.DeviceBoard devices = new org.triad.building.DeviceBoard(); // and the building's doors and lifts
        try {
            AccessTokens tokens = AccessTokens.load(o.env(), o.config(), store);
            FleetRoster roster = new FleetRoster();
            robots = connect(models, o, roster, traffic, devices);
            TaskCatalog catalog = new TaskCatalog(models.schema(), worldObjects(models, robots, o.situation()));
            GoalSolver solver = new GoalSolver(models.schema());
            // robots under traffic control: moves cost their expected wait (congestion), so plans may go round it
            solver = traffic.costs().map(solver::withCosts).orElse(solver);
            fleet = new FleetService(catalog, store, robots, solver, Clock.systemUTC());
            roster.attach(fleet);
            DispatchLimit.of(Thread.currentThread().getContextClassLoader()).ifPresent(fleet::limitAtOnce);
            java.util.Optional<ChargingPolicy> charging = ChargingPolicy.of(Thread.currentThread().getContextClassLoader());
            if (charging.isPresent()) {
                try {
                    fleet.useCharging(charging.get());
                } catch (ServiceError e) {
                    throw ServiceError.startup(ChargingPolicy.RESOURCE + ": charging.task: " + e.getMessage());
                }
            }
            ObjectNode openApi = OpenApiDocument.of(catalog, VERSION);
            HttpApi http = new HttpApi(fleet, tokens, new UserStore(store), new AuditLog(store), openApi, https).showing(traffic).showing(devices);
            int port;
            try {
                port = http.start(o.host(), o.port());
            } catch (RuntimeException e) {
                http.stop();
                throw ServiceError.startup(bindFailure(o, e));
            }
            TriadService service = new TriadService(models, store, tokens, fleet, http, o.host(), port, https != null);
            service.traffic = traffic;
            return service;
        } catch (RuntimeException e) {
            if (fleet != null) {
                fleet.close();
            } else {
                robots.forEach(r -> {
                    try {
                        r.close();
                    } catch (Exception ignored) {
                        // failing start-up: report the first problem, not the clean-up's
                    }
                });
            }
            store.close();
            throw e;
        }
    }

    /** Where the robots' traffic controls show their waits (the operator page's traffic section; benchmarks sample it). */
    public TrafficBoard traffic() {
        return traffic;
    }

    private static String bindFailure(Options o, RuntimeException e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof BindException) {
                return "cannot listen on " + o.host() + ":" + o.port() + " (" + t.getMessage() + "); choose another with --port";
            }
        }
        return "cannot listen on " + o.host() + ":" + o.port() + ": " + e.getMessage();
    }

    /** The robots the options name; providers whose robots run under traffic control show their waits on {@code traffic}. */
    static List<FleetRobot> connect(ApplicationModels models, Options o, FleetRoster roster, TrafficBoard traffic,
            org.triad.building.DeviceBoard devices) {
        AppSchema schema = models.schema();
        List<RobotPlatformProvider> providers = new ArrayList<>();
        ServiceLoader.load(RobotPlatformProvider.class).forEach(providers::add);
        List<String> specs = o.robots();
        if (specs.isEmpty()) {
            boolean ownSim = providers.stream().anyMatch(p -> p.scheme().equals("sim") && p.application().equals(schema.name()));
            specs = List.of(ownSim ? "sim:1" : "dry:1");
        }
        // one building for the whole fleet: its world starts as --situation says if given, else as the first dry spec's
        // state=S or the first robot with a platform reports it, else as the application's first situation
        State start;
        try {
            start = models.situation(o.situation());
        } catch (IllegalArgumentException e) {
            if (o.situation() != null) {
                throw ServiceError.startup("--situation " + o.situation() + ": " + e.getMessage());
            }
            start = State.builder().build(); // no situation in the models: the robots' observations fill the world
        }
        SharedWorld world = new SharedWorld(schema, start);
        roster.building(world);
        if (o.situation() != null) {
            world.startAs(start); // the user named the building's situation: robots join it
        }
        BuildingContext context = new BuildingContext() {
            @Override
            public AppSchema schema() {
                return schema;
            }

            @Override
            public State situation(String name) {
                return models.situation(name != null ? name : o.situation());
            }

            @Override
            public SharedWorld world() {
                return world;
            }

            @Override
            public TrafficBoard traffic() {
                return traffic;
            }

            @Override
            public org.triad.building.DeviceBoard devices() {
                return devices;
            }

            @Override
            public org.triad.refarc.fleet.FleetChanges changes() {
                return roster;
            }
        };
        List<FleetRobot> robots = new ArrayList<>();
        Set<String> names = new HashSet<>();
        try {
            for (String spec : specs) {
                int colon = spec.indexOf(':');
                if (colon < 1) {
                    throw ServiceError.startup("--robots takes SCHEME:ARGUMENT, e.g. sim:3 or dry:2, not '" + spec + "'; " + schemes(providers, schema));
                }
                String scheme = spec.substring(0, colon);
                RobotPlatformProvider provider = providers.stream()
                        .filter(p -> p.scheme().equals(scheme) && (p.application().equals(schema.name()) || p.application().equals(RobotPlatformProvider.ANY_APPLICATION)))
                        .findFirst().orElse(null);
                if (provider == null) {
                    List<String> elsewhere = providers.stream().filter(p -> p.scheme().equals(scheme)).map(RobotPlatformProvider::application).toList();
                    throw ServiceError.startup(elsewhere.isEmpty() ? "unknown robot scheme '" + scheme + "'; " + schemes(providers, schema)
                            : "robots '" + scheme + ":' are for the application " + elsewhere + ", not " + schema.name() + "; " + schemes(providers, schema));
                }
                List<FleetRobot> connected;
                try {
                    connected = provider.connect(spec.substring(colon + 1), context);
                } catch (IllegalArgumentException e) {
                    throw ServiceError.startup("--robots " + spec + ": " + e.getMessage());
                } catch (Exception e) {
                    throw ServiceError.startup("--robots " + spec + ": cannot connect: " + e.getMessage());
                }
                for (FleetRobot connectedRobot : connected) {
                    FleetRobot r = world.observing(connectedRobot);
                    robots.add(r);
                    if (!r.name().matches("[A-Za-z0-9_-]+") || !names.add(r.name())) {
                        throw ServiceError.startup("--robots: robot name '" + r.name() + "' is " + (names.contains(r.name()) ? "used twice" : "not letters, digits, '-' and '_'"));
                    }
                }
            }
        } catch (RuntimeException e) {
            for (FleetRobot r : robots) {
                try {
                    r.close();
                } catch (Exception ignored) {
                    // reporting the start-up error matters more
                }
            }
            throw e;
        }
        return robots;
    }

    private static String schemes(List<RobotPlatformProvider> providers, AppSchema schema) {
        List<String> usable = providers.stream()
                .filter(p -> p.application().equals(schema.name()) || p.application().equals(RobotPlatformProvider.ANY_APPLICATION))
                .map(RobotPlatformProvider::usage).toList();
        return "for " + schema.name() + ": " + String.join(" | ", usable);
    }

    /** The objects the world lists: from the robots' current states, or the models' situation when no robot answers. */
    private static Map<String, DomainObject> worldObjects(ApplicationModels models, List<FleetRobot> robots, String situation) {
        Map<String, DomainObject> objects = new LinkedHashMap<>();
        for (FleetRobot r : robots) {
            try {
                objects.putAll(r.stateSource().currentState().objects());
            } catch (Exception e) {
                // a robot that does not answer now does not list objects; the others do
            }
        }
        if (objects.isEmpty()) {
            try {
                objects.putAll(models.situation(situation).objects());
            } catch (IllegalArgumentException e) {
                throw ServiceError.startup("no robot answers and " + e.getMessage());
            }
        }
        return objects;
    }

    /** The live event stream's clients (tests publish through them as the fleet does). */
    EventStreams events() {
        return http.events();
    }

    public int port() {
        return port;
    }

    /** {@code http://HOST:PORT}, or {@code https://HOST:PORT} when given a certificate */
    public String url() {
        return (secure ? "https" : "http") + "://" + (host.contains(":") ? "[" + host + "]" : host) + ":" + port;
    }

    public AccessTokens tokens() {
        return tokens;
    }

    public FleetService fleet() {
        return fleet;
    }

    /** The database (for the users and audit stores, and tests). */
    public TaskStore store() {
        return store;
    }

    /** The database file, or the server's address without password. */
    public String database() {
        return store.database().shown();
    }

    public String application() {
        return models.schema().name();
    }

    /** Stops the server, the robots and the database; tasks that were running are recovered as interrupted at the next start. */
    @Override
    public void close() {
        http.stop();
        fleet.close();
        store.close();
    }
}
