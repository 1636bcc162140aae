'use strict';
const test = require('node:test');
const assert = require('node:assert');
const path = require('path');
const { findJava, javaMajorVersion, serverCommand } = require('../lib/launch');

const JDK17 = 'openjdk version "17.0.13" 2024-10-15\nOpenJDK Runtime Environment';
const files = (...present) => (f) => present.includes(f);

test('the triad.java.home setting wins over JAVA_HOME and the PATH', () => {
  const found = findJava({ javaHomeSetting: '/opt/jdk', env: { JAVA_HOME: '/usr/jdk', PATH: '/bin' }, platform: 'linux',
    exists: files('/opt/jdk/bin/java', '/usr/jdk/bin/java', '/bin/java') });
  assert.deepStrictEqual(found, { java: path.join('/opt/jdk', 'bin', 'java'), source: "the setting 'triad.java.home'" });
});

test('JAVA_HOME comes next, then the first java on the PATH', () => {
  assert.strictEqual(findJava({ env: { JAVA_HOME: '/usr/jdk', PATH: '/bin' }, platform: 'linux', exists: files('/usr/jdk/bin/java', '/bin/java') }).source, 'JAVA_HOME');
  const onPath = findJava({ env: { PATH: '/nope:/usr/local/bin:/bin' }, platform: 'linux', exists: files('/usr/local/bin/java', '/bin/java') });
  assert.deepStrictEqual(onPath, { java: path.join('/usr/local/bin', 'java'), source: 'the PATH' });
});

test('Windows looks for java.exe and splits the PATH on semicolons', () => {
  const found = findJava({ env: { Path: 'C:\\a;C:\\jdk\\bin' }, platform: 'win32', exists: files(path.join('C:\\jdk\\bin', 'java.exe')) });
  assert.strictEqual(found.java, path.join('C:\\jdk\\bin', 'java.exe'));
});

test('a setting or JAVA_HOME without java is reported, not skipped', () => {
  assert.match(findJava({ javaHomeSetting: '/opt/none', env: { PATH: '/bin' }, platform: 'linux', exists: files('/bin/java') }).error,
    /'triad\.java\.home' is \/opt\/none/);
  assert.match(findJava({ env: { JAVA_HOME: '/opt/none', PATH: '/bin' }, platform: 'linux', exists: files('/bin/java') }).error, /JAVA_HOME is \/opt\/none/);
});

test('no java anywhere gives a message that says what to do', () => {
  const r = serverCommand({ env: { PATH: '/bin' }, platform: 'linux', exists: files(), jar: '/x.jar', javaVersion: () => JDK17 });
  assert.match(r.error, /needs Java 17 or later, and none was found: set 'triad\.java\.home'.*JAVA_HOME.*PATH/);
});

test('java versions are read from java -version, old and new style', () => {
  assert.strictEqual(javaMajorVersion(JDK17), 17);
  assert.strictEqual(javaMajorVersion('java version "1.8.0_392"'), 8);
  assert.strictEqual(javaMajorVersion('openjdk version "21" 2023-09-19'), 21);
  assert.strictEqual(javaMajorVersion('garbage'), null);
});

test('a Java older than 17, or one that does not run, is refused with its version and origin', () => {
  const base = { env: { PATH: '/bin' }, platform: 'linux', exists: files('/bin/java', '/x.jar'), jar: '/x.jar' };
  assert.match(serverCommand({ ...base, javaVersion: () => 'java version "1.8.0_392"' }).error, /\/bin\/java \(from the PATH\) is Java 8; .* needs Java 17/);
  assert.match(serverCommand({ ...base, javaVersion: () => null }).error, /did not run/);
});

test('the command is java, the VM options, then -jar and the jar; a missing jar is reported', () => {
  const ok = serverCommand({ env: { PATH: '/bin' }, platform: 'linux', exists: files('/bin/java', '/ext/server/s.jar'), jar: '/ext/server/s.jar',
    vmargs: ['-Xmx1g'], javaVersion: () => JDK17 });
  assert.deepStrictEqual([ok.command, ...ok.args], [path.join('/bin', 'java'), '-Xmx1g', '-jar', '/ext/server/s.jar']);
  const missing = serverCommand({ env: { PATH: '/bin' }, platform: 'linux', exists: files('/bin/java'), jar: '/ext/server/s.jar', javaVersion: () => JDK17 });
  assert.match(missing.error, /jar \/ext\/server\/s\.jar does not exist/);
});
