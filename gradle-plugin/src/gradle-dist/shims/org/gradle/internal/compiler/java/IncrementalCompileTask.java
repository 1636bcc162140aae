package org.gradle.internal.compiler.java;

import java.util.Locale;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.function.Function;

import javax.annotation.processing.Processor;
import javax.tools.JavaCompiler;

/** Compiles without reporting Gradle's incremental-compilation facts (full recompilation instead). */
public class IncrementalCompileTask implements JavaCompiler.CompilationTask {
	private final JavaCompiler.CompilationTask delegate;

	public IncrementalCompileTask(JavaCompiler.CompilationTask delegate, Function<?, ?> relativize, Consumer<?> backup, Consumer<?> classes,
			BiConsumer<?, ?> publicConstants, BiConsumer<?, ?> privateConstants) {
		this.delegate = delegate;
	}

	@Override
	public void addModules(Iterable<String> moduleNames) {
		delegate.addModules(moduleNames);
	}

	@Override
	public void setProcessors(Iterable<? extends Processor> processors) {
		delegate.setProcessors(processors);
	}

	@Override
	public void setLocale(Locale locale) {
		delegate.setLocale(locale);
	}

	@Override
	public Boolean call() {
		return delegate.call();
	}
}
