#!/bin/sh
# The corpus verdict review (issue 10's ecosystem check): lints every file of ../shared/corpus/esi
# with esi-lint as shipped and prints how the verdicts differ from the reviewed snapshot
# tests/corpus/expected/verdicts.tsv: per rule and severity +N/-N findings (and in which files),
# the files whose pass/fail under --fail-on error flips, and the official vendor files' figures
# (origins in tests/corpus/expected/origins.tsv).
#   scripts/corpus-verdicts.sh [--update] [BUILD_DIR]     (BUILD_DIR defaults to build)
# --update replaces the snapshot with today's verdicts; commit it together with the change that
# caused them, after reading the printed account. Exit status: 0 when the verdicts match the
# snapshot (or it was updated), 1 when they differ, 2 on a usage or build problem.
set -eu
cd "$(dirname "$0")/.."
update=0
if [ "${1:-}" = "--update" ]; then
    update=1
    shift
fi
case "${1:-}" in -*) echo "usage: scripts/corpus-verdicts.sh [--update] [BUILD_DIR]" >&2; exit 2 ;; esac
build=${1:-build}
if [ ! -d ../shared/corpus/esi ]; then
    echo "corpus-verdicts: ../shared/corpus/esi is absent; nothing to compare" >&2
    exit 2
fi
cmake --build "$build" --target corpus_tests esi-lint >/dev/null || { echo "corpus-verdicts: build failed" >&2; exit 2; }

snapshot=tests/corpus/expected/verdicts.tsv
# Written next to the snapshot, so that --update is a rename within one file system.
now=$(mktemp "$snapshot.XXXXXX")
trap 'rm -f "$now" "$now.log"' EXIT INT TERM
status=0
ESI_CORPUS_VERDICTS_OUT=$now "$build/tests/corpus_tests" --gtest_filter=CorpusVerdicts.MatchTheReviewedSnapshot \
    >"$now.log" 2>&1 || status=$?
# The test prints the account on stdout; leave out gtest's own lines and its failure message.
awk '/: Failure$/ { exit } /^\[/ || /^Running main\(\)/ || /^Note: Google Test filter/ { next } { print }' "$now.log"
if [ ! -s "$now" ]; then
    cat "$now.log" >&2
    rm -f "$now.log"
    echo "corpus-verdicts: the test wrote no verdicts" >&2
    exit 2
fi
rm -f "$now.log"
if [ "$status" -eq 0 ]; then
    exit 0
fi
if [ "$update" -eq 1 ]; then
    mv "$now" "$snapshot"
    echo "corpus-verdicts: $snapshot updated; commit it with the change that caused it"
    exit 0
fi
echo "corpus-verdicts: run with --update to accept this change"
exit 1
