#!/bin/sh
# Builds the libFuzzer targets with clang and runs each for a bounded time, seeded from the
# corpus and samples. Crashes, timeouts and out-of-memory inputs are left in
# build-fuzz/findings/<target>/ as reproducers (those of an earlier run move to .../previous/);
# the full libFuzzer log is build-fuzz/logs/<target>.log. Exit status 1 when any target left a
# reproducer or failed. docs/reliability.md describes the targets and the figures of a long run.
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
set -eu
cd "$(dirname "$0")/.."
seconds=${1:-60}
[ $# -gt 0 ] && shift
launcher=""
command -v ccache >/dev/null 2>&1 && launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
# -O1 with line tables and assertions on: the usual fuzzing build (fast to compile, asserts and
# sanitizers catch what they can, stack traces name the line).
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Fuzz -DCMAKE_CXX_FLAGS_FUZZ="-O1 -gline-tables-only" \
    -DCMAKE_C_FLAGS_FUZZ="-O1 -gline-tables-only" -DESI_BUILD_FUZZERS=ON \
    -DESI_BUILD_TESTS=OFF -DESI_BUILD_BENCH=OFF $launcher >/dev/null
# Only the fuzz targets (and the library under them), not the instrumented command-line tools.
targets=${*:-$(cd fuzz && ls *_fuzzer.cpp | sed 's/\.cpp$//')}
# shellcheck disable=SC2086
cmake --build build-fuzz --target $targets
shared=../shared/corpus
mkdir -p build-fuzz/logs
# diff_fuzzer seeds from the corpus: revision pairs of one product family, joined by the four
# NUL bytes the target splits at (fuzz/diff_fuzzer.cpp).
if [ -d "$shared/esi" ]; then
    mkdir -p build-fuzz/seeds/diff
    while read -r old new; do
        [ -f "$shared/esi/$old" ] && [ -f "$shared/esi/$new" ] || continue
        { cat "$shared/esi/$old"; printf '\000\000\000\000'; cat "$shared/esi/$new"; } >"build-fuzz/seeds/diff/$old+$new"
    done <<'PAIRS'
MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-02.xml MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-10.xml
SMC__EX250-SEN1-X156__dls-ethercat__2011-05.xml SMC__EX250-SEN1-X156__dls-ethercat__2014-03.xml
ProjectMARCH__BP-GES__ethercat-slaves__2020-02.xml ProjectMARCH__BP-GES__ethercat-slaves__2020-03.xml
Beckhoff__EK13xx__dls-ethercat__2018-01.xml Beckhoff__EK13xx__dls-ethercat__2018-06.xml
HPMicro__ECAT_CIA402__hpm_sdk__2024-09.xml HPMicro__ECAT_CIA402__hpm_sdk__2025-12.xml
PollenRobotics__NeckOrbita3d_fw1.0__poulpe.xml PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml
Synapticon__Somanet_CiA402-single__siitool__2013.xml Synapticon__Somanet_CiA402-single__siitool__2016.xml
PAIRS
fi
status=0
for target in $targets; do
    work=build-fuzz/corpus/$target
    findings=build-fuzz/findings/$target
    log=build-fuzz/logs/$target.log
    mkdir -p "$work" "$findings/previous"
    for old in "$findings"/crash-* "$findings"/timeout-* "$findings"/oom-* "$findings"/leak-*; do
        [ -e "$old" ] && mv "$old" "$findings/previous/"
    done
    seeds=""
    dict=fuzz/esi.dict
    case $target in
        xml_* | writer_* | codegen_*) seeds="samples/esi tests/rules/fixtures $shared/esi" ;;
        yaml_*) seeds="samples fuzz/seeds/yaml"; dict=fuzz/yaml.dict ;;
        sii_*) seeds="$shared/sii fuzz/seeds/sii"; dict=fuzz/sii.dict ;;
        diff_*) seeds="fuzz/seeds/diff build-fuzz/seeds/diff" ;;
    esac
    existing=""
    for s in $seeds; do [ -e "$s" ] && existing="$existing $s"; done
    echo "== $target: $seconds s (log: $log)"
    # -rss_limit_mb bounds memory per input (docs/reliability.md states the library's own
    # bounds, far below it); -timeout flags any input that takes longer than 10 s.
    rc=0
    build-fuzz/fuzz/"$target" "$work" $existing -dict="$dict" -max_total_time="$seconds" \
        -rss_limit_mb=2048 -timeout=10 -max_len=1048576 -artifact_prefix="$findings/" -print_final_stats=1 \
        >"$log" 2>&1 || rc=$?
    # The last progress line (executions, cov, ft, corpus) and the final statistics.
    grep -E '^#[0-9]+' "$log" | tail -n 1 || true
    grep -E '^stat::' "$log" || true
    if [ "$rc" -ne 0 ]; then
        echo "!! $target exited with status $rc:"
        grep -E 'ERROR|SUMMARY|==[0-9]+==' "$log" | head -n 20 || true
        status=1
    fi
    if ls "$findings"/crash-* "$findings"/timeout-* "$findings"/oom-* "$findings"/leak-* >/dev/null 2>&1; then
        echo "!! $target left reproducers in $findings:"
        ls "$findings"/crash-* "$findings"/timeout-* "$findings"/oom-* "$findings"/leak-* 2>/dev/null || true
        status=1
    fi
done
exit $status
