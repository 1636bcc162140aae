package org.triad.cli;

import java.nio.file.Path;

import org.triad.runtime.app.State;

import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** The options of commands that work on an application against one of its situations. */
final class SituationOptions {
	@Parameters(index = "0", paramLabel = "DIR", description = "the application's folder")
	Path dir;

	@Option(names = "--state", required = true, paramLabel = "S.state|NAME", description = "a .state file of the application, or a situation's name")
	String state;

	@Option(names = "--situation", paramLabel = "NAME", description = "which situation of the .state file (default: its first)")
	String situation;

	/** The application, checked, and the chosen situation. */
	record Opened(ModelSession session, State state) {
	}

	Opened open() {
		ModelSession session = ModelSession.open(dir);
		return new Opened(session, session.situation(state, situation));
	}
}
