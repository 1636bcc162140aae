// The org.triad.models Gradle plugin (mirrors gradle-plugin/pom.xml) and the toolchain's shared conventions.
plugins {
    `java-gradle-plugin` // declares the plugin id to the including build, adds gradleApi(), validates the task's annotations
}

val triadVersion: String by project

allprojects {
    group = "org.triad"
    version = triadVersion
    apply(plugin = "java-library")
    tasks.withType<JavaCompile>().configureEach {
        options.encoding = "UTF-8"
        options.release.set(17)
    }
    dependencies {
        "testImplementation"(platform("org.junit:junit-bom:5.10.2"))
        "testImplementation"("org.junit.jupiter:junit-jupiter")
        "testRuntimeOnly"("org.junit.platform:junit-platform-launcher")
    }
    tasks.withType<Test>().configureEach {
        useJUnitPlatform()
    }
}

dependencies {
    api(project(":triad-generator"))
}

gradlePlugin {
    plugins {
        create("triadModels") {
            id = "org.triad.models"
            implementationClass = "org.triad.gradle.TriadModelsPlugin"
        }
    }
}

// src/main/resources has the same plugin descriptor for the Maven build
tasks.withType<Jar>().configureEach { duplicatesStrategy = DuplicatesStrategy.EXCLUDE }
tasks.processResources { duplicatesStrategy = DuplicatesStrategy.EXCLUDE }

tasks.test {
    // what Gradle's ProjectBuilder needs (it defines classes in the JDK's loaders)
    jvmArgs("--add-opens=java.base/java.lang=ALL-UNNAMED")
    // these compare with the Maven build's output (HospitalGradleBuildIT also runs the Gradle Maven assembles)
    exclude("**/*IT.class")
    filter {
        excludeTestsMatching("*.GenerateModelsTest.theHospitalGeneratesExactlyWhatItsMavenBuildGenerates")
        excludeTestsMatching("*.RefArcGradleGenerationTest")
    }
}
