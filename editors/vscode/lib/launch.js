'use strict';
// How the extension starts the Triad language server: which java, which jar, which arguments.
// Kept free of the 'vscode' module so that Node's test runner can check it on its own.

const path = require('path');

const MIN_JAVA = 17;

/** The java executable inside a Java installation folder. */
function javaIn(home, platform) {
  return path.join(home, 'bin', platform === 'win32' ? 'java.exe' : 'java');
}

/**
 * Finds java: the 'triad.java.home' setting, else JAVA_HOME, else 'java' on the PATH.
 * Returns { java, source } or { error }. A setting or JAVA_HOME that names no Java is an error
 * rather than silently skipped: the user asked for that Java.
 */
function findJava({ javaHomeSetting, env, platform, exists }) {
  if (javaHomeSetting) {
    const java = javaIn(javaHomeSetting, platform);
    return exists(java) ? { java, source: "the setting 'triad.java.home'" }
      : { error: `The setting 'triad.java.home' is ${javaHomeSetting}, but ${java} does not exist.` };
  }
  if (env.JAVA_HOME) {
    const java = javaIn(env.JAVA_HOME, platform);
    return exists(java) ? { java, source: 'JAVA_HOME' }
      : { error: `JAVA_HOME is ${env.JAVA_HOME}, but ${java} does not exist. Fix JAVA_HOME or set 'triad.java.home'.` };
  }
  const dirs = (env.PATH || env.Path || '').split(platform === 'win32' ? ';' : ':').filter(Boolean);
  for (const dir of dirs) {
    const java = path.join(dir, platform === 'win32' ? 'java.exe' : 'java');
    if (exists(java)) {
      return { java, source: 'the PATH' };
    }
  }
  return { error: `The Triad language server needs Java ${MIN_JAVA} or later, and none was found: set 'triad.java.home' to a Java installation, set JAVA_HOME, or put java on the PATH.` };
}

/** The major version from `java -version` output ('openjdk version "17.0.9"', 'java version "1.8.0_392"'), or null. */
function javaMajorVersion(versionOutput) {
  const m = /version "(\d+)(?:\.(\d+))?/.exec(versionOutput || '');
  if (!m) {
    return null;
  }
  const first = Number(m[1]);
  return first === 1 && m[2] ? Number(m[2]) : first;
}

/**
 * The command that starts the server, or { error } with a message for the user.
 * options: javaHomeSetting, env, platform, exists(file), jar (path), vmargs (array),
 * javaVersion(java) -> output of `java -version` (stderr), or null when it cannot run.
 */
function serverCommand(options) {
  const found = findJava(options);
  if (found.error) {
    return { error: found.error };
  }
  const version = javaMajorVersion(options.javaVersion(found.java));
  if (version === null) {
    return { error: `${found.java} (from ${found.source}) did not run: the Triad language server needs Java ${MIN_JAVA} or later.` };
  }
  if (version < MIN_JAVA) {
    return { error: `${found.java} (from ${found.source}) is Java ${version}; the Triad language server needs Java ${MIN_JAVA} or later.` };
  }
  if (!options.exists(options.jar)) {
    return { error: `The Triad language server jar ${options.jar} does not exist: reinstall the extension or fix the setting 'triad.server.jar'.` };
  }
  return { command: found.java, args: [...(options.vmargs || []), '-jar', options.jar], source: found.source };
}

module.exports = { findJava, javaMajorVersion, serverCommand, MIN_JAVA };
