package org.triad.refarc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Proxy;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import org.eclipse.emf.ecore.resource.Resource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.arc.ArcModel;
import org.triad.dsl.arc.ComponentType;
import org.triad.generator.arc.ArcGenerator;
import org.triad.generator.arc.ArcNames;

/**
 * The architecture generator's output for src/main/arc, freshly generated here (independently of
 * the build's copy in target/generated-sources), compiles with the hand-written behavior classes
 * against the runtime alone, and the generated compositions build the parts and connections their
 * models declare.
 */
class GeneratedArchitectureTest {
    private static final Path MODELS = Path.of("src/main/arc");
    private static final Path SOURCES = Path.of("src/main/java");

    @TempDir
    Path work;

    @Test
    void generatedClassesReplaceTheStandInsAndRun() throws Exception {
        LoadedApplication app = ApplicationAssembler.load(MODELS);
        assertEquals("", app.diagnostics().stream().map(d -> d.format(app.root())).collect(Collectors.joining("\n")));
        Map<String, String> generated = new LinkedHashMap<>();
        ArcGenerator generator = new ArcGenerator(new ArcNames());
        Map<String, ComponentType> components = new LinkedHashMap<>();
        for (Resource r : app.resourceSet().getResources()) {
            if (!r.getContents().isEmpty() && r.getContents().get(0) instanceof ArcModel m) {
                generated.putAll(generator.files(m.getComponent()));
                components.put(m.getComponent().getName(), m.getComponent());
            }
        }
        assertEquals(new TreeSet<>(List.of("org/triad/refarc/ActionExecutorTOP.java", "org/triad/refarc/ControllerTOP.java",
                "org/triad/refarc/OpenRefArc.java", "org/triad/refarc/PlanVerifierTOP.java", "org/triad/refarc/PlannerTOP.java",
                "org/triad/refarc/RefArc.java", "org/triad/refarc/RemoteOperatorTOP.java", "org/triad/refarc/StateProviderTOP.java")),
                new TreeSet<>(generated.keySet()));

        List<File> sources = new ArrayList<>();
        Path gen = work.resolve("generated");
        for (Map.Entry<String, String> e : generated.entrySet()) {
            Path file = gen.resolve(e.getKey());
            Files.createDirectories(file.getParent());
            Files.writeString(file, e.getValue());
            sources.add(file.toFile());
        }
        try (Stream<Path> walk = Files.walk(SOURCES)) {
            walk.filter(p -> p.toString().endsWith(".java"))
                    .filter(p -> !generated.containsKey(SOURCES.relativize(p).toString().replace(File.separatorChar, '/')))
                    .forEach(p -> sources.add(p.toFile()));
        }
        Path classes = Files.createDirectories(work.resolve("classes"));
        List<String> classpath = classpathWithoutRefArc();
        compile(sources, classes, classpath);

        List<URL> urls = new ArrayList<>();
        urls.add(classes.toUri().toURL());
        for (String entry : classpath) {
            urls.add(Path.of(entry).toUri().toURL());
        }
        try (URLClassLoader loader = new URLClassLoader(urls.toArray(URL[]::new), ClassLoader.getPlatformClassLoader())) {
            for (String composed : List.of("RefArc", "OpenRefArc")) {
                Object instance = instantiate(loader.loadClass("org.triad.refarc." + composed));
                assertEquals(modelSubcomponents(components.get(composed)), subcomponents(instance), composed + ": subcomponents");
                assertEquals(modelConnectors(components.get(composed)), connectors(instance), composed + ": connectors");
            }
        }
    }

    private static void compile(List<File> sources, Path classes, List<String> classpath) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, Locale.ROOT, null)) {
            List<String> options = List.of("-d", classes.toString(), "-classpath", String.join(File.pathSeparator, classpath),
                    "--release", "17", "-proc:none");
            boolean ok = javac.getTask(null, files, diagnostics, options, null, files.getJavaFileObjectsFromFiles(sources)).call();
            String errors = diagnostics.getDiagnostics().stream().filter(d -> d.getKind() == Diagnostic.Kind.ERROR)
                    .map(d -> d.getSource() + ":" + d.getLineNumber() + ": " + d.getMessage(Locale.ROOT)).collect(Collectors.joining("\n"));
            assertEquals("", errors);
            assertTrue(ok);
        }
    }

    /** The test's classpath without this module's own classes (nor the build's generated copy), so only this test's output is used. */
    private static List<String> classpathWithoutRefArc() {
        Path own = Path.of("target").toAbsolutePath().normalize();
        return Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
                .filter(e -> !e.isBlank())
                .filter(e -> !Path.of(e).toAbsolutePath().normalize().startsWith(own))
                .toList();
    }

    /** Calls the only constructor with do-nothing implementations of its (functional interface) parameters. */
    private static Object instantiate(Class<?> type) throws ReflectiveOperationException {
        Constructor<?> c = type.getConstructors()[0];
        Object[] args = new Object[c.getParameterCount()];
        for (int i = 0; i < args.length; i++) {
            Class<?> p = c.getParameterTypes()[i];
            args[i] = Proxy.newProxyInstance(type.getClassLoader(), new Class<?>[] { p }, (proxy, method, a) -> {
                throw new UnsupportedOperationException(method.getName());
            });
        }
        return c.newInstance(args);
    }

    private static TreeSet<String> modelSubcomponents(ComponentType c) {
        return org.triad.dsl.semantics.ArcModels.subcomponents(c).stream().map(s -> org.triad.dsl.semantics.ArcModels.type(s).getName() + " " + s.getName())
                .collect(Collectors.toCollection(TreeSet::new));
    }

    private static TreeSet<String> modelConnectors(ComponentType c) {
        TreeSet<String> result = new TreeSet<>();
        c.getConnectors().forEach(con -> con.getTargets().forEach(t -> result.add(text(con.getSource()) + " -> " + text(t))));
        return result;
    }

    private static String text(org.triad.dsl.arc.PortRef ref) {
        if (ref.isFaults()) {
            return "faults";
        }
        return (ref.getSubcomponent() == null ? "" : ref.getSubcomponent().getName() + ".") + ref.getPort().getName();
    }

    private static TreeSet<String> subcomponents(Object composed) throws ReflectiveOperationException {
        TreeSet<String> result = new TreeSet<>();
        for (Object sub : (List<?>) call(composed, "subcomponents")) {
            result.add(sub.getClass().getSimpleName() + " " + call(sub, "name"));
        }
        return result;
    }

    /** Connections read back from the runtime objects: from in ports of the composition and out ports of its parts. */
    private static TreeSet<String> connectors(Object composed) throws ReflectiveOperationException {
        List<Object[]> sources = new ArrayList<>(); // {owner label prefix, port}
        for (Object p : (List<?>) call(composed, "ports")) {
            if (p.getClass().getSimpleName().equals("InPort")) {
                sources.add(new Object[] { "", p });
            }
        }
        for (Object sub : (List<?>) call(composed, "subcomponents")) {
            for (Object p : (List<?>) call(sub, "ports")) {
                if (p.getClass().getSimpleName().equals("OutPort")) {
                    sources.add(new Object[] { call(sub, "name") + ".", p });
                }
            }
        }
        TreeSet<String> result = new TreeSet<>();
        for (Object[] s : sources) {
            for (Object to : (Iterable<?>) call(s[1], "targets")) {
                Object owner = call(to, "owner");
                String target = owner == composed ? (String) call(to, "name") : call(owner, "name") + "." + call(to, "name");
                result.add(s[0] + (String) call(s[1], "name") + " -> " + target);
            }
        }
        return result;
    }

    private static Object call(Object target, String method) throws ReflectiveOperationException {
        Class<?> c = target.getClass();
        while (c != null) {
            for (var m : c.getDeclaredMethods()) {
                if (m.getName().equals(method) && m.getParameterCount() == 0) {
                    m.setAccessible(true);
                    return m.invoke(target);
                }
            }
            c = c.getSuperclass();
        }
        throw new NoSuchMethodException(target.getClass() + "." + method);
    }
}
