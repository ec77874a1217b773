# bash completion for the libesi tools: esi-lint, esi-gen, esi-diff, esi-sii, esi-net, esi-doc, esi-sim, esi-lsp.
# Commands, options and option values come from the tool itself (TOOL --help-completion prints
# the table its --help is rendered from, cli/cli_reference.hpp), so the completion knows exactly
# the options of the installed tool. Rule ids after esi-lint --explain come from
# esi-lint --list-rules, output kinds after esi-gen --only from esi-gen --list-kinds.
# Installed once per tool name, as bash-completion loads completions/COMMAND on first use.

_esi_complete() {
    local tool=$1 cur=${COMP_WORDS[COMP_CWORD]} prev=
    ((COMP_CWORD > 0)) && prev=${COMP_WORDS[COMP_CWORD - 1]}
    COMPREPLY=()
    local table
    table=$("$tool" --help-completion 2>/dev/null) || return 0

    local kind scope names value choices
    local -a commands=()
    while IFS=$'\t' read -r kind scope names value choices; do
        [[ $kind == command ]] && commands+=("$scope")
    done <<<"$table"

    # The command is the first word that names one (esi-sii build …); "." is the tool itself.
    local command=. word i c
    for ((i = 1; i < COMP_CWORD; i++)); do
        word=${COMP_WORDS[i]}
        for c in "${commands[@]}"; do
            if [[ $command == . && $word == "$c" ]]; then command=$c; fi
        done
    done

    # The value of an option of this command.
    local option_names=() takes=
    while IFS=$'\t' read -r kind scope names value choices; do
        [[ $kind == option && $scope == "$command" ]] || continue
        option_names+=($names)
        [[ " $names " == *" $prev "* && $value == 1 ]] || continue
        takes=1
        case "${tool##*/} $prev" in
        "esi-lint --explain")
            COMPREPLY=($(compgen -W "$("$tool" --list-rules 2>/dev/null | cut -d' ' -f1)" -- "$cur"))
            return 0
            ;;
        "esi-sim --iface")
            COMPREPLY=($(compgen -W "$(ls /sys/class/net 2>/dev/null)" -- "$cur"))
            return 0
            ;;
        "esi-gen --only")
            # A comma-separated list: complete the last kind, keep the ones before it.
            local done_kinds=${cur%"${cur##*,}"} kinds
            kinds=$("$tool" --list-kinds 2>/dev/null | cut -f1)
            COMPREPLY=($(compgen -P "$done_kinds" -W "$kinds" -- "${cur##*,}"))
            compopt -o nospace 2>/dev/null
            return 0
            ;;
        esac
        if [[ $choices != - ]]; then
            COMPREPLY=($(compgen -W "$choices" -- "$cur"))
            return 0
        fi
    done <<<"$table"
    if [[ -z $takes && $cur == -* ]]; then
        COMPREPLY=($(compgen -W "${option_names[*]}" -- "$cur"))
        return 0
    fi
    if [[ -z $takes && $command == . && ${#commands[@]} -gt 0 ]]; then
        COMPREPLY=($(compgen -W "${commands[*]}" -- "$cur"))
        return 0
    fi
    # Anything else is a file or directory.
    compopt -o filenames 2>/dev/null
    COMPREPLY=($(compgen -f -- "$cur"))
    return 0
}

complete -F _esi_complete esi-lint esi-gen esi-diff esi-sii esi-net esi-doc esi-sim esi-lsp
