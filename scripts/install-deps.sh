#!/bin/sh
# Installs the Debian 12 packages libesi builds and tests with, when any is missing.
# Runs as root (CI, fresh machines) or through sudo when it is available. groff, man, zsh and fish
# are for the tests of the man pages and shell completions (tests/packaging/); iproute2 (`ip`) makes
# the veth pairs of bench/esi_sim_veth.sh and of esi-sim run by hand; tshark is Wireshark's reader, whose EtherCAT dissectors
# decode the frames between the tests' master and the emulated slaves (tests/sim_esc/
# line_wireshark_test.cpp); neovim is the editor whose LSP client the esi-lsp test drives
# (tests/lsp/nvim_test.cpp).
#   --with-browser  also headless Chromium, for the browser test of esi-doc's pages
#                   (tests/doc/browser_test.cpp; it skips where Chromium is absent)
#   --with-sarif-validator  also the official SARIF multitool from npm, for the SARIF check of
#                   esi-lint --format sarif (tests/cli/code_scanning_test.cpp; it skips where absent)
set -eu

packages="build-essential cmake ninja-build pkgconf git
libpugixml-dev libcli11-dev libfmt-dev nlohmann-json3-dev libyaml-dev
libgtest-dev libgmock-dev libbenchmark-dev libkainjow-mustache-dev libxml2-dev libxml2-utils
clang libclang-rt-14-dev ccache
groff-base man-db zsh fish iproute2 tshark neovim"
[ "${1:-}" = "--with-browser" ] && packages="$packages chromium"
[ "${1:-}" = "--with-sarif-validator" ] && ! command -v npm >/dev/null && packages="$packages npm"

missing=""
for p in $packages; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi

if [ -n "$missing" ]; then
    echo "install-deps: installing$missing"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    # shellcheck disable=SC2086
    $sudo apt-get install -y -qq --no-install-recommends $missing
fi

if [ "${1:-}" = "--with-sarif-validator" ] && ! npm ls -g @microsoft/sarif-multitool-linux >/dev/null 2>&1; then
    echo "install-deps: installing the SARIF multitool (npm)"
    $sudo npm install -g @microsoft/sarif-multitool-linux@5.7.0
fi
