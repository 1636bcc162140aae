// The org.triad.models Gradle plugin (mirrors gradle-plugin/pom.xml) and the toolchain's shared conventions.
// src/main/resources/META-INF/gradle-plugins/org.triad.models.properties declares the plugin id.
plugins {
    `java-library`
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
    compileOnly(gradleApi())
    testImplementation(gradleApi())
}

tasks.test {
    // what Gradle's ProjectBuilder needs (it defines classes in the JDK's loaders)
    jvmArgs("--add-opens=java.base/java.lang=ALL-UNNAMED")
    // HospitalGradleBuildIT compares with the Maven build's output and runs the Gradle assembled by Maven
    exclude("**/*IT.class")
}
