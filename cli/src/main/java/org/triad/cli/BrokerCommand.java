package org.triad.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;

import org.triad.vda5050.broker.MosquittoBroker;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code triad broker}: a Mosquitto broker for VDA 5050 robots, configured from the repository's config file. */
@Command(name = "broker", mixinStandardHelpOptions = true,
		description = { "Start an Eclipse Mosquitto MQTT broker (Debian package mosquitto) on 127.0.0.1 for VDA 5050 robots, with",
				"persistence on (QoS 1 messages and sessions survive a restart), until stopped (Ctrl-C). Prints its address.",
				"Exit code 2 if mosquitto is not installed or cannot listen." })
public final class BrokerCommand implements Callable<Integer> {
	@Option(names = "--port", paramLabel = "PORT", description = "the port on 127.0.0.1 (default: a free one)")
	private Integer port;

	@Option(names = "--dir", paramLabel = "DIR", description = "config, persistence and log (default: target/mosquitto-PORT)")
	private Path dir;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		PrintWriter out = spec.commandLine().getOut();
		int p = port != null ? port : MosquittoBroker.freePort();
		Path d = dir != null ? dir : Path.of("target", "mosquitto-" + p);
		MosquittoBroker broker;
		try {
			broker = MosquittoBroker.start(d, p);
		} catch (IllegalArgumentException | IllegalStateException | java.io.UncheckedIOException e) {
			throw new ModelSession.UserError(e.getMessage());
		}
		out.println("broker " + broker.url() + " (Mosquitto; config, persistence and log in " + broker.dir() + "); Ctrl-C stops it");
		out.println("  robots: ./triad robot --broker " + broker.url() + " [--count N]");
		out.println("  tasks:  ./triad run models/hospital/src/main/models --state Morning.state --task \"GoTo(ward3)\" --robots vda5050:"
				+ broker.url());
		out.flush();
		CountDownLatch stopped = new CountDownLatch(1);
		Runtime.getRuntime().addShutdownHook(new Thread(() -> {
			broker.close();
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
