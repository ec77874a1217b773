#!/bin/sh
# The VS Code extension (editors/vscode) packages: `npm ci` from the committed lock file, then
# `vsce package` into a temporary directory; the .vsix must hold the extension manifest, the
# package.json and the compiled extension. Skips (77) without node/npm or without access to the
# npm registry. About 1.5 min (the install is most of it), hence its own label, vscode.
#   vscode_extension.sh SOURCE_DIR
set -eu
source_dir=$1
if ! command -v npm >/dev/null 2>&1 || ! command -v node >/dev/null 2>&1; then
    echo "npm/node not installed: VS Code extension test skipped"
    exit 77
fi
if ! timeout 30 npm ping >/dev/null 2>&1; then
    echo "npm registry not reachable: VS Code extension test skipped"
    exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A copy without what a developer's checkout may hold (node_modules, out, packages).
mkdir "$work/ext"
(cd "$source_dir/editors/vscode" && tar --exclude=./node_modules --exclude=./out --exclude='*.vsix' -cf - .) | (cd "$work/ext" && tar -xf -)
cd "$work/ext"
# The registry answered the ping, but a download can still break off: one retry, and a failure
# the log shows to be the network's (not the lock file's or the build's) is a skip, not a failure.
if ! timeout 600 npm ci --no-audit --no-fund >"$work/npm.log" 2>&1 &&
   ! timeout 600 npm ci --no-audit --no-fund >"$work/npm.log" 2>&1; then
    cat "$work/npm.log"
    if grep -qE 'ETIMEDOUT|ECONNRESET|ECONNREFUSED|EAI_AGAIN|ENOTFOUND|ENETUNREACH|socket hang up' "$work/npm.log"; then
        echo "npm ci lost the registry: VS Code extension test skipped"
        exit 77
    fi
    echo "npm ci failed"
    exit 1
fi
mkdir "$work/out"
timeout 300 npx --no-install @vscode/vsce package -o "$work/out/esi-lsp.vsix" >"$work/vsce.log" 2>&1 ||
    { cat "$work/vsce.log"; echo "vsce package failed"; exit 1; }
vsix="$work/out/esi-lsp.vsix"
[ -s "$vsix" ] || { echo "no .vsix written"; exit 1; }
# A .vsix is a zip: its entry names are stored as they are.
for entry in extension.vsixmanifest extension/package.json extension/out/extension.js extension/node_modules/vscode-languageclient/package.json; do
    grep -q -a "$entry" "$vsix" || { echo "the .vsix lacks $entry"; exit 1; }
done
echo "ok: $(wc -c <"$vsix") bytes"
