package org.triad.cli;

import java.io.PrintWriter;
import java.nio.file.Path;

import org.triad.vda5050.security.ClientCredentials;

import picocli.CommandLine.Option;

/**
 * {@code --credentials DIR}: the folder {@code ./triad broker} made, for commands that connect to a VDA 5050
 * broker (robot, run, serve). Without it the environment variable {@code TRIAD_MQTT_CREDENTIALS} names the
 * folder. A plain {@code tcp://} broker is accepted only as asked for, with a warning.
 */
final class MqttCredentialsOption {
	@Option(names = "--credentials", paramLabel = "DIR",
			description = "the broker credentials ./triad broker made, for an ssl:// broker (else $TRIAD_MQTT_CREDENTIALS)")
	Path credentials;

	/** Makes the folder the one every MQTT connection of this process (and of the applications it starts) uses. */
	void apply() {
		if (credentials != null) {
			System.setProperty(ClientCredentials.PROPERTY, credentials.toAbsolutePath().toString());
		}
	}

	/** One warning line when {@code broker} is plain TCP. */
	static void warnIfPlain(String command, String broker, PrintWriter err) {
		if (broker != null && broker.startsWith("tcp://")) {
			err.println("triad " + command + ": warning: " + broker + " is plain TCP: unencrypted, and the broker decides alone who may"
					+ " command the robots; use the ssl:// address and --credentials of ./triad broker");
			err.flush();
		}
	}
}
