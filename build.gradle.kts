// Conventions of every project in this build; mirrors the parent pom.xml (Java 17, UTF-8, JUnit 5).
val triadVersion: String by project

allprojects {
    group = "org.triad"
    version = triadVersion
}

subprojects {
    pluginManager.withPlugin("java") {
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
}
