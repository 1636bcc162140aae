package org.triad.dsl.rules;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.Grammar;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.IGrammarAccess;
import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider.ILinkingDiagnosticContext;
import org.junit.jupiter.api.Test;
import org.triad.dsl.TriadLanguages;
import org.triad.dsl.validation.ActorIssueCodes;
import org.triad.dsl.validation.CdIssueCodes;
import org.triad.dsl.validation.CommonIssueCodes;
import org.triad.dsl.validation.GoalIssueCodes;
import org.triad.dsl.validation.StateIssueCodes;
import org.triad.dsl.validation.TaskIssueCodes;

/** Every diagnostic code in the registries is unique and proven by a bad and a good rule case. */
class IssueCodeRegistryTest {
	static final List<Class<?>> REGISTRIES = List.of(CommonIssueCodes.class, CdIssueCodes.class, ActorIssueCodes.class,
			GoalIssueCodes.class, TaskIssueCodes.class, StateIssueCodes.class);

	/** Registries whose codes are proven by bad and good models elsewhere, with where. */
	static final Map<Class<?>, String> TESTED_ELSEWHERE = Map.of(org.triad.dsl.validation.ArcIssueCodes.class,
			"org.triad.dsl.arc.ArcValidationTest",
			// a bad case is a file over 2 MiB, written by the test rather than kept in the repository
			org.triad.dsl.validation.FileIssueCodes.class, "org.triad.dsl.app.ModelFileSizeTest");

	/**
	 * Codes no model can produce, with the reason. The linker's fallback code is unreachable as
	 * long as every cross-reference has its own code, which {@link #everyCrossReferenceHasItsOwnCode()} checks.
	 */
	static final Map<String, String> UNREACHABLE = Map.of(CommonIssueCodes.UNKNOWN_NAME,
			"fallback for a cross-reference without its own code; there is none");

	static Map<String, String> codes() throws IllegalAccessException {
		Map<String, String> byCode = new TreeMap<>();
		for (Class<?> registry : REGISTRIES) {
			for (Field f : registry.getFields()) {
				int m = f.getModifiers();
				if (Modifier.isStatic(m) && Modifier.isFinal(m) && f.getType() == String.class) {
					String code = (String) f.get(null);
					String previous = byCode.put(code, registry.getSimpleName() + "." + f.getName());
					assertEquals(null, previous, "code " + code + " is defined twice: " + previous + " and " + registry.getSimpleName() + "."
							+ f.getName());
				}
			}
		}
		return byCode;
	}

	@Test
	void registryListIsComplete() throws IOException {
		Path validation = Path.of("target", "classes", "org", "triad", "dsl", "validation");
		try (Stream<Path> files = Files.list(validation)) {
			Set<String> found = files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith("IssueCodes.class"))
					.map(n -> n.substring(0, n.length() - ".class".length())).collect(Collectors.toCollection(TreeSet::new));
			Set<String> listed = REGISTRIES.stream().map(Class::getSimpleName).collect(Collectors.toCollection(TreeSet::new));
			TESTED_ELSEWHERE.keySet().forEach(r -> listed.add(r.getSimpleName()));
			assertEquals(found, listed);
		}
	}

	@Test
	void everyCodeHasABadAndAGoodCase() throws Exception {
		Map<String, String> codes = codes();
		assertTrue(codes.size() >= 40, "registries were read: " + codes.keySet());
		List<RuleCase> cases = RuleCase.all();
		List<String> problems = new ArrayList<>();
		for (String code : codes.keySet()) {
			if (UNREACHABLE.containsKey(code)) {
				continue;
			}
			boolean bad = false;
			for (RuleCase c : cases) {
				if (c.code().equals(code) && c.isBad() && c.expectations().stream().anyMatch(e -> e.code().equals(code))) {
					bad = true;
				}
			}
			boolean good = cases.stream().anyMatch(c -> c.code().equals(code) && c.name().startsWith("good"));
			if (!bad) {
				problems.add(code + " (" + codes.get(code) + ") has no bad case in rules/" + code + "/bad*");
			}
			if (!good) {
				problems.add(code + " (" + codes.get(code) + ") has no good case in rules/" + code + "/good*");
			}
		}
		for (RuleCase c : cases) {
			if (!codes.containsKey(c.code())) {
				problems.add("rules/" + c.code() + " is not a code of any registry");
			}
			if (!c.isBad() && !c.name().startsWith("good")) {
				problems.add("rules/" + c + " is neither bad* nor good*");
			}
		}
		assertEquals("", String.join("\n", problems));
	}

	/** Registries tested elsewhere: each of their codes is asserted (as {@code Registry.FIELD}) in the named test class. */
	@Test
	void everyCodeTestedElsewhereIsAsserted() throws Exception {
		List<String> problems = new ArrayList<>();
		for (Map.Entry<Class<?>, String> e : TESTED_ELSEWHERE.entrySet()) {
			Path test = Path.of("src", "test", "java", e.getValue().replace('.', '/') + ".java");
			String text = Files.readString(test);
			for (Field f : e.getKey().getFields()) {
				String ref = e.getKey().getSimpleName() + "." + f.getName();
				if (f.getType() == String.class && !text.contains(ref)) {
					problems.add(ref + " (" + f.get(null) + ") is not asserted in " + test);
				}
			}
		}
		assertEquals("", String.join("\n", problems));
	}

	@Test
	void everyCrossReferenceHasItsOwnCode() throws Exception {
		Set<String> linkCodes = codes().keySet().stream().filter(c -> c.startsWith("link.")).collect(Collectors.toSet());
		for (Class<?> registry : TESTED_ELSEWHERE.keySet()) {
			for (java.lang.reflect.Field f : registry.getFields()) {
				if (f.getType() == String.class && ((String) f.get(null)).contains(".unknown-")) {
					linkCodes.add((String) f.get(null));
				}
			}
		}
		int checked = 0;
		for (Map.Entry<EReference, ILinkingDiagnosticMessageProvider> entry : grammarCrossReferences().entrySet()) {
			EReference ref = entry.getKey();
			ILinkingDiagnosticMessageProvider provider = entry.getValue();
			EClass owner = concreteOwner(ref);
			EObject context = EcoreUtil.create(owner);
			DiagnosticMessage message = provider.getUnresolvedProxyMessage(new ILinkingDiagnosticContext() {
				@Override
				public EObject getContext() {
					return context;
				}

				@Override
				public EReference getReference() {
					return ref;
				}

				@Override
				public String getLinkText() {
					return "Missing";
				}
			});
			String where = owner.getName() + "." + ref.getName();
			assertNotNull(message, where + " gets no diagnostic when unresolved");
			assertTrue(!message.getIssueCode().equals(CommonIssueCodes.UNKNOWN_NAME)
					&& (linkCodes.contains(message.getIssueCode()) || message.getIssueCode().equals(CommonIssueCodes.UNQUALIFIED_CALL)),
					where + " gets code " + message.getIssueCode());
			checked++;
		}
		assertTrue(checked >= 10, "cross-references checked: " + checked);
	}

	/** The references some grammar of the languages writes as a cross-reference {@code [Type]}. */
	/** Each cross-reference of every language's grammar, with the linking message provider of its language. */
	private static Map<EReference, ILinkingDiagnosticMessageProvider> grammarCrossReferences() {
		Map<EReference, ILinkingDiagnosticMessageProvider> refs = new java.util.LinkedHashMap<>();
		for (com.google.inject.Injector injector : TriadLanguages.setup().values()) {
			ILinkingDiagnosticMessageProvider provider = injector.getInstance(ILinkingDiagnosticMessageProvider.class);
			Grammar grammar = injector.getInstance(IGrammarAccess.class).getGrammar();
			List<Grammar> all = new ArrayList<>(GrammarUtil.allUsedGrammars(grammar));
			all.add(grammar);
			for (Grammar g : all) {
				for (CrossReference cr : EcoreUtil2.getAllContentsOfType(g, CrossReference.class)) {
					refs.putIfAbsent(GrammarUtil.getReference(cr), provider);
				}
			}
		}
		return refs;
	}

	private static EClass concreteOwner(EReference ref) {
		EClass declared = ref.getEContainingClass();
		if (!declared.isAbstract()) {
			return declared;
		}
		for (EClassifier c : declared.getEPackage().getEClassifiers()) {
			if (c instanceof EClass e && !e.isAbstract() && declared.isSuperTypeOf(e)) {
				return e;
			}
		}
		throw new AssertionError("no concrete class has " + ref.getName());
	}
}
