package org.triad.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;

import org.triad.service.ServiceError;
import org.triad.service.TriadService;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code triad serve DIR [--robots sim:3 ...] [--port P] [--db FILE]}: the application as a service for a fleet. */
@Command(name = "serve", mixinStandardHelpOptions = true,
		description = { "Run the application as a service: a task API derived from its task models (OpenAPI at /api/openapi.json),",
				"a persistent task queue, dispatch to a fleet of robots (one RefArc each), a staff page (/) and an operator page",
				"(/operator.html). Stops on Ctrl-C; tasks that were running are re-planned at the next start.",
				"Exit code: 2 when it cannot start (models, robots, database, port)." })
public final class ServeCommand implements Callable<Integer> {
	@Parameters(index = "0", paramLabel = "DIR", description = "the application's folder (e.g. models/hospital)")
	private Path dir;

	@Option(names = "--robots", paramLabel = "SCHEME:ARG", split = "\\s+",
			description = { "the fleet, repeatable: sim:N[@SPEED|@max] (the application's simulated robots, if it has them),",
					"dry:N[,state=S][,delay=MS][,fail=ACTION*K][,gone=K] (any application),",
					"vda5050:tcp://HOST:PORT[,wait=S] (the hospital couriers ONLINE on that broker), or a binding's scheme;",
					"default: sim:1 if the application has simulated robots, else dry:1" })
	private List<String> robots = List.of();

	@Option(names = "--state", paramLabel = "S.state|NAME", description = "the situation dry-run robots start in (default: the application's first)")
	private String situation;

	@Option(names = "--port", paramLabel = "P", description = "the port (default 8080; 0 picks a free one)")
	private int port = 8080;

	@Option(names = "--host", paramLabel = "ADDRESS", description = "the address to listen on (default 127.0.0.1: this machine only)")
	private String host = "127.0.0.1";

	@Option(names = "--db", paramLabel = "FILE|URL", description = { "the task database: a file (default DIR/" + TriadService.DEFAULT_DB + ".db, SQLite),",
			"or postgresql://USER:PASSWORD@HOST:PORT/DB, which several instances can share (one dispatches, the others take over)" })
	private String db;

	@Option(names = "--recover", description = "copy every readable row of a damaged database file into a new one (the damaged file is kept), then start")
	private boolean recover;

	@Option(names = "--config", paramLabel = "FILE",
			description = "a properties file with submit-token= and operator-token= (else $TRIAD_SUBMIT_TOKEN/$TRIAD_OPERATOR_TOKEN, else generated once)")
	private Path config;

	@CommandLine.Mixin
	private MqttCredentialsOption credentials = new MqttCredentialsOption();

	@Option(names = "--https-keystore", paramLabel = "FILE.p12",
			description = "serve HTTPS only, with this PKCS#12 certificate and key (password: --https-password-file or $TRIAD_HTTPS_PASSWORD)")
	private Path httpsKeyStore;

	@Option(names = "--https-password-file", paramLabel = "FILE", description = "a file whose first line is the key store's password")
	private Path httpsPasswordFile;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() throws InterruptedException {
		PrintWriter out = spec.commandLine().getOut();
		PrintWriter err = spec.commandLine().getErr();
		// the application's own robots (e.g. the hospital's simulated couriers) are plug-ins on its class path
		if (Files.isDirectory(dir.resolve("src/main/models"))) {
			new ApplicationLauncher(dir).classLoader(ServeCommand.class.getClassLoader())
					.ifPresent(loader -> Thread.currentThread().setContextClassLoader(loader));
		}
		credentials.apply();
		for (String r : robots) {
			MqttCredentialsOption.warnIfPlain("serve", r.substring(r.indexOf(':') + 1), err);
		}
		if (port < 0 || port > 65535) {
			err.println("triad serve: --port takes 0 to 65535, not " + port);
			return 2;
		}
		Path models = Files.isDirectory(dir.resolve("src/main/models")) ? dir.resolve("src/main/models") : dir;
		TriadService service;
		String database = db != null ? db : dir.resolve(TriadService.DEFAULT_DB).toString();
		try {
			if (recover && org.triad.service.store.Database.of(database).shared()) {
				err.println("triad serve: --recover salvages the embedded database file; a PostgreSQL server has its own tools (pg_amcheck, pg_dump)");
				return 2;
			}
			if (recover) {
				out.println("triad serve: " + org.triad.service.store.Migrations.salvage(Path.of(database)));
				out.flush();
			}
			service = TriadService.start(new TriadService.Options(models, robots, situation, database, config, host, port, environment()));
		} catch (ServiceError | java.io.UncheckedIOException e) {
			err.println("triad serve: " + e.getMessage());
			boolean made = org.triad.service.store.Database.of(database).shared() || Files.exists(Path.of(database))
					|| Files.exists(Path.of(database + ".db")) || Files.exists(Path.of(database + ".mv.db"));
			if (made) {
				// the database was made (tokens included) before the start failed: how to get in, whatever it holds
				err.println("  access, whatever this start left: ./triad users " + dir + (db != null ? " --db " + db : "")
						+ " add NAME --role staff|operator|admin (a named user's token), or list");
			}
			return 2;
		}
		CountDownLatch stopped = new CountDownLatch(1);
		Runtime.getRuntime().addShutdownHook(new Thread(() -> {
			service.close();
			stopped.countDown();
		}, "triad-serve-shutdown"));
		String url = service.url();
		out.println("triad serve: " + service.application() + " at " + url + "/ with robots "
				+ String.join(", ", service.fleet().robots().stream().map(r -> r.name()).toList()) + "; tasks in " + service.database());
		if (service.tokens().generated()) {
			out.println("  new access tokens (kept in the database; set " + "TRIAD_SUBMIT_TOKEN/TRIAD_OPERATOR_TOKEN or --config to choose your own):");
			out.println("  staff page:    " + url + "/#token=" + service.tokens().submitToken());
			out.println("  operator page: " + url + "/operator.html#token=" + service.tokens().operatorToken());
		} else {
			out.println("  staff page:    " + url + "/   operator page: " + url + "/operator.html   (tokens as configured, or a named"
					+ " user's: ./triad users " + dir + " add NAME --role operator, while the service is stopped)");
		}
		out.println("  API: " + url + "/api/openapi.json; Ctrl-C stops");
		out.flush();
		stopped.await();
		return 0;
	}

	/** The environment, with the HTTPS options in the variables the service reads. */
	private java.util.Map<String, String> environment() {
		java.util.Map<String, String> env = new java.util.HashMap<>(System.getenv());
		if (httpsKeyStore != null) {
			env.put("TRIAD_HTTPS_KEYSTORE", httpsKeyStore.toString());
		}
		if (httpsPasswordFile != null) {
			try {
				env.put("TRIAD_HTTPS_PASSWORD", Files.readAllLines(httpsPasswordFile).stream().findFirst().orElse("").strip());
			} catch (java.io.IOException e) {
				throw new java.io.UncheckedIOException("cannot read the HTTPS password file " + httpsPasswordFile + ": " + e.getMessage(), e);
			}
		}
		return env;
	}
}
