#!/bin/sh
# The installed man pages: one per installed tool, rendering without a groff/man warning, and
# listing every option and command that the tool's --help (and each command's --help) lists;
# esi-lint.yaml(5) names every key docs/lint-config.md documents.
#   man_pages.sh PREFIX SOURCE_DIR
set -eu
prefix=$1
source_dir=$2
if ! command -v groff >/dev/null 2>&1; then
    echo "SKIP: groff is not installed"
    exit 77
fi
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# Text of a page, plain ASCII (no overstrike), one long line per paragraph.
render() { groff -man -Tascii -rLL=300n -P-c -P-b -P-u "$1" 2>/dev/null; }

check_renders() {
    warnings=$(groff -man -Tutf8 -ww -z "$1" 2>&1) || fail "$1: groff failed"
    [ -z "$warnings" ] || fail "$1: groff warns: $warnings"
    if command -v man >/dev/null 2>&1; then
        warnings=$(MANPAGER=cat man --warnings -l "$1" 2>&1 >/dev/null) || fail "$1: man -l failed"
        [ -z "$warnings" ] || fail "$1: man -l warns: $warnings"
    fi
}

# Options (-x, --xyz) and, after "Subcommands:", the command names of a --help text.
options_of() { grep -oE '(^|[ ,])--?[a-zA-Z][a-zA-Z0-9-]*' | sed 's/^[ ,]//' | sort -u; }
commands_of() { sed -n '/^Subcommands:/,$p' | sed -n 's/^  \([a-z][a-z-]*\) .*/\1/p'; }

tools=0
for tool in "$prefix"/bin/esi-*; do
    name=$(basename "$tool")
    page="$prefix/share/man/man1/$name.1"
    tools=$((tools + 1))
    if [ ! -f "$page" ]; then
        fail "$name has no installed man page $page"
        continue
    fi
    check_renders "$page"
    text=$(render "$page")
    help=$("$tool" --help)
    for option in $(printf '%s\n' "$help" | options_of); do
        printf '%s\n' "$text" | grep -qe "$option\b" || fail "$name(1) lacks $option of --help"
    done
    for command in $(printf '%s\n' "$help" | commands_of); do
        printf '%s\n' "$text" | grep -q "$name $command" || fail "$name(1) lacks the command $command"
        for option in $("$tool" "$command" --help | options_of); do
            # The command's own section, from its .SS heading to the next one.
            section=$(printf '%s\n' "$text" | sed -n "/^   $name $command\$/,/^   $name [a-z]/p")
            printf '%s\n' "$section" | grep -qe "$option\b" || fail "$name(1) lacks $option of $name $command --help"
        done
    done
done
[ "$tools" -gt 0 ] || fail "no tool installed in $prefix/bin"

config_page="$prefix/share/man/man5/esi-lint.yaml.5"
if [ -f "$config_page" ]; then
    check_renders "$config_page"
    text=$(render "$config_page")
    # The top-level keys (### `key` headings) and the limits (first column of the table).
    keys=$(sed -n 's/^### `\([a-z_]*\)`.*/\1/p; s/^| `\([a-z_0-9]*\)` |.*/\1/p' "$source_dir/docs/lint-config.md")
    [ -n "$keys" ] || fail "no keys found in docs/lint-config.md"
    for key in $keys files product_codes; do
        printf '%s\n' "$text" | grep -qw -- "$key" || fail "esi-lint.yaml(5) lacks the key $key of docs/lint-config.md"
    done
else
    fail "esi-lint.yaml(5) is not installed"
fi
[ "$failed" -eq 0 ] && echo "man pages of $tools tools and esi-lint.yaml(5) checked"
exit "$failed"
