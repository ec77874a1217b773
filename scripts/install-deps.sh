#!/bin/sh
# Installs the Debian 12 packages libesi builds and tests with, when any is missing.
# Runs as root (CI, fresh machines) or through sudo when it is available. groff, man, zsh and fish
# are for the tests of the man pages and shell completions (tests/packaging/).
#   --with-browser  also headless Chromium, for the browser test of esi-doc's pages
#                   (tests/doc/browser_test.cpp; it skips where Chromium is absent)
set -eu

packages="build-essential cmake ninja-build pkgconf git
libpugixml-dev libcli11-dev libfmt-dev nlohmann-json3-dev libyaml-dev
libgtest-dev libgmock-dev libbenchmark-dev libkainjow-mustache-dev libxml2-dev libxml2-utils
clang libclang-rt-14-dev ccache
groff-base man-db zsh fish"
[ "${1:-}" = "--with-browser" ] && packages="$packages chromium"

missing=""
for p in $packages; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0

echo "install-deps: installing$missing"
if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
# shellcheck disable=SC2086
$sudo apt-get install -y -qq --no-install-recommends $missing
