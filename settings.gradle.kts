// The Gradle build beside the Maven reactor (pom.xml), for users who build with Gradle 8: the same modules.
// Tested here: the Maven build (`mvn -B verify`), which also runs the org.triad.models plugin in a real
// Gradle 8.10 (gradle-plugin/, HospitalGradleBuildIT, on a Groovy twin of models/hospital's build). These
// Kotlin scripts are not run here: no registry these machines reach has Gradle's Kotlin DSL (see README, "Gradle").
pluginManagement {
    // org.triad.models, built together with the toolchain it runs (gradle-plugin/settings.gradle.kts)
    includeBuild("gradle-plugin")
    // where the plugin's own dependencies (Xtext, EMF, ...) come from: Maven Central, not the plugin portal
    repositories {
        mavenCentral()
    }
}

dependencyResolutionManagement {
    repositories {
        mavenCentral()
    }
}

rootProject.name = "triad"

// the toolchain (planner, runtime, dsl, refarc, generator) lives in the plugin's build; its projects
// stand in for the org.triad:triad-* dependencies of the projects below
includeBuild("gradle-plugin")

include("pddl4j", "archetype", "building", "sim", "vda5050", "service", "cli", "editors", "tests", "fuzz")
include("models:logistics", "models:hospital")
