'use strict';
// The extension's start-up logic on this machine: it finds java as the extension would (JAVA_HOME,
// else the PATH), starts the bundled server jar with the command it builds, and the server
// answers initialize and checks an opened model.
const test = require('node:test');
const assert = require('node:assert');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { spawn, spawnSync } = require('child_process');
const { pathToFileURL } = require('url');
const rpc = require('vscode-jsonrpc/node');
const { serverCommand } = require('../lib/launch');

const jar = path.join(__dirname, '..', 'server', 'triad-language-server.jar');

test('the bundled server starts with the extension\'s command, answers initialize and publishes diagnostics', { timeout: 120000 }, async () => {
  const plan = serverCommand({
    env: process.env, platform: process.platform, exists: fs.existsSync, jar, vmargs: ['-Xmx512m'],
    javaVersion: (java) => { const r = spawnSync(java, ['-version'], { encoding: 'utf8' }); return r.error ? null : r.stderr + r.stdout; },
  });
  assert.ok(!plan.error, plan.error);
  const workspace = fs.mkdtempSync(path.join(os.tmpdir(), 'triad-vscode-'));
  fs.writeFileSync(path.join(workspace, 'Shop.cd'), 'classdiagram Shop {\n  class Place;\n}\n');
  const server = spawn(plan.command, plan.args, { stdio: ['pipe', 'pipe', 'ignore'] });
  const connection = rpc.createMessageConnection(new rpc.StreamMessageReader(server.stdout), new rpc.StreamMessageWriter(server.stdin));
  const diagnostics = new Promise((resolve) => connection.onNotification('textDocument/publishDiagnostics', (p) => {
    if (p.uri.endsWith('/At.goal') && p.diagnostics.length > 0) resolve(p.diagnostics);
  }));
  connection.listen();
  try {
    const init = await connection.sendRequest('initialize', { processId: process.pid, rootUri: pathToFileURL(workspace).href, capabilities: {} });
    assert.strictEqual(init.capabilities.hoverProvider, true);
    assert.ok(init.capabilities.semanticTokensProvider.legend.tokenTypes.includes('property'));
    connection.sendNotification('initialized', {});
    const uri = pathToFileURL(path.join(workspace, 'At.goal')).href;
    connection.sendNotification('textDocument/didOpen', { textDocument: { uri, languageId: 'triad-goal', version: 1, text: 'domain Shop;\n\ngoal At(Plac p) {\n  true\n}\n' } });
    const found = await diagnostics;
    assert.strictEqual(found[0].code, 'link.unknown-type');
    await connection.sendRequest('shutdown');
    const exited = new Promise((resolve) => server.on('exit', resolve));
    connection.sendNotification('exit');
    await exited;
  } finally {
    connection.dispose();
    server.kill();
    fs.rmSync(workspace, { recursive: true, force: true });
  }
});
