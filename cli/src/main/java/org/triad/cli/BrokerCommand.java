package org.triad.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;

import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.security.BrokerCredentials;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code triad broker}: a secured Mosquitto broker for VDA 5050 robots (TLS, certificates, passwords, ACL). */
@Command(name = "broker", mixinStandardHelpOptions = true,
		description = { "Start an Eclipse Mosquitto MQTT broker (Debian package mosquitto) on 127.0.0.1 for VDA 5050 robots, until",
				"stopped (Ctrl-C), with persistence on (QoS 1 messages and sessions survive a restart). Secured by default: TLS,",
				"a client certificate and a password per identity, and an access control list (master control sends orders and",
				"instant actions; each robot publishes only its own connection/state/visualization/factsheet and reads only its",
				"own order/instantActions); anonymous clients are refused. The credentials (a CA, the server's and every client's",
				"certificate and password) are made once into --credentials DIR and kept; naming more robots adds theirs.",
				"Exit code 2 if mosquitto is not installed or cannot listen." })
public final class BrokerCommand implements Callable<Integer> {
	/** Where the credentials go unless --credentials names a folder. */
	static final Path DEFAULT_CREDENTIALS = Path.of(".triad", "broker-credentials");

	@Option(names = "--port", paramLabel = "PORT", description = "the port on 127.0.0.1 (default: a free one)")
	private Integer port;

	@Option(names = "--dir", paramLabel = "DIR", description = "config, persistence and log (default: target/mosquitto-PORT)")
	private Path dir;

	@Option(names = "--credentials", paramLabel = "DIR", description = "the credentials folder (default: " + ".triad/broker-credentials)")
	private Path credentials;

	@Option(names = "--robots", paramLabel = "SERIAL", split = ",",
			description = "the robots' serial numbers that get an identity (default: courier-1,courier-2,courier-3)")
	private List<String> robots = List.of("courier-1", "courier-2", "courier-3");

	@Option(names = "--plain-tcp", description = "no TLS, no passwords, no ACL: anyone on this machine may command the robots (tests only)")
	private boolean plainTcp;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		PrintWriter out = spec.commandLine().getOut();
		int p = port != null ? port : MosquittoBroker.freePort();
		Path d = dir != null ? dir : Path.of("target", "mosquitto-" + p);
		MosquittoBroker broker;
		BrokerCredentials c = null;
		try {
			if (plainTcp) {
				spec.commandLine().getErr().println("triad broker: warning: --plain-tcp: no encryption, no authentication, no access control;"
						+ " any program on this machine may command the robots");
				spec.commandLine().getErr().flush();
				broker = MosquittoBroker.start(d, p);
			} else {
				c = BrokerCredentials.ensure(credentials != null ? credentials : DEFAULT_CREDENTIALS, MasterControl.TRIAD, robots);
				broker = MosquittoBroker.startSecured(d, p, c);
			}
		} catch (IllegalArgumentException | IllegalStateException | java.io.UncheckedIOException e) {
			throw new ModelSession.UserError(e.getMessage());
		}
		out.println("broker " + broker.url() + " (Mosquitto; config, persistence and log in " + broker.dir() + "); Ctrl-C stops it");
		String creds = "";
		if (c != null) {
			out.println("  credentials in " + c.dir() + (c.made().isEmpty() ? " (existing)" : " (made now: " + String.join(", ", c.made()) + ")")
					+ " for " + String.join(", ", c.identities()));
			creds = " --credentials " + c.dir();
		}
		out.println("  robots: ./triad robot --broker " + broker.url() + creds + " [--count N]");
		out.println("  tasks:  ./triad run models/hospital/src/main/models --state Morning.state --task \"GoTo(ward3)\" --robots vda5050:"
				+ broker.url() + creds);
		out.flush();
		CountDownLatch stopped = new CountDownLatch(1);
		MosquittoBroker b = broker;
		Runtime.getRuntime().addShutdownHook(new Thread(() -> {
			b.close();
			stopped.countDown();
		}, "broker-shutdown"));
		try {
			stopped.await();
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
		}
		return 0;
	}
}
