# fish completion for the libesi tools, installed as TOOL.fish for each tool (fish loads a
# completion by command name). Commands, options and option values come from the tool itself
# (TOOL --help-completion, the table its --help is rendered from); rule ids after
# esi-lint --explain from esi-lint --list-rules, output kinds after esi-gen --only from
# esi-gen --list-kinds.

function __esi_complete
    set -l words (commandline -opc)
    set -l cur (commandline -ct)
    set -l tool $words[1]
    set -l table ($tool --help-completion 2>/dev/null)
    or return
    set -l commands
    for line in $table
        set -l f (string split \t -- $line)
        test "$f[1]" = command; and set -a commands $f[2]
    end
    # The command is the first word that names one (esi-sii build …); "." is the tool itself.
    set -l command .
    set -l prev
    if test (count $words) -gt 1
        set prev $words[-1]
        for w in $words[2..-1]
            if test $command = .; and contains -- $w $commands
                set command $w
            end
        end
    end
    set -l options
    for line in $table
        set -l f (string split \t -- $line)
        test "$f[1]" = option -a "$f[2]" = $command; or continue
        set -l names (string split ' ' -- $f[3])
        set -a options $names
        if test "$f[4]" = 1; and contains -- "$prev" $names
            switch (basename $tool)" $prev"
                case 'esi-lint --explain'
                    $tool --list-rules 2>/dev/null | string replace -r ' .*' ''
                    return
                case 'esi-gen --only'
                    # A comma-separated list: complete the last kind, keep the ones before it.
                    set -l given (string replace -r '[^,]*$' '' -- $cur)
                    for kind in ($tool --list-kinds 2>/dev/null | string replace -r '\t.*' '')
                        echo $given$kind
                    end
                    return
            end
            if test "$f[5]" != -
                string split ' ' -- $f[5]
                return
            end
            __fish_complete_path $cur
            return
        end
    end
    if string match -q -- '-*' $cur
        printf '%s\n' $options
        return
    end
    if test $command = .; and test (count $commands) -gt 0
        printf '%s\n' $commands
        return
    end
    __fish_complete_path $cur
end

complete -c (basename (status filename) .fish) -f -a '(__esi_complete)'
