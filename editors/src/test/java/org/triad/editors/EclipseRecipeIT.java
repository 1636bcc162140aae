package org.triad.editors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.jar.Manifest;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import javax.xml.parsers.DocumentBuilderFactory;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.InitializedParams;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.TriadLanguages;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * The Eclipse recipe in editors/eclipse: its drop-in bundle is well-formed and declares a text
 * content type, opened in the Generic Editor, for each model language; and its launch
 * configuration's command, with Eclipse's variables expanded the way Eclipse expands them,
 * starts the packaged language server, which answers initialize and checks a model.
 */
class EclipseRecipeIT {
	private static final Path ECLIPSE = Path.of(System.getProperty("triad.editors", ".")).resolve("eclipse");

	@TempDir
	Path home;

	@TempDir
	Path workspace;

	private static Document xml(Path file) throws Exception {
		try (InputStream in = Files.newInputStream(file)) {
			return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(in);
		}
	}

	@Test
	void bundleDeclaresATextContentTypePerModelLanguageOpenedInTheGenericEditor() throws Exception {
		Path bundle = ECLIPSE.resolve("org.triad.editors.eclipse");
		Manifest manifest;
		try (InputStream in = Files.newInputStream(bundle.resolve("META-INF/MANIFEST.MF"))) {
			manifest = new Manifest(in);
		}
		assertEquals("org.triad.editors.eclipse;singleton:=true", manifest.getMainAttributes().getValue("Bundle-SymbolicName"));
		assertEquals("2", manifest.getMainAttributes().getValue("Bundle-ManifestVersion"));

		Document plugin = xml(bundle.resolve("plugin.xml"));
		NodeList types = plugin.getElementsByTagName("content-type");
		Set<String> extensions = new LinkedHashSet<>();
		Set<String> ids = new LinkedHashSet<>();
		for (int i = 0; i < types.getLength(); i++) {
			Element t = (Element) types.item(i);
			assertEquals("org.eclipse.core.runtime.text", t.getAttribute("base-type"), "LSP4E needs text content types");
			extensions.add(t.getAttribute("file-extensions"));
			ids.add(t.getAttribute("id"));
		}
		assertEquals(Set.copyOf(TriadLanguages.EXTENSIONS), extensions);
		NodeList bindings = plugin.getElementsByTagName("editorContentTypeBinding");
		Set<String> bound = new LinkedHashSet<>();
		for (int i = 0; i < bindings.getLength(); i++) {
			Element b = (Element) bindings.item(i);
			assertEquals("org.eclipse.ui.genericeditor.GenericEditor", b.getAttribute("editorId"));
			bound.add(b.getAttribute("contentTypeId"));
		}
		assertEquals(ids, bound);
	}

	@Test
	void launchConfigurationStartsTheServerWhichAnswersInitializeAndChecksModels() throws Exception {
		Document launch = xml(ECLIPSE.resolve("Triad Language Server.launch"));
		assertEquals("org.eclipse.ui.externaltools.ProgramLaunchConfigurationType", launch.getDocumentElement().getAttribute("type"));
		String location = attribute(launch, "org.eclipse.ui.externaltools.ATTR_LOCATION");
		String arguments = attribute(launch, "org.eclipse.ui.externaltools.ATTR_TOOL_ARGUMENTS");

		// the recipe's install step: the packaged jar in ~/.triad
		Files.createDirectories(home.resolve(".triad"));
		Files.copy(Path.of(System.getProperty("triad.serverJar")), home.resolve(".triad/triad-language-server.jar"));
		List<String> command = new ArrayList<>();
		command.add(expand(location));
		command.addAll(split(expand(arguments)));

		Files.writeString(workspace.resolve("Shop.cd"), "classdiagram Shop {\n  class Place;\n}\n");
		Files.writeString(workspace.resolve("Bot.actor"), "domain Shop;\n\nrobot Bot {\n  property Plcae loc();\n}\n");

		Process process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.DISCARD).start();
		try (LspProcessClient client = new LspProcessClient(process)) {
			InitializeParams init = new InitializeParams();
			init.setProcessId((int) ProcessHandle.current().pid());
			init.setRootUri(workspace.toUri().toString());
			init.setCapabilities(new ClientCapabilities());
			InitializeResult result = client.server().initialize(init).get(60, TimeUnit.SECONDS);
			assertNotNull(result.getCapabilities().getHoverProvider());
			assertTrue(result.getCapabilities().getCodeActionProvider().getLeft(), "quick fixes are offered");
			client.server().initialized(new InitializedParams());
			assertEquals("link.unknown-type", client.awaitFirstCode("Bot.actor"));
			client.server().shutdown().get(60, TimeUnit.SECONDS);
			client.server().exit();
			assertTrue(process.waitFor(30, TimeUnit.SECONDS), "the server ends on 'exit'");
		} finally {
			process.destroyForcibly();
		}
	}

	private static String attribute(Document launch, String key) {
		NodeList attributes = launch.getElementsByTagName("stringAttribute");
		for (int i = 0; i < attributes.getLength(); i++) {
			Element a = (Element) attributes.item(i);
			if (a.getAttribute("key").equals(key)) {
				return a.getAttribute("value");
			}
		}
		throw new AssertionError("no " + key + " in the launch configuration");
	}

	/** Eclipse's ${system_property:X} and ${env_var:X}, with the recipe's home folder as user.home. */
	private String expand(String value) {
		Matcher m = Pattern.compile("\\$\\{(system_property|env_var):([^}]+)}").matcher(value);
		StringBuilder b = new StringBuilder();
		while (m.find()) {
			String name = m.group(2);
			String v = m.group(1).equals("env_var") ? System.getenv(name) : name.equals("user.home") ? home.toString() : System.getProperty(name);
			assertNotNull(v, "Eclipse would not know " + m.group());
			m.appendReplacement(b, Matcher.quoteReplacement(v));
		}
		m.appendTail(b);
		assertTrue(!b.toString().contains("${"), "unexpanded variable in " + b);
		return b.toString();
	}

	/** Splits arguments as Eclipse does: on spaces, double quotes group. */
	private static List<String> split(String arguments) {
		List<String> result = new ArrayList<>();
		Matcher m = Pattern.compile("\"([^\"]*)\"|(\\S+)").matcher(arguments);
		while (m.find()) {
			result.add(m.group(1) != null ? m.group(1) : m.group(2));
		}
		return result;
	}
}
