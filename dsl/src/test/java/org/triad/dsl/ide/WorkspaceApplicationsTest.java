package org.triad.dsl.ide;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An editor opened on a folder that holds two applications (as the repository root holds the
 * hospital and the logistics models): each model is checked within its own application, like
 * {@code triad check DIR} checks the models below one folder, so the two robots, worlds and
 * same-named goals do not clash, and one application's names do not resolve in the other.
 */
class WorkspaceApplicationsTest {
	@TempDir
	Path workspace;

	@Test
	void eachApplicationFolderIsCheckedOnItsOwn() throws Exception {
		Path shop = Files.createDirectories(workspace.resolve("shop"));
		try (Stream<Path> files = Files.list(Path.of("src", "test", "resources", "rules", "_base"))) {
			for (Path f : files.toList()) {
				Files.copy(f, shop.resolve(f.getFileName()));
			}
		}
		Path farm = Files.createDirectories(workspace.resolve("farm"));
		Files.writeString(farm.resolve("Farm.cd"), "classdiagram Farm {\n  class Field;\n}\n");
		Files.writeString(farm.resolve("Tractor.actor"), "domain Farm;\n\nrobot Tractor {\n  property Field at();\n}\n");
		Files.writeString(farm.resolve("Weather.actor"), "domain Farm;\n\nworld Weather {\n  property boolean dry(Field f);\n}\n");
		Files.writeString(farm.resolve("At.goal"), "domain Farm;\n\ngoal At(Field f) {\n  Tractor.at() == f && Bot.handEmpty()\n}\n");

		try (LspSession lsp = new LspSession(workspace, new ClientCapabilities())) {
			String farmGoal = LspSession.uri(farm.resolve("At.goal"));
			List<Diagnostic> farmGoalDiagnostics = lsp.client.awaitCode(farmGoal, "link.unknown-actor");
			assertEquals(List.of("link.unknown-actor"), codes(farmGoalDiagnostics), "the shop's robot is not the farm's");
			for (Path quiet : List.of(shop.resolve("Bot.actor"), shop.resolve("World.actor"), shop.resolve("At.goal"), farm.resolve("Tractor.actor"),
					farm.resolve("Weather.actor"))) {
				assertEquals(List.of(), codes(lsp.client.awaitPublished(LspSession.uri(quiet))), quiet.toString());
			}
		}
	}

	private static List<String> codes(List<Diagnostic> diagnostics) {
		return diagnostics.stream().map(d -> d.getCode().getLeft()).toList();
	}
}
