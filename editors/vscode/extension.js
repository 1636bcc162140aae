'use strict';
// The Triad extension: languages, grammars and snippets come from package.json; this starts the
// bundled Triad language server (java -jar) and connects VS Code to it.

const fs = require('fs');
const { spawnSync } = require('child_process');
const vscode = require('vscode');
const { LanguageClient, TransportKind } = require('vscode-languageclient/node');
const { serverCommand } = require('./lib/launch');

const LANGUAGES = ['cd', 'actor', 'goal', 'task', 'state', 'arc'].map((ext) => `triad-${ext}`);

let client;

async function activate(context) {
  const config = vscode.workspace.getConfiguration('triad');
  const plan = serverCommand({
    javaHomeSetting: config.get('java.home'),
    env: process.env,
    platform: process.platform,
    exists: (file) => fs.existsSync(file),
    jar: config.get('server.jar') || context.asAbsolutePath('server/triad-language-server.jar'),
    vmargs: config.get('server.vmargs'),
    javaVersion: (java) => {
      const r = spawnSync(java, ['-version'], { encoding: 'utf8', timeout: 20000 });
      return r.error ? null : `${r.stderr}${r.stdout}`;
    },
  });
  if (plan.error) {
    vscode.window.showErrorMessage(plan.error);
    return;
  }
  const serverOptions = { command: plan.command, args: plan.args, transport: TransportKind.stdio };
  const clientOptions = {
    documentSelector: LANGUAGES.map((language) => ({ scheme: 'file', language })),
    outputChannelName: 'Triad',
  };
  client = new LanguageClient('triad', 'Triad language server', serverOptions, clientOptions);
  context.subscriptions.push(client);
  await client.start();
}

async function deactivate() {
  if (client) {
    await client.stop();
  }
}

module.exports = { activate, deactivate };
