// Starts esi-lsp (libesi's language server) for XML and YAML documents: the ESI files and YAML
// device sources the server lints. The server decides what is an ESI file by content, so every
// XML and YAML file on disk is handed to it (an untitled buffer too).

import * as vscode from 'vscode';
import { LanguageClient, LanguageClientOptions, ServerOptions, TransportKind } from 'vscode-languageclient/node';

let client: LanguageClient | undefined;

function serverOptions(): ServerOptions {
    const config = vscode.workspace.getConfiguration('esi-lsp');
    const command = config.get<string>('path', 'esi-lsp') || 'esi-lsp';
    const debounce = config.get<number>('debounceMs', 100);
    return { command, args: ['--debounce', String(debounce)], transport: TransportKind.stdio };
}

async function start(): Promise<void> {
    const clientOptions: LanguageClientOptions = {
        documentSelector: [
            { scheme: 'file', language: 'xml' },
            { scheme: 'file', language: 'yaml' },
            { scheme: 'untitled', language: 'xml' },
            { scheme: 'untitled', language: 'yaml' },
        ],
        synchronize: {
            // A changed .esi-lint.yaml changes the findings of the files below it.
            fileEvents: vscode.workspace.createFileSystemWatcher('**/.esi-lint.yaml'),
        },
    };
    client = new LanguageClient('esi-lsp', 'EtherCAT ESI (esi-lsp)', serverOptions(), clientOptions);
    await client.start();
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
    context.subscriptions.push(
        vscode.workspace.onDidChangeConfiguration(async (event) => {
            if (!event.affectsConfiguration('esi-lsp')) return;
            // A new path or debounce: restart the server with it.
            await client?.stop();
            await start();
        }),
    );
    try {
        await start();
    } catch (error) {
        void vscode.window.showErrorMessage(
            `esi-lsp could not be started (${String(error)}). Set "esi-lsp.path" to the esi-lsp executable.`,
        );
    }
}

export async function deactivate(): Promise<void> {
    await client?.stop();
}
