// Starts `edsc lsp` for EDS files and passes the user's diagnostic flags
// (edsc.warnings, the strings of `edsc check -W...`) to it.
'use strict';

const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

function settings() {
  const config = vscode.workspace.getConfiguration('edsc');
  return { path: config.get('path') || 'edsc', warnings: config.get('warnings') || [] };
}

function createClient() {
  const { path, warnings } = settings();
  // stdio is the default transport; `edsc lsp` speaks nothing else.
  const server = { command: path, args: ['lsp'] };
  return new LanguageClient('edsc', 'edsc', server, {
    documentSelector: [{ language: 'eds' }],
    // Read once at start; later changes of the "edsc" section reach the
    // server as workspace/didChangeConfiguration.
    initializationOptions: { warnings },
    synchronize: { configurationSection: 'edsc' },
  });
}

async function start() {
  client = createClient();
  try {
    await client.start();
  } catch (err) {
    vscode.window.showErrorMessage(
      `edsc: cannot start '${settings().path} lsp' (${err.message}). Set "edsc.path" to the edsc executable.`);
  }
}

async function activate(context) {
  context.subscriptions.push(vscode.workspace.onDidChangeConfiguration(async (event) => {
    // A different executable needs a new server process.
    if (event.affectsConfiguration('edsc.path')) {
      if (client) await client.stop();
      await start();
    }
  }));
  await start();
}

async function deactivate() {
  if (client) await client.stop();
}

module.exports = { activate, deactivate };
