// The extension's glue without VS Code: `vscode` and the language client are
// stand-ins, so this checks what the extension asks for — `<edsc.path> lsp`
// for documents of language eds, edsc.warnings as initializationOptions, the
// "edsc" section synchronised — and that changing edsc.path restarts it.
'use strict';
const assert = require('assert');
const Module = require('module');
const path = require('path');

const settings = { path: '/opt/edsc/bin/edsc', warnings: ['-Wpedantic', '-Wno-class-numbering', '-Werror'] };
const clients = [];
let onConfig = null;
const vscode = {
  workspace: {
    getConfiguration: (section) => {
      assert.strictEqual(section, 'edsc');
      return { get: (key) => settings[key] };
    },
    onDidChangeConfiguration: (listener) => {
      onConfig = listener;
      return { dispose() {} };
    },
  },
  window: { showErrorMessage: (m) => assert.fail(m) },
};
class LanguageClient {
  constructor(id, name, server, options) {
    Object.assign(this, { id, name, server, options, running: false });
    clients.push(this);
  }
  async start() { this.running = true; }
  async stop() { this.running = false; }
}
const load = Module._load;
Module._load = function (request, ...rest) {
  if (request === 'vscode') return vscode;
  if (request === 'vscode-languageclient/node') return { LanguageClient };
  return load.call(this, request, ...rest);
};

(async () => {
  const extension = require(path.join(__dirname, '..', 'src', 'extension.js'));
  await extension.activate({ subscriptions: [] });
  assert.strictEqual(clients.length, 1);
  const [first] = clients;
  assert.deepStrictEqual(first.server, { command: '/opt/edsc/bin/edsc', args: ['lsp'] });
  assert.deepStrictEqual(first.options.documentSelector, [{ language: 'eds' }]);
  assert.deepStrictEqual(first.options.initializationOptions, { warnings: settings.warnings });
  assert.strictEqual(first.options.synchronize.configurationSection, 'edsc');
  assert.ok(first.running);

  // -W changes reach the running server through didChangeConfiguration.
  await onConfig({ affectsConfiguration: (key) => key === 'edsc.warnings' });
  assert.strictEqual(clients.length, 1);
  // Another executable: the old server stops, a new one starts.
  settings.path = 'edsc-dev';
  await onConfig({ affectsConfiguration: (key) => key === 'edsc.path' || key === 'edsc' });
  assert.strictEqual(clients.length, 2);
  assert.ok(!first.running);
  assert.strictEqual(clients[1].server.command, 'edsc-dev');
  assert.ok(clients[1].running);

  await extension.deactivate();
  assert.ok(!clients[1].running);
  console.log('extension client glue: ok');
})().catch((err) => {
  console.error(err);
  process.exit(1);
});
