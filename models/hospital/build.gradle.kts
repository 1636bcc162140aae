// mirrors models/hospital/pom.xml: the hospital application. generateModels (plugin org.triad.models)
// checks src/main/models and src/main/arc and generates their Java into build/generated/sources/triad.
plugins {
    id("org.triad.models")
    `java-library`
}

val triadVersion: String by project

dependencies {
    api("org.triad:triad-runtime:$triadVersion")
    api("org.triad:triad-refarc:$triadVersion")
    api(project(":sim"))
}

triad {
    // the architecture extends RefArc, whose .arc models it links against
    architectureLibraries.from(rootProject.file("refarc/src/main/arc"))
    architecturePackage.set("org.triad")
}

tasks.withType<JavaCompile>().configureEach {
    options.compilerArgs.addAll(listOf("-Xlint:all", "-Werror")) // generated code compiles without warnings
}
