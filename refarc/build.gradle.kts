// mirrors refarc/pom.xml: RefArc's components are generated from src/main/arc (ArcGeneratorMain of the dsl)
val architectureGenerator: Configuration by configurations.creating

dependencies {
    api(project(":triad-runtime"))
    architectureGenerator(project(":triad-dsl"))
    testImplementation(project(":triad-dsl"))
}

val generatedArchitecture = layout.buildDirectory.dir("generated/sources/arc")

val generateArchitecture by tasks.registering(JavaExec::class) {
    description = "Generates the Java of RefArc's .arc models."
    mainClass.set("org.triad.dsl.arc.generator.ArcGeneratorMain")
    classpath = architectureGenerator
    args("src/main/arc", generatedArchitecture.get().asFile.absolutePath, "org.triad")
    inputs.dir("src/main/arc")
    outputs.dir(generatedArchitecture)
}

sourceSets.main {
    java.srcDir(generateArchitecture.map { generatedArchitecture.get() })
}
