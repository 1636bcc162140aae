package org.triad.dsl.ide;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.triad.dsl.ide.LspSession.at;
import static org.triad.dsl.ide.LspSession.get;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionContext;
import org.eclipse.lsp4j.CodeActionParams;
import org.eclipse.lsp4j.Command;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.CreateFile;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DidChangeWatchedFilesCapabilities;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesRegistrationOptions;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.DocumentSymbolCapabilities;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.FileChangeType;
import org.eclipse.lsp4j.FileEvent;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.ImplementationParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.Registration;
import org.eclipse.lsp4j.RenameParams;
import org.eclipse.lsp4j.SemanticTokens;
import org.eclipse.lsp4j.SemanticTokensLegend;
import org.eclipse.lsp4j.SemanticTokensParams;
import org.eclipse.lsp4j.SignatureHelp;
import org.eclipse.lsp4j.SignatureHelpParams;
import org.eclipse.lsp4j.SymbolInformation;
import org.eclipse.lsp4j.SymbolKind;
import org.eclipse.lsp4j.TextDocumentClientCapabilities;
import org.eclipse.lsp4j.TextDocumentEdit;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.TypeDefinitionParams;
import org.eclipse.lsp4j.WorkspaceClientCapabilities;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.ide.server.TriadLanguageServer;

/**
 * What a model author's editor gets from the language server beyond diagnostics: hovers, quick
 * fixes, semantic tokens, signature help, document symbols, file watching, type definitions,
 * completion and a rename that refuses clashes. Driven over the protocol like an editor.
 */
class EditorServicesTest {
	@TempDir
	static Path workspace;

	private static LspSession lsp;

	@BeforeAll
	static void start() throws Exception {
		try (Stream<Path> files = Files.list(Path.of("src", "test", "resources", "rules", "_base"))) {
			for (Path f : files.toList()) {
				Files.copy(f, workspace.resolve(f.getFileName()));
			}
		}
		Files.writeString(workspace.resolve("Carried.goal"), """
				domain Shop;

				// The box is in the robot's hand,
				// ready to be carried.
				goal Carried(Box b) {
				  Bot.holds(b)
				}
				""");
		Files.writeString(workspace.resolve("Relay.arc"), """
				package shop;

				/* Passes text on unchanged. */
				component Relay {
				  port in String input;
				  port out String output;
				  input -> output;
				}
				""");
		ClientCapabilities capabilities = new ClientCapabilities();
		WorkspaceClientCapabilities ws = new WorkspaceClientCapabilities();
		ws.setDidChangeWatchedFiles(new DidChangeWatchedFilesCapabilities(true));
		capabilities.setWorkspace(ws);
		TextDocumentClientCapabilities text = new TextDocumentClientCapabilities();
		DocumentSymbolCapabilities symbols = new DocumentSymbolCapabilities();
		symbols.setHierarchicalDocumentSymbolSupport(true);
		text.setDocumentSymbol(symbols);
		capabilities.setTextDocument(text);
		lsp = new LspSession(workspace, capabilities);
	}

	@AfterAll
	static void stop() throws Exception {
		lsp.close();
	}

	private static String read(String file) throws Exception {
		return Files.readString(workspace.resolve(file));
	}

	private static String hover(String file, String text, String marker, int delta) throws Exception {
		String uri = lsp.open(file, text);
		Hover h = get(lsp.server.getTextDocumentService().hover(new HoverParams(new TextDocumentIdentifier(uri), at(text, marker, delta))));
		return h.getContents().getRight().getValue();
	}

	// ---- hover

	@Test
	void hoverOnAGoalReferenceShowsItsSignatureSituationAndDocumentation() throws Exception {
		String text = "domain Shop;\n\ntask Carry(Box b) {\n  Carried(b);\n}\n";
		String contents = hover("Carry.task", text, "Carried(b)", 2);
		assertEquals("```triad-goal\ngoal Carried(Box b) {\n  Bot.holds(b)\n}\n```\n\nThe box is in the robot's hand,\nready to be carried.", contents);
	}

	@Test
	void hoverOnAPropertyReferenceShowsItsTypeParametersAndActor() throws Exception {
		String contents = hover("At.goal", read("At.goal"), "holds(b)", 1);
		assertEquals("```triad-actor\n// robot Bot\nproperty boolean holds(Box b);\n```", contents);
	}

	@Test
	void hoverOnAnActionShowsItsPreAndPost() throws Exception {
		String contents = hover("Bot.actor", read("Bot.actor"), "action move", 8);
		assertTrue(contents.contains("action move(Place src, Place dst) {\n  pre: loc() == src && World.adj(src, dst) && World.door(src, dst) == DoorState.OPEN;\n  post: loc() == dst;\n}"),
				contents);
	}

	@Test
	void hoverOnATypeShowsItsSuperclassAndAttributes() throws Exception {
		String text = read("Go.task");
		assertEquals("```triad-cd\nclass Room extends Place {\n  String name;\n}\n```", hover("Go.task", text, "Room r", 1));
	}

	@Test
	void hoverOnParametersObjectsLiteralsAndPorts() throws Exception {
		assertTrue(hover("At.goal", read("At.goal"), "== p", 3).contains("// parameter of goal At\nPlace p"));
		assertTrue(hover("Start.state", read("Start.state"), "loc() == hall", 9).contains("// object of state Start\nPlace hall;"));
		assertTrue(hover("World.actor", read("World.actor"), "DoorState.OPEN", 11).contains("DoorState.OPEN"));
		String relay = hover("Relay.arc", read("Relay.arc"), "input -> output", 1);
		assertEquals("```triad-arc\nport in String input;\n```", relay);
		assertTrue(hover("Relay.arc", read("Relay.arc"), "Relay {", 1).endsWith("\n```\n\nPasses text on unchanged."));
	}

	// ---- quick fixes

	private static List<CodeAction> fixes(String uri, Diagnostic d) throws Exception {
		CodeActionParams params = new CodeActionParams(new TextDocumentIdentifier(uri), d.getRange(), new CodeActionContext(List.of(d)));
		List<CodeAction> result = new ArrayList<>();
		for (Either<Command, CodeAction> e : get(lsp.server.getTextDocumentService().codeAction(params))) {
			result.add(e.getRight());
		}
		return result;
	}

	private static Diagnostic diagnostic(String uri, String code) throws Exception {
		return lsp.client.awaitCode(uri, code).stream().filter(d -> code.equals(d.getCode().getLeft())).findFirst()
				.orElseThrow(() -> new AssertionError("no " + code + " in " + lsp.client.diagnostics.get(uri)));
	}

	private static List<String> titles(List<CodeAction> actions) {
		return actions.stream().map(CodeAction::getTitle).toList();
	}

	@Test
	void misspeltPropertyTypeAndGoalGetDidYouMeanFixes() throws Exception {
		String goalUri = lsp.open("Typo.goal", "domain Shop;\n\ngoal Typo(Plcae p) {\n  Bot.lco() == p\n}\n");
		Diagnostic property = diagnostic(goalUri, "link.unknown-property");
		List<CodeAction> propertyFixes = fixes(goalUri, property);
		assertEquals(List.of("Change to 'loc'"), titles(propertyFixes));
		assertEquals(List.of(new TextEdit(property.getRange(), "loc")), propertyFixes.get(0).getEdit().getChanges().get(goalUri));
		assertEquals(List.of("Change to 'Place'"), titles(fixes(goalUri, diagnostic(goalUri, "link.unknown-type"))));

		String taskUri = lsp.open("Typo.task", "domain Shop;\n\ntask Typo(Box b) {\n  Holdng(b);\n}\n");
		assertTrue(titles(fixes(taskUri, diagnostic(taskUri, "link.unknown-goal"))).contains("Change to 'Holding'"));
	}

	@Test
	void anUnknownGoalCanBeCreatedWithTheParametersTheCallImplies() throws Exception {
		String uri = lsp.open("Deliver.task", "domain Shop;\n\ntask Deliver(Box b, Room to) {\n  Delivered(b, to, true);\n}\n");
		List<CodeAction> actions = fixes(uri, diagnostic(uri, "link.unknown-goal"));
		CodeAction create = actions.stream().filter(a -> a.getTitle().equals("Create goal 'Delivered' in Delivered.goal")).findFirst()
				.orElseThrow(() -> new AssertionError(titles(actions).toString()));
		List<Either<TextDocumentEdit, org.eclipse.lsp4j.ResourceOperation>> changes = create.getEdit().getDocumentChanges();
		String newFile = lsp.uri("Delivered.goal");
		assertEquals(newFile, assertInstanceOf(CreateFile.class, changes.get(0).getRight()).getUri());
		TextDocumentEdit content = changes.get(1).getLeft();
		assertEquals(newFile, content.getTextDocument().getUri());
		assertEquals("domain Shop;\n\ngoal Delivered(Box b, Room to, boolean p3) {\n  true\n}\n", content.getEdits().get(0).getLeft().getNewText());
	}

	@Test
	void aMissingDomainLineCanBeInserted() throws Exception {
		String uri = lsp.open("Loose.goal", "// no domain yet\ngoal Loose(Place p) {\n  Bot.loc() == p\n}\n");
		List<CodeAction> actions = fixes(uri, diagnostic(uri, "syntax"));
		assertEquals(List.of("Insert 'domain Shop;'"), titles(actions));
		TextEdit edit = actions.get(0).getEdit().getChanges().get(uri).get(0);
		assertEquals(new Range(new Position(1, 0), new Position(1, 0)), edit.getRange());
		assertEquals("domain Shop;\n\n", edit.getNewText());
	}

	@Test
	void aWrongArgumentCountIsAdjustedToTheDeclaredParameters() throws Exception {
		String uri = lsp.open("Count.task", "domain Shop;\n\ntask Count(Room r, Box b) {\n  At();\n  Holding(b, r);\n}\n");
		List<Diagnostic> counts = lsp.client.await(uri,
				ds -> ds.stream().filter(d -> "task.argument-count".equals(d.getCode().getLeft())).count() == 2);
		List<String> all = new ArrayList<>();
		for (Diagnostic d : counts) {
			if ("task.argument-count".equals(d.getCode().getLeft())) {
				for (CodeAction a : fixes(uri, d)) {
					all.add(a.getTitle() + " " + a.getEdit().getChanges().get(uri));
				}
			}
		}
		assertEquals(2, all.size(), all.toString());
		assertTrue(all.get(0).startsWith("Change to At(r) "), all.toString());
		assertTrue(all.get(0).contains("newText = \"r\""), all.toString());
		assertTrue(all.get(1).startsWith("Change to Holding(b) "), all.toString());

		String goalUri = lsp.open("Count.goal", "domain Shop;\n\ngoal Count(Box b) {\n  Bot.holds()\n}\n");
		assertEquals(List.of("Change to holds(b)"), titles(fixes(goalUri, diagnostic(goalUri, "expr.argument-count"))));
	}

	// ---- semantic tokens

	@Test
	void semanticTokensColourKeywordsAndNamesByWhatTheyName() throws Exception {
		String text = read("At.goal");
		String uri = lsp.open("At.goal", text);
		SemanticTokens tokens = get(lsp.server.getTextDocumentService().semanticTokensFull(new SemanticTokensParams(new TextDocumentIdentifier(uri))));
		SemanticTokensLegend legend = lsp.initializeResult.getCapabilities().getSemanticTokensProvider().getLegend();
		List<String> decoded = decode(text, tokens.getData(), legend);
		assertEquals(List.of("domain:keyword", "Shop:namespace", "goal:keyword", "At:function+declaration", "Place:class", "p:parameter+declaration",
				"Bot:namespace", "loc:property", "p:parameter", "goal:keyword", "Holding:function+declaration", "Box:class",
				"b:parameter+declaration", "Bot:namespace", "holds:property", "b:parameter"), decoded);
	}

	private static List<String> decode(String text, List<Integer> data, SemanticTokensLegend legend) {
		List<String> lines = text.lines().toList();
		List<String> result = new ArrayList<>();
		int line = 0;
		int col = 0;
		for (int i = 0; i < data.size(); i += 5) {
			line += data.get(i);
			col = data.get(i) == 0 ? col + data.get(i + 1) : data.get(i + 1);
			String word = lines.get(line).substring(col, col + data.get(i + 2));
			StringBuilder kind = new StringBuilder(legend.getTokenTypes().get(data.get(i + 3)));
			for (int m = 0; m < legend.getTokenModifiers().size(); m++) {
				if ((data.get(i + 4) & (1 << m)) != 0) {
					kind.append('+').append(legend.getTokenModifiers().get(m));
				}
			}
			result.add(word + ":" + kind);
		}
		return result;
	}

	// ---- signature help

	@Test
	void signatureHelpShowsTheParametersOfTheGoalOrPropertyBeingCalled() throws Exception {
		String task = "domain Shop;\n\ntask Sig(Box b, Room r) {\n  Holding(b);\n  At(\n}\n";
		String taskUri = lsp.open("Sig.task", task);
		SignatureHelp help = get(lsp.server.getTextDocumentService().signatureHelp(new SignatureHelpParams(new TextDocumentIdentifier(taskUri),
				at(task, "At(", 3))));
		assertEquals("goal At(Place p)", help.getSignatures().get(0).getLabel());
		assertEquals(0, help.getActiveParameter());

		String goal = "domain Shop;\n\ngoal Sig(Place a, Place c) {\n  World.door(a, c\n}\n";
		String goalUri = lsp.open("Sig.goal", goal);
		help = get(lsp.server.getTextDocumentService().signatureHelp(new SignatureHelpParams(new TextDocumentIdentifier(goalUri),
				at(goal, "a, c", 3))));
		assertEquals("property DoorState World.door(Place a, Place b)", help.getSignatures().get(0).getLabel());
		assertEquals(1, help.getActiveParameter());
		var second = help.getSignatures().get(0).getParameters().get(1).getLabel().getRight();
		assertEquals("Place b", help.getSignatures().get(0).getLabel().substring(second.getFirst(), second.getSecond()));

		help = get(lsp.server.getTextDocumentService().signatureHelp(new SignatureHelpParams(new TextDocumentIdentifier(goalUri),
				at(goal, "Sig(", 4))));
		assertTrue(help.getSignatures().isEmpty(), "a declaration is not a call");
	}

	// ---- document symbols

	@Test
	void documentSymbolsHaveTheirOwnKindsNamesAndDetails() throws Exception {
		List<String> actor = symbols("Bot.actor");
		assertEquals(List.of("Bot Object robot", "  loc Property (): Place", "  holds Property (Box b): boolean", "  b Variable Box",
				"  handEmpty Property (): boolean", "  charge Property (): double", "  move Method (Place src, Place dst)", "  src Variable Place",
				"  dst Variable Place", "  pick Method (Box b)", "  b Variable Box"), actor.stream().map(s -> s.replace("    ", "  ")).toList());
		assertEquals(List.of("Go Function (Room r)", "  r Variable Room", "Fetch Function (Box b, Room from, Room to)", "  b Variable Box",
				"  from Variable Room", "  to Variable Room"), symbols("Go.task"));
		assertTrue(symbols("Shop.cd").containsAll(List.of("Shop Package ", "  Room Class extends Place", "    name Field String", "  DoorState Enum ",
				"    OPEN EnumMember ")), symbols("Shop.cd").toString());
		assertEquals("At Event (Place p)", symbols("At.goal").get(0));
	}

	private static List<String> symbols(String file) throws Exception {
		String uri = lsp.open(file);
		List<Either<SymbolInformation, DocumentSymbol>> result = get(
				lsp.server.getTextDocumentService().documentSymbol(new DocumentSymbolParams(new TextDocumentIdentifier(uri))));
		List<String> lines = new ArrayList<>();
		for (Either<SymbolInformation, DocumentSymbol> e : result) {
			flatten(e.getRight(), "", lines);
		}
		return lines;
	}

	private static void flatten(DocumentSymbol s, String indent, List<String> lines) {
		lines.add(indent + s.getName() + " " + s.getKind() + " " + s.getDetail());
		for (DocumentSymbol child : s.getChildren()) {
			flatten(child, indent + "  ", lines);
		}
	}

	// ---- file watching

	@Test
	void registersAWatcherAndChecksModelsChangedOnDisk() throws Exception {
		lsp.client.awaitRegistration();
		Registration r = lsp.client.registrations.stream().flatMap(p -> p.getRegistrations().stream())
				.filter(x -> x.getMethod().equals("workspace/didChangeWatchedFiles")).findFirst().orElseThrow();
		assertEquals(TriadLanguageServer.WATCHER_REGISTRATION, r.getId());
		String options = r.getRegisterOptions().toString();
		assertTrue(options.contains("**/*.{cd,actor,goal,task,state,arc}"), options);

		Path later = workspace.resolve("Later.goal");
		Files.writeString(later, "domain Shop;\n\ngoal Later(Place p) {\n  Bot.nowhere() == p\n}\n");
		String uri = LspSession.uri(later);
		lsp.server.getWorkspaceService().didChangeWatchedFiles(new DidChangeWatchedFilesParams(List.of(new FileEvent(uri, FileChangeType.Created))));
		assertEquals("link.unknown-property", diagnostic(uri, "link.unknown-property").getCode().getLeft());
	}

	// ---- navigation that used to fail

	@Test
	void typeDefinitionAndImplementationAnswerInsteadOfFailing() throws Exception {
		String text = read("At.goal");
		String uri = lsp.open("At.goal", text);
		List<? extends Location> types = get(lsp.server.getTextDocumentService()
				.typeDefinition(new TypeDefinitionParams(new TextDocumentIdentifier(uri), at(text, "== p", 3)))).getLeft();
		assertEquals(1, types.size(), types.toString());
		assertEquals(lsp.uri("Shop.cd"), types.get(0).getUri());
		assertEquals(new Range(new Position(3, 8), new Position(3, 13)), types.get(0).getRange()); // "class Place;"

		List<? extends Location> impl = get(lsp.server.getTextDocumentService()
				.implementation(new ImplementationParams(new TextDocumentIdentifier(uri), at(text, "loc()", 1)))).getLeft();
		assertEquals(lsp.uri("Bot.actor"), impl.get(0).getUri());
		List<? extends Location> none = get(lsp.server.getTextDocumentService()
				.typeDefinition(new TypeDefinitionParams(new TextDocumentIdentifier(uri), new Position(0, 0)))).getLeft();
		assertEquals(List.of(), none);
	}

	// ---- completion

	@Test
	void completionAfterAPartialNameOffersOnlyNames() throws Exception {
		String text = "domain Shop;\n\ngoal Part(Place p) {\n  Bot.lo\n}\n";
		String uri = lsp.open("Part.goal", text);
		List<String> labels = complete(uri, at(text, "Bot.lo", 6));
		assertEquals(List.of("loc"), labels);

		String state = "domain Shop;\n\nstate Part {\n  Place h;\n  Bot.loc() == h\n}\n";
		String stateUri = lsp.open("Part.state", state);
		List<String> afterValue = complete(stateUri, at(state, "== h", 4));
		assertFalse(afterValue.contains("value") || afterValue.contains("\"value\""), afterValue.toString());
		assertTrue(afterValue.stream().noneMatch(l -> List.of("==", "!=", "<", "<=", ">", ">=", "&&", "||").contains(l)), afterValue.toString());
		assertTrue(afterValue.contains("h"), afterValue.toString());
	}

	@Test
	void completionAfterADotOffersTheObjectsAttributesOrTheEnumerationsLiterals() throws Exception {
		String text = "domain Shop;\n\ngoal Heavy(Box b) {\n  Bot.holds(b) && b.\n}\n";
		String uri = lsp.open("Heavy.goal", text);
		assertEquals(List.of("label", "weight"), complete(uri, at(text, "&& b.", 5)), "Box's own attribute and Thing's");
		String open = "domain Shop;\n\ngoal Open(Place a, Place b) {\n  World.door(a, b) == DoorState.\n}\n";
		String openUri = lsp.open("Open.goal", open);
		assertEquals(List.of("CLOSED", "OPEN"), complete(openUri, at(open, "DoorState.", 10)));
	}

	private static List<String> complete(String uri, Position p) throws Exception {
		Either<List<CompletionItem>, CompletionList> r = get(lsp.server.getTextDocumentService().completion(new CompletionParams(new TextDocumentIdentifier(uri), p)));
		return (r.isLeft() ? r.getLeft() : r.getRight().getItems()).stream().map(CompletionItem::getLabel).sorted().collect(Collectors.toList());
	}

	// ---- rename

	@Test
	void renameRefusesANameThatClashesAndRenamesOtherwise() throws Exception {
		String text = read("Bot.actor");
		String uri = lsp.open("Bot.actor", text);
		ExecutionException clash = assertThrows(ExecutionException.class,
				() -> get(lsp.server.getTextDocumentService().rename(new RenameParams(new TextDocumentIdentifier(uri), at(text, "loc()", 1), "holds"))));
		ResponseErrorException error = assertInstanceOf(ResponseErrorException.class, clash.getCause());
		assertTrue(error.getResponseError().getMessage().contains("cannot rename 'loc' to 'holds': robot Bot already has property 'holds'")
				|| String.valueOf(error.getResponseError().getData()).contains("robot Bot already has property 'holds'"), error.getResponseError().toString());

		assertThrows(ExecutionException.class,
				() -> get(lsp.server.getTextDocumentService().rename(new RenameParams(new TextDocumentIdentifier(uri), at(text, "loc()", 1), "robot"))));

		WorkspaceEdit edit = get(lsp.server.getTextDocumentService().rename(new RenameParams(new TextDocumentIdentifier(uri), at(text, "charge()", 1), "battery")));
		String all = String.valueOf(edit);
		assertTrue(all.contains("Start.state") && all.contains("battery"), all);
	}
}
