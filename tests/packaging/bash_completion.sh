#!/bin/bash
# The installed bash completion, driven as bash drives it (COMP_WORDS, COMP_CWORD, the function
# `complete -F` registered): commands, options, option choices, rule ids after esi-lint --explain,
# output kinds after esi-gen --only, files elsewhere.
#   bash_completion.sh PREFIX SOURCE_DIR
set -u
prefix=$1
cd "$2" || exit 1
export PATH="$prefix/bin:$PATH"
for tool in esi-lint esi-gen esi-diff esi-sii; do
    script="$prefix/share/bash-completion/completions/$tool"
    [ -f "$script" ] || { echo "FAIL: $script is not installed"; exit 1; }
done
# shellcheck source=/dev/null
source "$prefix/share/bash-completion/completions/esi-lint"
complete -p esi-gen >/dev/null || { echo "FAIL: esi-gen has no completion"; exit 1; }

failed=0
# complete WORD... : completes the last word; COMPREPLY holds the candidates.
complete_line() {
    COMP_WORDS=("$@")
    COMP_CWORD=$(($# - 1))
    COMPREPLY=()
    local function
    function=$(complete -p "$1" | sed -n 's/.*-F \([^ ]*\) .*/\1/p')
    "$function" "$1" "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
}
# expect "WANTED..." -- WORD... : every wanted candidate is offered.
expect() {
    local wanted=() line
    while [ "$1" != -- ]; do wanted+=("$1"); shift; done
    shift
    complete_line "$@"
    line=" ${COMPREPLY[*]} "
    for w in "${wanted[@]}"; do
        [[ $line == *" $w "* ]] || { echo "FAIL: '$*' offers [${COMPREPLY[*]}], not $w"; failed=1; }
    done
}
# refuse "UNWANTED" -- WORD... : the candidate is not offered.
refuse() {
    local unwanted=$1
    shift 2
    complete_line "$@"
    [[ " ${COMPREPLY[*]} " != *" $unwanted "* ]] || { echo "FAIL: '$*' offers $unwanted"; failed=1; }
}

expect --explain --list-rules -- esi-lint --
refuse --help-man -- esi-lint --
expect pdo-entry-alignment -- esi-lint --explain pdo-entry-al
expect sarif -- esi-lint --format sa
expect breaking any never -- esi-diff --fail-on ""
expect structs -- esi-gen --only st
expect c,structs -- esi-gen --only c,st
expect build dump check -- esi-sii ""
expect --no-pdo --strict-size -- esi-sii build --
refuse --no-pdo -- esi-sii dump --
expect samples/esi -- esi-lint samples/es
expect samples/digital-io-8.yaml -- esi-sii build samples/digital-io
[ "$failed" -eq 0 ] && echo "bash completion checked"
exit "$failed"
