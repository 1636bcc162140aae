package org.gradle.internal.installation.beacon;

/**
 * The class of the module {@code gradle-installation-beacon}, which gradle-api lacks: Gradle finds its
 * installation through the jar this class is in, and {@code gradleApi()} asks for the module by name.
 */
public final class InstallationBeacon {
	private InstallationBeacon() {
	}
}
