'use strict';
const test = require('node:test');
const assert = require('node:assert');
const fs = require('fs');
const path = require('path');

const root = path.join(__dirname, '..');
const pkg = require('../package.json');
const KINDS = ['cd', 'actor', 'goal', 'task', 'state', 'arc'];

test('each of the six model kinds has a language, a grammar and snippets', () => {
  assert.deepStrictEqual(pkg.contributes.languages.map((l) => l.extensions).flat(), KINDS.map((k) => `.${k}`));
  for (const kind of KINDS) {
    const id = `triad-${kind}`;
    const grammar = pkg.contributes.grammars.find((g) => g.language === id);
    assert.ok(grammar, `grammar for ${id}`);
    assert.strictEqual(JSON.parse(fs.readFileSync(path.join(root, grammar.path), 'utf8')).scopeName, grammar.scopeName);
    const snippets = pkg.contributes.snippets.find((s) => s.language === id);
    const bodies = Object.values(JSON.parse(fs.readFileSync(path.join(root, snippets.path), 'utf8')));
    assert.ok(bodies.length > 0 && bodies.every((s) => s.prefix && s.body && s.description), `snippets for ${id}`);
    assert.ok(pkg.activationEvents.includes(`onLanguage:${id}`));
  }
});

test('the language configuration knows the comment syntax', () => {
  const config = JSON.parse(fs.readFileSync(path.join(root, 'language-configuration.json'), 'utf8'));
  assert.strictEqual(config.comments.lineComment, '//');
  assert.deepStrictEqual(config.comments.blockComment, ['/*', '*/']);
});
