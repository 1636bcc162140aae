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
    api(project(":vda5050")) // the hospital as VDA 5050 robots on a broker (package vda5050)
    implementation("info.picocli:picocli:4.7.6") // HospitalDemo's options (./triad demo launches it)
}

triad {
    // the architecture extends RefArc, whose .arc models it links against
    architectureLibraries.from(rootProject.file("refarc/src/main/arc"))
}

tasks.withType<JavaCompile>().configureEach {
    options.compilerArgs.addAll(listOf("-Xlint:all", "-Werror")) // generated code compiles without warnings
}
