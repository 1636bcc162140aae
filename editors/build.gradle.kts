// mirrors editors/pom.xml: the language server as one self-contained jar, build/libs/triad-language-server.jar
// (`gradle :editors:languageServerJar`), which the VS Code extension bundles and the editor recipes start
// with java -jar; the recipes' *IT tests run against that jar
plugins {
    java
}

val triadVersion: String by project

dependencies {
    implementation("org.triad:triad-dsl:$triadVersion")
}

val runtimeJars = configurations.runtimeClasspath
val mergedResources = layout.buildDirectory.dir("language-server-merged")

// what maven-shade's ServicesResourceTransformer and AppendingTransformer do: every language registers
// its setup as a service, and EMF reads every bundle's messages from one plugin.properties
val mergeLanguageServerResources by tasks.registering {
    description = "Concatenates the dependencies' META-INF/services files and plugin.properties."
    inputs.files(runtimeJars)
    outputs.dir(mergedResources)
    doLast {
        val out = mergedResources.get().asFile
        out.deleteRecursively()
        val merged = sortedMapOf<String, StringBuilder>()
        runtimeJars.get().filter { it.isFile }.forEach { jar ->
            java.util.zip.ZipFile(jar).use { zip ->
                zip.entries().asSequence()
                    .filter { !it.isDirectory && (it.name.startsWith("META-INF/services/") || it.name == "plugin.properties") }
                    .forEach { e -> merged.getOrPut(e.name) { StringBuilder() }.append(zip.getInputStream(e).reader().readText()).append('\n') }
            }
        }
        merged.forEach { (name, text) -> out.resolve(name).apply { parentFile.mkdirs(); writeText(text.toString()) } }
    }
}

val languageServerJar by tasks.registering(Jar::class) {
    description = "The language server and all it needs in one jar."
    archiveFileName.set("triad-language-server.jar")
    manifest {
        attributes(
            "Main-Class" to "org.triad.dsl.ide.server.TriadLanguageServerMain",
            "Implementation-Title" to "Triad language server",
            "Implementation-Version" to project.version,
        )
    }
    from(mergeLanguageServerResources)
    from(runtimeJars.map { jars -> jars.map { if (it.isDirectory) it else zipTree(it) } }) {
        exclude("META-INF/services/**", "plugin.properties", "META-INF/MANIFEST.MF", "META-INF/*.SF", "META-INF/*.DSA", "META-INF/*.RSA",
            "META-INF/versions/*/module-info.class", "module-info.class", "about.html", "about_files/**", "plugin.xml",
            ".api_description", ".options")
    }
    duplicatesStrategy = DuplicatesStrategy.EXCLUDE
}

tasks.test {
    dependsOn(languageServerJar)
    systemProperty("triad.serverJar", languageServerJar.get().archiveFile.get().asFile.absolutePath)
    systemProperty("triad.editors", projectDir.absolutePath)
    include("**/*IT.class") // as Maven's failsafe: the recipes' launch commands against the packaged jar
}
