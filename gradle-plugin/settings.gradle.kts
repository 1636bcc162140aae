// The org.triad.models plugin and the toolchain it runs, as one Gradle build: the root build includes it
// for the plugin and for its org.triad:triad-* libraries. Project names are the Maven artifactIds, so
// Gradle substitutes them for those dependencies in the including build.
dependencyResolutionManagement {
    repositories {
        mavenCentral()
    }
}

rootProject.name = "triad-gradle-plugin"

for ((project, folder) in listOf(
    "triad-planner" to "planner",
    "triad-runtime" to "runtime",
    "triad-dsl" to "dsl",
    "triad-refarc" to "refarc",
    "triad-generator" to "generator",
)) {
    include(project)
    project(":$project").projectDir = file("../$folder")
}
