package org.triad.dsl.formatting2;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.formatting2.FormatterRequest;
import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.formatting2.regionaccess.TextRegionAccessBuilder;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.StringInputStream;
import org.junit.jupiter.api.Test;
import org.triad.dsl.RobustnessTest;
import org.triad.dsl.TriadLanguages;

import com.google.inject.Injector;

/**
 * Formatting (an editor may ask for it at any time) never fails and never changes meaning: for
 * seeded mutations of the example models, formatting a model that parses gives a model that parses
 * to the same tokens, and formatting it again changes nothing; formatting a broken model that has
 * a root element does not throw.
 */
class FormatterRobustnessTest {
	static final int CASES = 400;

	static XtextResource parse(Injector injector, String extension, String text) throws IOException {
		XtextResourceSet resourceSet = injector.getInstance(XtextResourceSet.class);
		XtextResource resource = (XtextResource) resourceSet.createResource(URI.createURI("memory:/Model." + extension));
		resource.load(new StringInputStream(text, StandardCharsets.UTF_8.name()), null);
		return resource;
	}

	static String format(Injector injector, XtextResource resource) {
		FormatterRequest request = injector.getInstance(FormatterRequest.class);
		request.setTextRegionAccess(injector.getInstance(TextRegionAccessBuilder.class).forNodeModel(resource).create());
		return request.getTextRegionAccess().getRewriter().renderToString(injector.getInstance(IFormatter2.class).format(request));
	}

	static List<String> tokens(String text) {
		List<String> result = new ArrayList<>();
		java.util.regex.Matcher m = java.util.regex.Pattern.compile("\"[^\"\\n]*\"|//[^\\n]*|/\\*.*?\\*/|\\w+|\\S", java.util.regex.Pattern.DOTALL)
				.matcher(text);
		while (m.find()) {
			result.add(m.group());
		}
		return result;
	}

	@Test
	void formattingMutatedModelsKeepsTheirMeaning() throws IOException {
		List<RobustnessTest.Model> corpus = RobustnessTest.corpus();
		Random random = new Random(RobustnessTest.SEED + 1);
		List<String> problems = new ArrayList<>();
		int parsedCleanly = 0;
		for (int i = 0; i < CASES; i++) {
			RobustnessTest.Case c = RobustnessTest.generate(i, random, corpus);
			if (c.extension().equals("arc")) {
				continue; // the architecture language has no formatter
			}
			String text = new String(c.content(), StandardCharsets.UTF_8);
			Injector injector = TriadLanguages.setup().get(c.extension());
			try {
				XtextResource resource = parse(injector, c.extension(), text);
				if (resource.getContents().isEmpty()) {
					continue; // nothing to format: the editors' formatting service returns no edit (see LanguageServerTest)
				}
				String formatted = format(injector, resource);
				if (resource.getParseResult().hasSyntaxErrors()) {
					continue; // only: no exception
				}
				parsedCleanly++;
				XtextResource again = parse(injector, c.extension(), formatted);
				if (again.getParseResult().hasSyntaxErrors() || !tokens(formatted).equals(tokens(text))) {
					problems.add(c.description() + ": formatting changed the model:\n" + text + "\n---\n" + formatted);
				} else if (!format(injector, again).equals(formatted)) {
					problems.add(c.description() + ": formatting is not idempotent:\n" + formatted);
				}
			} catch (RuntimeException e) {
				problems.add(c.description() + ": " + e);
			}
		}
		assertEquals("", String.join("\n\n", problems.stream().limit(5).toList()), problems.size() + " problems");
		// the mutations must leave enough valid models for the meaning check to mean something
		org.junit.jupiter.api.Assertions.assertTrue(parsedCleanly > CASES / 20, "models that parsed: " + parsedCleanly);
	}
}
