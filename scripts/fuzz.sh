#!/bin/sh
# Builds the libFuzzer targets with clang and runs each for a bounded time, seeded from the
# corpus and samples. Crashes, timeouts and out-of-memory inputs are left in
# build-fuzz/findings/<target>/ as reproducers (those of an earlier run move to .../previous/);
# the full libFuzzer log is build-fuzz/logs/<target>.log. Exit status 1 when any target left a
# reproducer or failed. docs/reliability.md describes the targets and the figures of a long run.
#   scripts/fuzz.sh [-j JOBS] [SECONDS_PER_TARGET] [TARGET...]
# -j runs up to JOBS targets at once (default 1), each for the full time: on a machine with JOBS
# idle cores every target gets what it gets alone, in 1/JOBS of the wall time.
set -eu
cd "$(dirname "$0")/.."
jobs=1
if [ "${1:-}" = "-j" ]; then
    jobs=$2
    shift 2
fi
seconds=${1:-60}
[ $# -gt 0 ] && shift
# build-fuzz/ is the tree of CMakePresets.json's "fuzz" preset (clang, -O1 with line tables and
# assertions on, everything under ASan + UBSan); CI builds its test suite too. Only the fuzz
# targets (and the library under them) are built here.
cmake --preset fuzz >/dev/null
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
# Runs one target (in the background when -j > 1); its exit status goes to <log>.status.
run_target() {
    target=$1
    work=build-fuzz/corpus/$target
    findings=build-fuzz/findings/$target
    log=build-fuzz/logs/$target.log
    seeds=""
    dict=fuzz/esi.dict
    case $target in
        xml_* | writer_* | codegen_*) seeds="samples/esi tests/rules/fixtures $shared/esi" ;;
        yaml_*) seeds="samples fuzz/seeds/yaml"; dict=fuzz/yaml.dict ;;
        sii_*) seeds="$shared/sii fuzz/seeds/sii"; dict=fuzz/sii.dict ;;
        diff_*) seeds="fuzz/seeds/diff build-fuzz/seeds/diff" ;;
        coe_*) seeds="fuzz/seeds/coe" ;;
        esc_*) seeds="fuzz/seeds/esc"; dict=fuzz/esc.dict ;;
    esac
    existing=""
    for s in $seeds; do [ -e "$s" ] && existing="$existing $s"; done
    # -rss_limit_mb bounds memory per input (docs/reliability.md states the library's own
    # bounds, far below it); -timeout flags any input that takes longer than 10 s.
    rc=0
    # shellcheck disable=SC2086
    build-fuzz/fuzz/"$target" "$work" $existing -dict="$dict" -max_total_time="$seconds" \
        -rss_limit_mb=2048 -timeout=10 -max_len=1048576 -artifact_prefix="$findings/" -print_final_stats=1 \
        >"$log" 2>&1 || rc=$?
    echo "$rc" >"$log.status"
}

# Prints a finished target's last progress line (executions, cov, ft, corpus) and final
# statistics; sets status=1 when it failed or left a reproducer.
report_target() {
    target=$1
    findings=build-fuzz/findings/$target
    log=build-fuzz/logs/$target.log
    rc=$(cat "$log.status" 2>/dev/null || echo "no status")
    echo "== $target: $seconds s (log: $log)"
    grep -E '^#[0-9]+' "$log" | tail -n 1 || true
    grep -E '^stat::' "$log" || true
    if [ "$rc" != 0 ]; then
        echo "!! $target exited with status $rc:"
        grep -E 'ERROR|SUMMARY|==[0-9]+==' "$log" | head -n 20 || true
        status=1
    fi
    if ls "$findings"/crash-* "$findings"/timeout-* "$findings"/oom-* "$findings"/leak-* >/dev/null 2>&1; then
        echo "!! $target left reproducers in $findings:"
        ls "$findings"/crash-* "$findings"/timeout-* "$findings"/oom-* "$findings"/leak-* 2>/dev/null || true
        status=1
    fi
}

status=0
batch=""
count=0
for target in $targets; do
    findings=build-fuzz/findings/$target
    mkdir -p "build-fuzz/corpus/$target" "$findings/previous"
    for old in "$findings"/crash-* "$findings"/timeout-* "$findings"/oom-* "$findings"/leak-*; do
        [ -e "$old" ] && mv "$old" "$findings/previous/"
    done
    rm -f "build-fuzz/logs/$target.log.status"
    echo "-- $target: fuzzing for $seconds s"
    run_target "$target" &
    batch="$batch $target"
    count=$((count + 1))
    # Every target runs for the same time, so batches of JOBS keep the cores busy.
    if [ "$count" -ge "$jobs" ]; then
        wait
        for t in $batch; do report_target "$t"; done
        batch=""
        count=0
    fi
done
wait
for t in $batch; do report_target "$t"; done
exit $status
