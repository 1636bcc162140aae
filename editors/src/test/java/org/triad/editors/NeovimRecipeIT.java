package org.triad.editors;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Neovim set-up of editors/README.md, exactly as written there, in the Neovim Debian ships
 * (0.7, which has no vim.lsp.start): headless Neovim opens a broken model, the snippet starts the
 * packaged language server, and the server's diagnostic arrives with its code.
 */
class NeovimRecipeIT {
	private static final Path README = Path.of(System.getProperty("triad.editors", ".")).resolve("README.md");

	@TempDir
	Path home;

	@TempDir
	Path workspace;

	@Test
	void readmeSnippetStartsTheServerAndShowsItsDiagnostics() throws Exception {
		Matcher lua = Pattern.compile("## Neovim.*?```lua\\n(.*?)```", Pattern.DOTALL).matcher(Files.readString(README));
		assertTrue(lua.find(), "a Lua snippet under '## Neovim'");
		Path init = home.resolve("init.lua");
		Files.writeString(init, lua.group(1));
		Files.createDirectories(home.resolve(".triad"));
		Files.copy(Path.of(System.getProperty("triad.serverJar")), home.resolve(".triad/triad-language-server.jar"));

		Files.writeString(workspace.resolve("Shop.cd"), "classdiagram Shop {\n  class Place;\n}\n");
		Files.writeString(workspace.resolve("Near.goal"), "domain Shop;\n\ngoal Near(Plcae p) {\n  true\n}\n");
		Path out = workspace.resolve("diagnostics.txt");
		String report = "lua vim.wait(90000, function() return #vim.diagnostic.get(0) > 0 end, 100);"
				+ " local f = io.open('" + out + "', 'w');"
				+ " for _, d in ipairs(vim.diagnostic.get(0)) do f:write((d.code or '?') .. ' ' .. (d.lnum + 1) .. ' ' .. d.message .. '\\n') end;"
				+ " f:close()";
		ProcessBuilder nvim = new ProcessBuilder("nvim", "--headless", "-n", "-i", "NONE", "-u", init.toString(), "-c", report, "-c", "qa!", "Near.goal")
				.directory(workspace.toFile()).redirectErrorStream(true).redirectOutput(workspace.resolve("nvim.log").toFile());
		nvim.environment().put("HOME", home.toString());
		nvim.environment().put("XDG_CONFIG_HOME", home.resolve("config").toString());
		nvim.environment().put("XDG_DATA_HOME", home.resolve("data").toString());
		nvim.environment().put("XDG_STATE_HOME", home.resolve("state").toString());
		nvim.environment().put("XDG_CACHE_HOME", home.resolve("cache").toString());
		Process p = nvim.start();
		try {
			assertTrue(p.waitFor(120, TimeUnit.SECONDS), "Neovim ended");
		} finally {
			p.destroyForcibly();
			// the server Neovim started ends with Neovim; if not, end it here
			p.descendants().forEach(ProcessHandle::destroyForcibly);
		}
		assertTrue(Files.exists(out), "Neovim wrote no diagnostics: " + Files.readString(workspace.resolve("nvim.log")));
		List<String> lines = Files.readAllLines(out);
		assertTrue(lines.stream().anyMatch(l -> l.startsWith("link.unknown-type 3 unknown type 'Plcae'")), lines.toString());
	}
}
