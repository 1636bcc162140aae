package org.triad.planner.pddl;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Parses PDDL domains and problems (STRIPS, typing incl. {@code either}, negative preconditions,
 * equality, disjunctive/quantified preconditions and goals, {@code forall} and conditional
 * ({@code when}) effects, action costs: PDDL's ADL subset).
 * Every syntax error is a {@link PddlParseException} with {@code line:col}.
 */
public final class PddlParser {
    private final String source;

    private PddlParser(String source) {
        this.source = source;
    }

    public static Domain parseDomain(String text, String source) {
        return new PddlParser(source).domain(SExpr.read(text, source));
    }

    public static Problem parseProblem(String text, String source) {
        return new PddlParser(source).problem(SExpr.read(text, source));
    }

    /**
     * A problem read against its domain: also a located error where the problem needs a numeric value it
     * can never have ({@link UndefinedFluents}: the goal or metric reads a fluent that has no value and no
     * action assigns, or an action reads a function that has no value for any arguments).
     */
    public static Problem parseProblem(String text, String source, Domain domain) {
        SExpr root = SExpr.read(text, source);
        Problem problem = new PddlParser(source).problem(root);
        UndefinedFluents.check(domain, problem, root, source);
        return problem;
    }

    /** {@link #parseProblem(String, String, Domain)} of a file. */
    public static Problem parseProblem(Path file, Domain domain) throws IOException {
        return parseProblem(Files.readString(file), file.toString(), domain);
    }

    /** A metric's text, {@code minimize (total-cost)} (what {@link Problem#metric()} holds); a bad one is a located error. */
    static PlanMetric parseMetric(String text, String source) {
        SExpr e = SExpr.read("(" + text + ")", source);
        PddlParser p = new PddlParser(source);
        return p.metric(e, e.items);
    }

    public static Domain parseDomain(Path file) throws IOException {
        return parseDomain(Files.readString(file), file.toString());
    }

    public static Problem parseProblem(Path file) throws IOException {
        return parseProblem(Files.readString(file), file.toString());
    }

    private PddlParseException err(SExpr at, String msg) {
        return new PddlParseException(source, at.line, at.column, msg);
    }

    private List<SExpr> list(SExpr e, String what) {
        if (!e.isList()) throw err(e, "expected " + what + " in parentheses, found '" + e.symbol + "'");
        return e.items;
    }

    private String name(SExpr e, String what) {
        if (e.isList()) throw err(e, "expected " + what + ", found a parenthesised expression");
        return e.symbol;
    }

    private List<SExpr> header(SExpr root, String kind) {
        List<SExpr> items = list(root, "'(define (" + kind + " NAME) ...)'");
        if (items.isEmpty() || !items.get(0).isSymbol("define")) throw err(root, "expected '(define (" + kind + " NAME) ...)'");
        if (items.size() < 2) throw err(root, "missing '(" + kind + " NAME)' after 'define'");
        List<SExpr> h = list(items.get(1), "'(" + kind + " NAME)'");
        if (h.size() != 2 || !h.get(0).isSymbol(kind)) {
            throw err(items.get(1), "expected '(" + kind + " NAME)'" + (h.isEmpty() || h.get(0).isList() ? "" : ", found '(" + h.get(0).symbol + " ...)'"));
        }
        return items;
    }

    private Domain domain(SExpr root) {
        List<SExpr> items = header(root, "domain");
        String name = name(items.get(1).items.get(1), "a domain name");
        List<String> reqs = new ArrayList<>();
        List<TypedName> types = new ArrayList<>();
        List<TypedName> constants = new ArrayList<>();
        List<PredicateDecl> preds = new ArrayList<>();
        List<PredicateDecl> functions = new ArrayList<>();
        List<Action> actions = new ArrayList<>();
        List<SExpr> actionExprs = new ArrayList<>();
        List<Axiom> axioms = new ArrayList<>();
        List<SExpr> axiomExprs = new ArrayList<>();
        for (SExpr sec : items.subList(2, items.size())) {
            String head = sec.head();
            if (head == null) throw err(sec, "expected a domain section such as '(:predicates ...)'");
            List<SExpr> rest = sec.items.subList(1, sec.items.size());
            switch (head) {
                case ":requirements" -> reqs.addAll(requirements(rest));
                case ":types" -> types.addAll(typedList(rest, "object", false));
                case ":constants" -> constants.addAll(typedList(rest, "object", false));
                case ":predicates" -> {
                    for (SExpr p : rest) preds.add(predicateDecl(p));
                }
                case ":functions" -> {
                    for (SExpr p : rest) {
                        if (p.isList()) functions.add(predicateDecl(p));
                        // "- number" type annotations are accepted and ignored
                    }
                }
                case ":action" -> {
                    actions.add(action(sec));
                    actionExprs.add(sec);
                }
                case ":derived" -> {
                    axioms.add(axiom(sec));
                    axiomExprs.add(sec);
                }
                case ":durative-action" -> throw err(sec, head + " is not supported (durative actions)");
                default -> throw err(sec, "unknown domain section '" + head + "'");
            }
        }
        Set<String> seen = new HashSet<>();
        for (int i = 0; i < actions.size(); i++) {
            if (!seen.add(actions.get(i).name())) throw err(actionExprs.get(i), "action '" + actions.get(i).name() + "' is defined twice");
        }
        Set<String> declared = new HashSet<>();
        preds.forEach(p -> declared.add(p.name()));
        for (int i = 0; i < actions.size(); i++) checkPredicates(actions.get(i), declared, actionExprs.get(i));
        Set<String> declaredFunctions = new HashSet<>();
        functions.forEach(f -> declaredFunctions.add(f.name()));
        for (int i = 0; i < actions.size(); i++) {
            for (NumericExpr.Fluent f : NumericParts.fluents(actions.get(i))) {
                if (!declaredFunctions.contains(f.name())) {
                    throw err(actionExprs.get(i), "action '" + actions.get(i).name() + "' uses undeclared function '" + f.name() + "'");
                }
            }
        }
        Set<String> effectPredicates = new HashSet<>();
        for (Action a : actions) {
            List<Formula.Atom> atoms = new ArrayList<>();
            collectEffectAtomsOnly(a.effects(), atoms);
            atoms.forEach(at -> effectPredicates.add(at.predicate()));
        }
        for (int i = 0; i < axioms.size(); i++) {
            Axiom ax = axioms.get(i);
            SExpr at = axiomExprs.get(i);
            if (!declared.contains(ax.predicate())) throw err(at, "derived predicate '" + ax.predicate() + "' is not declared in :predicates");
            if (effectPredicates.contains(ax.predicate())) throw err(at, "derived predicate '" + ax.predicate() + "' is changed by an action effect");
            List<Formula.Atom> atoms = new ArrayList<>();
            collectAtoms(ax.body(), atoms);
            for (Formula.Atom a : atoms) {
                if (!declared.contains(a.predicate())) throw err(at, "derived predicate '" + ax.predicate() + "' uses undeclared predicate '" + a.predicate() + "'");
            }
        }
        return new Domain(name, reqs, types, constants, preds, functions, actions, axioms);
    }

    /** Requirements the parser and engine handle. */
    static final Set<String> SUPPORTED_REQUIREMENTS = Set.of(":strips", ":typing", ":negative-preconditions",
            ":disjunctive-preconditions", ":equality", ":existential-preconditions", ":universal-preconditions",
            ":quantified-preconditions", ":conditional-effects", ":adl", ":action-costs", ":derived-predicates",
            ":numeric-fluents", ":fluents");
    /** Requirements of PDDL 1.2-3.1 that this planner does not handle (it would plan wrongly if it ignored them). */
    static final Set<String> UNSUPPORTED_REQUIREMENTS = Set.of(":object-fluents",
            ":durative-actions", ":duration-inequalities", ":continuous-effects",
            ":timed-initial-literals", ":preferences", ":constraints", ":time", ":expression-evaluation",
            ":domain-axioms", ":safety-constraints", ":open-world", ":true-negation", ":ucpop", ":foreach-expansions",
            ":dag-expansions", ":subgoal-through-axioms", ":action-expansions");

    /**
     * Reads a requirements list and rejects what the planner cannot honour: the error sits at the
     * first unsupported requirement and names every one.
     */
    private List<String> requirements(List<SExpr> items) {
        List<String> out = new ArrayList<>();
        List<SExpr> bad = new ArrayList<>();
        for (SExpr r : items) {
            String n = name(r, "a requirement such as ':strips'");
            if (!n.startsWith(":")) throw err(r, "expected a requirement such as ':strips', found '" + n + "'");
            if (!SUPPORTED_REQUIREMENTS.contains(n)) bad.add(r);
            out.add(n);
        }
        if (!bad.isEmpty()) {
            StringBuilder sb = new StringBuilder();
            for (SExpr r : bad) {
                if (sb.length() > 0) sb.append(", ");
                sb.append('\'').append(r.symbol).append('\'');
                if (r != bad.get(0)) sb.append(" (").append(r.line).append(':').append(r.column).append(')');
                if (!UNSUPPORTED_REQUIREMENTS.contains(r.symbol)) sb.append(" (not a PDDL requirement)");
            }
            throw err(bad.get(0), "unsupported requirement" + (bad.size() > 1 ? "s " : " ") + sb
                    + "; Triad's planner supports " + String.join(" ", new java.util.TreeSet<>(SUPPORTED_REQUIREMENTS)));
        }
        return out;
    }

    private void checkPredicates(Action a, Set<String> declared, SExpr root) {
        List<Formula.Atom> atoms = new ArrayList<>();
        collectAtoms(a.precondition(), atoms);
        collectEffectAtoms(a.effects(), atoms);
        for (Formula.Atom at : atoms) {
            if (!declared.contains(at.predicate())) {
                throw err(root, "action '" + a.name() + "' uses undeclared predicate '" + at.predicate() + "'");
            }
        }
    }

    static void collectAtoms(Formula f, List<Formula.Atom> out) {
        if (f instanceof Formula.Atom a) out.add(a);
        else if (f instanceof Formula.Not n) collectAtoms(n.body(), out);
        else if (f instanceof Formula.And a) a.parts().forEach(p -> collectAtoms(p, out));
        else if (f instanceof Formula.Or o) o.parts().forEach(p -> collectAtoms(p, out));
        else if (f instanceof Formula.Imply i) {
            collectAtoms(i.condition(), out);
            collectAtoms(i.consequence(), out);
        } else if (f instanceof Formula.Forall q) collectAtoms(q.body(), out);
        else if (f instanceof Formula.Exists q) collectAtoms(q.body(), out);
    }

    static void collectEffectAtoms(List<PddlEffect> effects, List<Formula.Atom> out) {
        for (PddlEffect e : effects) {
            if (e instanceof PddlEffect.Add a) out.add(a.atom());
            else if (e instanceof PddlEffect.Delete d) out.add(d.atom());
            else if (e instanceof PddlEffect.Forall q) collectEffectAtoms(q.body(), out);
            else if (e instanceof PddlEffect.When w) {
                collectAtoms(w.condition(), out);
                collectEffectAtoms(w.body(), out);
            }
        }
    }

    private static void collectEffectAtomsOnly(List<PddlEffect> effects, List<Formula.Atom> out) {
        for (PddlEffect e : effects) {
            if (e instanceof PddlEffect.Add a) out.add(a.atom());
            else if (e instanceof PddlEffect.Delete d) out.add(d.atom());
            else if (e instanceof PddlEffect.Forall q) collectEffectAtomsOnly(q.body(), out);
            else if (e instanceof PddlEffect.When w) collectEffectAtomsOnly(w.body(), out);
        }
    }

    /** {@code (:derived (PREDICATE ?x - t ...) BODY)}: the body may only use the head's variables (and its own quantified ones). */
    private Axiom axiom(SExpr sec) {
        List<SExpr> it = sec.items;
        if (it.size() != 3) throw err(sec, "expected '(:derived (PREDICATE PARAMETERS) FORMULA)'");
        List<SExpr> h = list(it.get(1), "'(PREDICATE PARAMETERS)'");
        if (h.isEmpty()) throw err(it.get(1), "empty derived predicate head");
        String pred = name(h.get(0), "a predicate name");
        List<TypedName> params = typedList(h.subList(1, h.size()), "object", true);
        Set<String> vars = new HashSet<>();
        for (TypedName p : params) {
            if (!vars.add(p.name())) throw err(it.get(1), "parameter '" + p.name() + "' is declared twice in derived predicate '" + pred + "'");
        }
        Formula body = formula(it.get(2));
        checkVariables(body, vars, sec, "derived predicate " + pred);
        return new Axiom(pred, params, body);
    }

    private PredicateDecl predicateDecl(SExpr p) {
        List<SExpr> it = list(p, "a predicate declaration");
        if (it.isEmpty()) throw err(p, "empty predicate declaration");
        return new PredicateDecl(name(it.get(0), "a predicate name"), typedList(it.subList(1, it.size()), "object", true));
    }

    /** Parses {@code a b - t c - (either u v) d}; untyped names get {@code defaultType}. */
    private List<TypedName> typedList(List<SExpr> items, String defaultType, boolean variables) {
        List<TypedName> out = new ArrayList<>();
        List<SExpr> pending = new ArrayList<>();
        for (int i = 0; i < items.size(); i++) {
            SExpr e = items.get(i);
            if (!e.isList() && e.symbol.length() > 1 && e.symbol.startsWith("-") && Character.isLetter(e.symbol.charAt(1))) {
                // "depot market -place": the dash glued to the type, as FF's and VAL's lexers read it (IPC 2023 tpp)
                if (pending.isEmpty()) throw err(e, "'-' without names before it");
                for (SExpr n : pending) out.add(TypedName.of(n.symbol, e.symbol.substring(1)));
                pending.clear();
            } else if (e.isSymbol("-")) {
                if (pending.isEmpty()) throw err(e, "'-' without names before it");
                if (i + 1 >= items.size()) throw err(e, "missing type after '-'");
                List<String> types = typeSpec(items.get(++i));
                for (SExpr n : pending) out.add(new TypedName(n.symbol, types));
                pending.clear();
            } else {
                String n = name(e, variables ? "a variable" : "a name");
                if (variables && !n.startsWith("?")) throw err(e, "expected a variable starting with '?', found '" + n + "'");
                if (!variables && n.startsWith("?")) throw err(e, "expected a name, found variable '" + n + "'");
                pending.add(e);
            }
        }
        for (SExpr n : pending) out.add(TypedName.of(n.symbol, defaultType));
        return out;
    }

    private List<String> typeSpec(SExpr t) {
        if (!t.isList()) return List.of(t.symbol);
        if (!"either".equals(t.head()) || t.items.size() < 2) throw err(t, "expected a type name or '(either T1 T2 ...)'");
        List<String> types = new ArrayList<>();
        for (SExpr x : t.items.subList(1, t.items.size())) types.add(name(x, "a type name"));
        return types;
    }

    private Action action(SExpr sec) {
        List<SExpr> it = sec.items;
        if (it.size() < 2) throw err(sec, "missing action name after ':action'");
        String name = name(it.get(1), "an action name");
        List<TypedName> params = List.of();
        Formula pre = new Formula.And(List.of());
        List<PddlEffect> effects = List.of();
        for (int i = 2; i < it.size(); i += 2) {
            SExpr key = it.get(i);
            String k = name(key, "':parameters', ':precondition' or ':effect'");
            if (i + 1 >= it.size()) throw err(key, "missing value after '" + k + "'");
            SExpr v = it.get(i + 1);
            switch (k) {
                case ":parameters" -> params = typedList(list(v, "a parameter list"), "object", true);
                case ":precondition" -> pre = v.isList() && v.items.isEmpty() ? new Formula.And(List.of()) : formula(v);
                case ":effect" -> effects = v.isList() && v.items.isEmpty() ? List.of() : effect(v);
                default -> throw err(key, "unknown action key '" + k + "' in action '" + name + "'");
            }
        }
        Set<String> vars = new HashSet<>();
        for (TypedName p : params) {
            if (!vars.add(p.name())) throw err(sec, "parameter '" + p.name() + "' is declared twice in action '" + name + "'");
        }
        checkVariables(pre, vars, sec, name);
        List<Formula.Atom> atoms = new ArrayList<>();
        collectEffectAtomsBound(effects, vars, sec, name);
        collectAtoms(pre, atoms);
        return new Action(name, params, pre, effects);
    }

    private void checkVariables(Formula f, Set<String> bound, SExpr at, String action) {
        if (f instanceof Formula.Atom a) a.args().forEach(x -> checkVar(x, bound, at, action));
        else if (f instanceof Formula.Equals e) {
            checkVar(e.left(), bound, at, action);
            checkVar(e.right(), bound, at, action);
        } else if (f instanceof Formula.Not n) checkVariables(n.body(), bound, at, action);
        else if (f instanceof Formula.And a) a.parts().forEach(p -> checkVariables(p, bound, at, action));
        else if (f instanceof Formula.Or o) o.parts().forEach(p -> checkVariables(p, bound, at, action));
        else if (f instanceof Formula.Imply i) {
            checkVariables(i.condition(), bound, at, action);
            checkVariables(i.consequence(), bound, at, action);
        } else if (f instanceof Formula.Forall q) checkVariables(q.body(), extend(bound, q.variables()), at, action);
        else if (f instanceof Formula.Exists q) checkVariables(q.body(), extend(bound, q.variables()), at, action);
        else if (f instanceof Formula.Compare c) {
            for (NumericExpr.Fluent fl : NumericParts.fluents(c)) fl.args().forEach(x -> checkVar(x, bound, at, action));
        }
    }

    private void collectEffectAtomsBound(List<PddlEffect> effects, Set<String> bound, SExpr at, String action) {
        for (PddlEffect e : effects) {
            if (e instanceof PddlEffect.Add a) a.atom().args().forEach(x -> checkVar(x, bound, at, action));
            else if (e instanceof PddlEffect.Delete d) d.atom().args().forEach(x -> checkVar(x, bound, at, action));
            else if (e instanceof PddlEffect.Forall q) collectEffectAtomsBound(q.body(), extend(bound, q.variables()), at, action);
            else if (e instanceof PddlEffect.When w) {
                checkVariables(w.condition(), bound, at, action);
                collectEffectAtomsBound(w.body(), bound, at, action);
            } else if (e instanceof PddlEffect.NumericEffect n) {
                for (NumericExpr.Fluent fl : NumericParts.fluents(n)) fl.args().forEach(x -> checkVar(x, bound, at, action));
            }
        }
    }

    private static Set<String> extend(Set<String> bound, List<TypedName> vars) {
        Set<String> s = new HashSet<>(bound);
        vars.forEach(v -> s.add(v.name()));
        return s;
    }

    private void checkVar(String term, Set<String> bound, SExpr at, String action) {
        if (term.startsWith("?") && !bound.contains(term)) {
            String owner = action.startsWith("derived predicate ") ? "derived predicate '" + action.substring(18) + "'" : "action '" + action + "'";
            throw err(at, "variable '" + term + "' is not a parameter of " + owner);
        }
    }

    private Formula formula(SExpr e) {
        List<SExpr> it = list(e, "a formula");
        if (it.isEmpty()) throw err(e, "empty formula '()'");
        String head = name(it.get(0), "a predicate or connective");
        List<SExpr> args = it.subList(1, it.size());
        switch (head) {
            case "and": {
                List<Formula> parts = new ArrayList<>();
                for (SExpr a : args) parts.add(formula(a));
                return new Formula.And(parts);
            }
            case "or": {
                List<Formula> parts = new ArrayList<>();
                for (SExpr a : args) parts.add(formula(a));
                return new Formula.Or(parts);
            }
            case "not":
                if (args.size() != 1) throw err(e, "'not' takes exactly one formula");
                return new Formula.Not(formula(args.get(0)));
            case "imply":
                if (args.size() != 2) throw err(e, "'imply' takes exactly two formulas");
                return new Formula.Imply(formula(args.get(0)), formula(args.get(1)));
            case "=":
                if (args.size() != 2) throw err(e, "'=' takes exactly two terms");
                if (isObjectTerm(args.get(0)) && isObjectTerm(args.get(1))) {
                    return new Formula.Equals(name(args.get(0), "a term"), name(args.get(1), "a term"));
                }
                return new Formula.Compare("=", numericExpr(args.get(0)), numericExpr(args.get(1)));
            case "<", "<=", ">", ">=":
                if (args.size() != 2) throw err(e, "'" + head + "' takes exactly two numeric expressions");
                return new Formula.Compare(head, numericExpr(args.get(0)), numericExpr(args.get(1)));
            case "forall":
            case "exists": {
                if (args.size() != 2) throw err(e, "'" + head + "' takes a variable list and a formula");
                List<TypedName> vars = typedList(list(args.get(0), "a variable list"), "object", true);
                Formula body = formula(args.get(1));
                return head.equals("forall") ? new Formula.Forall(vars, body) : new Formula.Exists(vars, body);
            }
            case "when":
                throw err(e, "'when' is an effect, not a formula");
            default:
                if (head.startsWith(":") || head.startsWith("?")) throw err(it.get(0), "expected a predicate name, found '" + head + "'");
                List<String> terms = new ArrayList<>();
                for (SExpr a : args) terms.add(name(a, "a term (object or variable)"));
                return new Formula.Atom(head, terms);
        }
    }

    private List<PddlEffect> effect(SExpr e) {
        List<SExpr> it = list(e, "an effect");
        if (it.isEmpty()) throw err(e, "empty effect '()'");
        String head = name(it.get(0), "an effect");
        List<SExpr> args = it.subList(1, it.size());
        switch (head) {
            case "and": {
                List<PddlEffect> out = new ArrayList<>();
                for (SExpr a : args) out.addAll(effect(a));
                return out;
            }
            case "not": {
                if (args.size() != 1) throw err(e, "'not' takes exactly one atom");
                Formula f = formula(args.get(0));
                if (!(f instanceof Formula.Atom a)) throw err(args.get(0), "only an atom can be deleted in an effect");
                return List.of(new PddlEffect.Delete(a));
            }
            case "forall": {
                if (args.size() != 2) throw err(e, "'forall' takes a variable list and an effect");
                List<TypedName> vars = typedList(list(args.get(0), "a variable list"), "object", true);
                return List.of(new PddlEffect.Forall(vars, effect(args.get(1))));
            }
            case "when": {
                if (args.size() != 2) throw err(e, "'when' takes a condition and an effect");
                Formula condition = args.get(0).isList() && args.get(0).items.isEmpty() ? new Formula.And(List.of()) : formula(args.get(0));
                List<PddlEffect> body = effect(args.get(1));
                for (PddlEffect b : body) {
                    if (b instanceof PddlEffect.Increase) throw err(args.get(1), "'increase' inside 'when' is not supported (action costs must not depend on the state)");
                }
                return List.of(new PddlEffect.When(condition, body));
            }
            case "increase", "decrease", "assign", "scale-up", "scale-down": {
                if (args.size() != 2) throw err(e, "'" + head + "' takes a function term and a numeric expression");
                List<SExpr> f = list(args.get(0), "a function term such as (battery ?r)");
                if (f.isEmpty()) throw err(args.get(0), "empty function term");
                NumericExpr value = numericExpr(args.get(1));
                if (head.equals("increase") && f.size() == 1 && "total-cost".equals(f.get(0).symbol)
                        && (value instanceof NumericExpr.Number || value instanceof NumericExpr.Fluent)) {
                    return List.of(new PddlEffect.Increase("total-cost", numeric(args.get(1)))); // an action cost
                }
                if (!(numericExpr(args.get(0)) instanceof NumericExpr.Fluent target)) throw err(args.get(0), "expected a function term");
                return List.of(new PddlEffect.NumericEffect(head, target, value));
            }
            default: {
                Formula f = formula(e);
                if (!(f instanceof Formula.Atom a)) throw err(e, "expected an atom in an effect");
                return List.of(new PddlEffect.Add(a));
            }
        }
    }

    /** An object name or variable (not a number, not a function term): the operand of object equality. */
    private static boolean isObjectTerm(SExpr e) {
        return !e.isList() && !isNumber(e.symbol);
    }

    /** {@code minimize|maximize EXPRESSION}; a bare {@code total-time} (as temporal problems write it) is the fluent. */
    private PlanMetric metric(SExpr at, List<SExpr> rest) {
        if (rest.size() != 2 || rest.get(0).isList() || !List.of("minimize", "maximize").contains(rest.get(0).symbol.toLowerCase(java.util.Locale.ROOT))) {
            throw err(at, "expected '(:metric minimize EXPRESSION)' or '(:metric maximize EXPRESSION)', such as '(:metric minimize (total-cost))'");
        }
        SExpr x = rest.get(1);
        NumericExpr e = !x.isList() && x.symbol.equalsIgnoreCase(PlanMetric.TOTAL_TIME) ? NumericExpr.Fluent.of(PlanMetric.TOTAL_TIME)
                : !x.isList() && x.symbol.equalsIgnoreCase(PlanMetric.TOTAL_COST) ? NumericExpr.Fluent.of(PlanMetric.TOTAL_COST) : numericExpr(x);
        for (NumericExpr.Fluent f : NumericParts.fluents(e)) {
            for (String t : f.args()) if (t.startsWith("?")) throw err(x, "variable '" + t + "' in the metric: it must be ground");
        }
        return new PlanMetric(rest.get(0).symbol.equalsIgnoreCase("minimize"), e);
    }

    private static final java.util.regex.Pattern NUMBER = java.util.regex.Pattern.compile("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");

    /** A decimal number as PDDL writes it (Java's parser would also take {@code 0x1p3}, {@code 1d} or {@code NaN}). */
    private static boolean isNumber(String s) {
        return NUMBER.matcher(s).matches();
    }

    /** A PDDL 2.1 numeric expression: a number, {@code (f args)}, {@code (+ a b ...)}, {@code (- a b)}, {@code (- a)}, {@code (* a b ...)}, {@code (/ a b)}. */
    private NumericExpr numericExpr(SExpr e) {
        if (!e.isList()) {
            if (!isNumber(e.symbol)) {
                if (List.of("nan", "inf", "infinity", "-inf", "-infinity").contains(e.symbol)) throw err(e, "'" + e.symbol + "' is not a finite number");
                if (e.symbol.startsWith("?") || Character.isLetter(e.symbol.charAt(0))) {
                    throw err(e, "'" + e.symbol + "' is " + (e.symbol.startsWith("?") ? "a variable, which stands for an object" : "an object")
                            + ", not a number: numeric comparisons and effects need numbers or function terms such as (battery ?r)");
                }
                throw err(e, "expected a number or a function term such as (battery ?r), found '" + e.symbol + "'");
            }
            double v = Double.parseDouble(e.symbol);
            if (!Double.isFinite(v)) throw err(e, "'" + e.symbol + "' is not a finite number (too large for a double)");
            return new NumericExpr.Number(v);
        }
        if (e.items.isEmpty()) throw err(e, "empty numeric expression '()'");
        String head = name(e.items.get(0), "a function name or an arithmetic operator");
        List<SExpr> args = e.items.subList(1, e.items.size());
        if (head.length() == 1 && "+-*/".indexOf(head.charAt(0)) >= 0) {
            char op = head.charAt(0);
            if (op == '-' && args.size() == 1) return new NumericExpr.Negation(numericExpr(args.get(0)));
            boolean nary = op == '+' || op == '*';
            if (args.size() < 2 || !nary && args.size() != 2) {
                throw err(e, "'" + head + "' takes " + (nary ? "two or more" : op == '-' ? "one or two" : "two") + " numeric expressions");
            }
            NumericExpr result = numericExpr(args.get(0));
            for (SExpr a : args.subList(1, args.size())) {
                NumericExpr right = numericExpr(a);
                if (op == '/' && right instanceof NumericExpr.Number z && z.value() == 0) throw err(a, "division by zero: '(/ ... 0)'");
                result = new NumericExpr.Arithmetic(op, result, right);
            }
            return result;
        }
        if (head.startsWith("?") || head.startsWith(":")) throw err(e.items.get(0), "expected a function name, found '" + head + "'");
        List<String> terms = new ArrayList<>();
        for (SExpr a : args) terms.add(name(a, "a term (object or variable)"));
        return new NumericExpr.Fluent(head, terms);
    }

    private NumericTerm numeric(SExpr e) {
        if (!e.isList()) {
            try {
                if (!isNumber(e.symbol)) throw new NumberFormatException(e.symbol);
                double v = Double.parseDouble(e.symbol);
                if (!Double.isFinite(v)) throw err(e, "'" + e.symbol + "' is not a finite number");
                return new NumericTerm.Constant(v);
            } catch (NumberFormatException ex) {
                throw err(e, "expected a number or a function term, found '" + e.symbol + "'");
            }
        }
        if (e.items.isEmpty()) throw err(e, "empty function term");
        List<String> args = new ArrayList<>();
        for (SExpr a : e.items.subList(1, e.items.size())) args.add(name(a, "a term"));
        return new NumericTerm.Function(name(e.items.get(0), "a function name"), args);
    }

    private Problem problem(SExpr root) {
        List<SExpr> items = header(root, "problem");
        String name = name(items.get(1).items.get(1), "a problem name");
        String domainName = null;
        List<TypedName> objects = new ArrayList<>();
        List<Formula.Atom> init = new ArrayList<>();
        List<Problem.NumericFact> numeric = new ArrayList<>();
        Formula goal = null;
        String metric = null;
        for (SExpr sec : items.subList(2, items.size())) {
            String head = sec.head();
            if (head == null) throw err(sec, "expected a problem section such as '(:init ...)'");
            List<SExpr> rest = sec.items.subList(1, sec.items.size());
            switch (head) {
                case ":domain" -> {
                    if (rest.size() != 1) throw err(sec, "expected '(:domain NAME)'");
                    domainName = name(rest.get(0), "a domain name");
                }
                case ":requirements" -> requirements(rest);
                case ":objects" -> objects.addAll(typedList(rest, "object", false));
                case ":init" -> {
                    for (SExpr f : rest) {
                        if ("=".equals(f.head())) {
                            if (f.items.size() != 3) throw err(f, "expected '(= (FUNCTION ARGS) NUMBER)'");
                            NumericTerm t = numeric(f.items.get(1));
                            NumericTerm v = numeric(f.items.get(2));
                            if (!(t instanceof NumericTerm.Function fn) || !(v instanceof NumericTerm.Constant c)) {
                                throw err(f, "expected '(= (FUNCTION ARGS) NUMBER)'");
                            }
                            numeric.add(new Problem.NumericFact(fn.name(), fn.args(), c.value()));
                            continue;
                        }
                        Formula a = formula(f);
                        if (!(a instanceof Formula.Atom atom)) throw err(f, "the initial state lists ground atoms only");
                        for (String t : atom.args()) {
                            if (t.startsWith("?")) throw err(f, "variable '" + t + "' in the initial state");
                        }
                        init.add(atom);
                    }
                }
                case ":goal" -> {
                    if (rest.size() != 1) throw err(sec, "expected '(:goal FORMULA)'");
                    goal = formula(rest.get(0));
                }
                case ":metric" -> {
                    metric(sec, rest); // checked here, so that a bad metric is an error at its place
                    StringBuilder sb = new StringBuilder();
                    for (SExpr r : rest) sb.append(sb.length() > 0 ? " " : "").append(r);
                    metric = sb.toString();
                }
                default -> throw err(sec, "unknown problem section '" + head + "'");
            }
        }
        if (domainName == null) throw err(root, "missing '(:domain NAME)'");
        if (goal == null) throw err(root, "missing '(:goal ...)'");
        return new Problem(name, domainName, objects, init, numeric, goal, metric);
    }
}
