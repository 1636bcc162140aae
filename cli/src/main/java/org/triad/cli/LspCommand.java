package org.triad.cli;

import java.util.concurrent.Callable;

import org.triad.dsl.ide.server.TriadServerLauncher;

import picocli.CommandLine.Command;

/** {@code triad lsp}: the language server for editors (Eclipse LSP4E, VS Code, Neovim, ...). */
@Command(name = "lsp", mixinStandardHelpOptions = true,
		description = { "Run the Triad language server on standard input and output (Language Server Protocol).",
				"Editors get diagnostics, completion, hover, quick fixes, signature help, semantic tokens, symbols, rename, go-to-definition and formatting for all Triad languages." })
public final class LspCommand implements Callable<Integer> {
	@Override
	public Integer call() {
		TriadServerLauncher.main(new String[0]);
		return 0;
	}
}
