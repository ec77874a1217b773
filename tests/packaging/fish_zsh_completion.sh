#!/bin/sh
# The installed fish and zsh completions offer what the bash one does (bash_completion.sh): fish
# through its own `complete -C`, zsh with compadd, _files and _values replaced by functions that
# record their candidates (zsh completes only inside its line editor). A shell that is not
# installed is skipped; neither installed: the test is skipped.
#   fish_zsh_completion.sh PREFIX SOURCE_DIR
set -u
prefix=$1
cd "$2" || exit 1
PATH="$prefix/bin:$PATH"
export PATH
failed=0
ran=0
# check SHELL "LINE" WANTED OFFERED: WANTED must be a line of OFFERED.
check() {
    printf '%s\n' "$4" | grep -qx -- "$3" || { echo "FAIL: $1 '$2' offers [$(echo $4)], not $3"; failed=1; }
}

if command -v fish >/dev/null 2>&1; then
    ran=1
    for tool in esi-lint esi-gen esi-sii esi-diff; do
        [ -f "$prefix/share/fish/vendor_completions.d/$tool.fish" ] || { echo "FAIL: $tool.fish is not installed"; failed=1; }
    done
    # Not --no-config, which also skips the vendor completions: an empty configuration instead.
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    fish_complete() {
        XDG_DATA_DIRS="$prefix/share" XDG_CONFIG_HOME="$scratch" XDG_DATA_HOME="$scratch" \
            fish -c "complete -C '$1'" | cut -f1
    }
    for case in "esi-lint --ex|--explain" "esi-lint --explain pdo-entry-al|pdo-entry-alignment" \
                "esi-gen --only c,st|c,structs" "esi-sii |build" "esi-sii build --no|--no-pdo" \
                "esi-diff --fail-on |breaking" "esi-lint samples/es|samples/esi/"; do
        line=${case%|*}
        check fish "$line" "${case#*|}" "$(fish_complete "$line")"
    done
fi

if command -v zsh >/dev/null 2>&1; then
    ran=1
    zsh_complete() {
        zsh -f -c '
            fpath=("$1/share/zsh/vendor-completions" $fpath)
            autoload -Uz _esi
            typeset -a offered
            compadd() { if [[ $1 == -a ]]; then offered+=(${(P)2}); else [[ $1 == -- ]] && shift; offered+=("$@"); fi }
            _files() { offered+=(FILES) }
            _values() { shift 3; offered+=("$@") }
            shift
            words=("$@")
            CURRENT=$#
            _esi
            print -l -- $offered' zsh "$prefix" "$@"
    }
    check zsh "esi-lint --ex" --explain "$(zsh_complete esi-lint --ex)"
    check zsh "esi-lint --explain pdo" pdo-entry-alignment "$(zsh_complete esi-lint --explain pdo)"
    check zsh "esi-gen --only s" structs "$(zsh_complete esi-gen --only s)"
    check zsh "esi-sii " build "$(zsh_complete esi-sii '')"
    check zsh "esi-sii build --" --no-pdo "$(zsh_complete esi-sii build --)"
    check zsh "esi-diff --fail-on " breaking "$(zsh_complete esi-diff --fail-on '')"
    check zsh "esi-lint sam" FILES "$(zsh_complete esi-lint sam)"
fi

if [ "$ran" -eq 0 ]; then
    echo "SKIP: neither fish nor zsh is installed"
    exit 77
fi
[ "$failed" -eq 0 ] && echo "fish and zsh completion checked"
exit "$failed"
