// mirrors generator/pom.xml: the templates are Xtend, compiled by Xtend's batch compiler (Maven Central,
// as xtend-maven-plugin does) into build/xtend-gen before javac
val xtextVersion: String by project

val xtend: Configuration by configurations.creating

dependencies {
    api(project(":triad-dsl"))
    api(project(":triad-runtime"))
    api("org.eclipse.xtext:org.eclipse.xtend.lib:$xtextVersion")
    xtend("org.eclipse.xtext:org.eclipse.xtend.core:$xtextVersion")
}

fun xtendTask(sourceSet: SourceSet, classpath: FileCollection) = tasks.register<JavaExec>("xtend" + sourceSet.name.replaceFirstChar { it.uppercase() }) {
    val out = layout.buildDirectory.dir("xtend-gen/${sourceSet.name}")
    description = "Compiles the ${sourceSet.name} Xtend sources to Java."
    mainClass.set("org.eclipse.xtend.core.compiler.batch.Main")
    this.classpath = xtend
    val sources = sourceSet.java.srcDirs.filter { it.exists() }
    inputs.files(sources.map { fileTree(it) { include("**/*.xtend") } })
    inputs.files(classpath)
    outputs.dir(out)
    argumentProviders.add(CommandLineArgumentProvider {
        listOf("-d", out.get().asFile.absolutePath, "-javaSourceVersion", "17", "-encoding", "UTF-8",
            "-cp", classpath.asPath, "-tempdir", temporaryDir.absolutePath) + sources.map { it.absolutePath }
    })
}

val xtendMain = xtendTask(sourceSets.main.get(), configurations.compileClasspath.get())
val xtendTest = xtendTask(sourceSets.test.get(), configurations.testCompileClasspath.get() + sourceSets.main.get().output)
sourceSets.main { java.srcDir(xtendMain) }
sourceSets.test { java.srcDir(xtendTest) }
