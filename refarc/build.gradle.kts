// mirrors refarc/pom.xml: RefArc's components are generated from src/main/arc by the architecture generator
// of generator/ (Maven: xtext-maven-plugin with ArcJavaGeneratorSetup; here its program ArcJavaGeneratorMain,
// the same ArcGenerator): a TOP class for each component with a hand-written class in src/main/java
val architectureGenerator: Configuration by configurations.creating

dependencies {
    api(project(":triad-runtime"))
    architectureGenerator(project(":triad-generator"))
    testImplementation(project(":triad-generator")) // GeneratedArchitectureTest runs the generator afresh
}

val generatedArchitecture = layout.buildDirectory.dir("generated/sources/arc")

val generateArchitecture by tasks.registering(JavaExec::class) {
    description = "Generates the Java of RefArc's .arc models."
    mainClass.set("org.triad.generator.arc.ArcJavaGeneratorMain")
    classpath = architectureGenerator
    args("src/main/arc", generatedArchitecture.get().asFile.absolutePath)
    inputs.dir("src/main/arc")
    inputs.dir("src/main/java") // which components have a hand-written class decides TOP or not
    outputs.dir(generatedArchitecture)
}

sourceSets.main {
    java.srcDir(generateArchitecture.map { generatedArchitecture.get() })
}

tasks.processResources {
    // RefArc's component models ship in the jar (triad-models/org/triad/refarc/*.arc), as Maven's
    // <resource> with <targetPath>triad-models</targetPath>: applications' architectures link against them
    from("src/main/arc") { into("triad-models") }
}
