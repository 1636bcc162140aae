package org.triad.dsl.ide.server;

import org.eclipse.xtext.ide.server.ServerLauncher;

/**
 * The Triad language server on standard input and output: what {@code triad lsp} runs and what
 * the self-contained editor jar (editors/) starts with {@code java -jar}.
 */
public final class TriadLanguageServerMain {
	private TriadLanguageServerMain() {
	}

	public static void main(String[] args) {
		TriadServerLauncher.main(args);
	}
}
