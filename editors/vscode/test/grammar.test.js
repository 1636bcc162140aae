'use strict';
// Every model file in the repository, coloured by the extension's TextMate grammars through the
// same engine VS Code uses (vscode-textmate + vscode-oniguruma), against an independent reading of
// the file: every keyword, comment and string must get a scope of its kind, and no other name a
// keyword's scope.
const test = require('node:test');
const assert = require('node:assert');
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');
const vsctm = require('vscode-textmate');
const oniguruma = require('vscode-oniguruma');

const root = path.join(__dirname, '..');
const repo = execFileSync('git', ['rev-parse', '--show-toplevel'], { cwd: root, encoding: 'utf8' }).trim();
const pkg = require('../package.json');

// The keywords of each language, as its Xtext grammar (dsl/src/main/java/org/triad/dsl/*.xtext) has them.
const COMMON = ['true', 'false', 'boolean', 'int', 'double', 'String'];
const KEYWORDS = {
  cd: ['classdiagram', 'class', 'abstract', 'extends', 'enum', ...COMMON],
  actor: ['domain', 'robot', 'world', 'property', 'action', 'pre', 'post', 'cost', ...COMMON],
  goal: ['domain', 'goal', ...COMMON],
  task: ['domain', 'task', ...COMMON],
  state: ['domain', 'state', ...COMMON],
  arc: ['package', 'import', 'component', 'port', 'in', 'out', 'automaton', 'initial', 'state', 'faults'],
};

/** What a keyword's scope must start with. */
function expectedKeywordScope(word) {
  if (word === 'true' || word === 'false') return ['constant.language.boolean'];
  if (['boolean', 'int', 'double', 'String'].includes(word)) return ['support.type.primitive'];
  return ['keyword.', 'storage.'];
}

/** Comments, strings, keywords and other names of each line, read without the grammar. */
function spans(text, keywords) {
  const result = [];
  let inBlock = false;
  text.split('\n').forEach((line, n) => {
    let i = 0;
    while (i < line.length) {
      if (inBlock) {
        const end = line.indexOf('*/', i);
        const stop = end < 0 ? line.length : end + 2;
        if (stop > i) result.push({ line: n, start: i, end: stop, kind: 'comment' });
        inBlock = end < 0;
        i = stop;
      } else if (line.startsWith('//', i)) {
        result.push({ line: n, start: i, end: line.length, kind: 'comment' });
        i = line.length;
      } else if (line.startsWith('/*', i)) {
        inBlock = true;
        const end = line.indexOf('*/', i + 2);
        const stop = end < 0 ? line.length : end + 2;
        result.push({ line: n, start: i, end: stop, kind: 'comment' });
        inBlock = end < 0;
        i = stop;
      } else if (line[i] === '"') {
        let j = i + 1;
        while (j < line.length && line[j] !== '"') j += line[j] === '\\' ? 2 : 1;
        result.push({ line: n, start: i, end: Math.min(j + 1, line.length), kind: 'string' });
        i = j + 1;
      } else if (/[A-Za-z_]/.test(line[i]) && (i === 0 || !/[\w]/.test(line[i - 1]))) {
        const word = /^[A-Za-z_]\w*/.exec(line.slice(i))[0];
        const afterDot = i > 0 && line[i - 1] === '.';
        const kind = !afterDot && keywords.includes(word) ? 'keyword' : 'name';
        result.push({ line: n, start: i, end: i + word.length, kind, word });
        i += word.length;
      } else {
        i++;
      }
    }
  });
  return result;
}

async function loadRegistry() {
  const wasm = fs.readFileSync(require.resolve('vscode-oniguruma/release/onig.wasm'));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const grammars = Object.fromEntries(pkg.contributes.grammars.map((g) => [g.scopeName, path.join(root, g.path)]));
  return new vsctm.Registry({
    onigLib: Promise.resolve({ createOnigScanner: (p) => new oniguruma.OnigScanner(p), createOnigString: (s) => new oniguruma.OnigString(s) }),
    loadGrammar: async (scopeName) => grammars[scopeName] ? vsctm.parseRawGrammar(fs.readFileSync(grammars[scopeName], 'utf8'), grammars[scopeName]) : null,
  });
}

function tokenize(grammar, text) {
  let stack = vsctm.INITIAL;
  return text.split('\n').map((line) => {
    const r = grammar.tokenizeLine(line, stack);
    stack = r.ruleStack;
    return r.tokens;
  });
}

const files = execFileSync('git', ['ls-files', '*.cd', '*.actor', '*.goal', '*.task', '*.state', '*.arc'], { cwd: repo, encoding: 'utf8' })
  .split('\n').filter(Boolean);

test('the repository has model files of every kind to check the grammars on', () => {
  for (const kind of Object.keys(KEYWORDS)) {
    assert.ok(files.some((f) => f.endsWith(`.${kind}`)), `a .${kind} file`);
  }
});

test('every keyword, comment and string of every model file is scoped as expected', async (t) => {
  const registry = await loadRegistry();
  const grammars = {};
  for (const kind of Object.keys(KEYWORDS)) {
    grammars[kind] = await registry.loadGrammar(`source.triad.${kind}`);
  }
  for (const file of files) {
    await t.test(file, () => {
      const kind = path.extname(file).slice(1);
      const text = fs.readFileSync(path.join(repo, file), 'utf8');
      const tokens = tokenize(grammars[kind], text);
      const problems = [];
      for (const span of spans(text, KEYWORDS[kind])) {
        const covering = tokens[span.line].filter((tk) => tk.startIndex < span.end && tk.endIndex > span.start);
        const where = `${file}:${span.line + 1}:${span.start + 1}`;
        const has = (prefixes) => covering.every((tk) => tk.scopes.some((s) => prefixes.some((p) => s.startsWith(p))));
        if (span.kind === 'comment' && !has(['comment.'])) problems.push(`${where} comment not scoped as comment: ${JSON.stringify(covering)}`);
        if (span.kind === 'string' && !has(['string.'])) problems.push(`${where} string not scoped as string`);
        if (span.kind === 'keyword' && !has(expectedKeywordScope(span.word))) problems.push(`${where} keyword '${span.word}' scoped ${JSON.stringify(covering.map((c) => c.scopes))}`);
        if (span.kind === 'name' && covering.some((tk) => tk.scopes.some((s) => /^(keyword\.other|storage\.)/.test(s)))) {
          problems.push(`${where} name '${span.word}' scoped as a keyword`);
        }
      }
      assert.deepStrictEqual(problems, []);
    });
  }
});
