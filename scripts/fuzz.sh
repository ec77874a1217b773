#!/bin/sh
# Builds the libFuzzer targets with clang and runs each for a bounded time, seeded from the
# corpus and samples. Crashes are left in build-fuzz/findings/<target>/ as reproducers.
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
set -eu
cd "$(dirname "$0")/.."
seconds=${1:-60}
[ $# -gt 0 ] && shift
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DESI_BUILD_FUZZERS=ON \
    -DESI_BUILD_TESTS=OFF -DESI_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz
targets=${*:-$(cd build-fuzz/fuzz && ls *_fuzzer)}
shared=../shared/corpus
status=0
for target in $targets; do
    work=build-fuzz/corpus/$target
    findings=build-fuzz/findings/$target
    mkdir -p "$work" "$findings"
    seeds=""
    case $target in
        xml_*) seeds="samples/esi tests/rules/fixtures $shared/esi" ;;
        yaml_*) seeds="samples tests/yaml" ;;
        sii_*) seeds="$shared/sii tests/sii" ;;
        diff_*) seeds="samples/esi" ;;
    esac
    existing=""
    for s in $seeds; do [ -e "$s" ] && existing="$existing $s"; done
    echo "== $target: $seconds s"
    # -rss_limit_mb bounds memory per input; -timeout flags inputs that take longer than 10 s.
    if ! build-fuzz/fuzz/"$target" "$work" $existing -dict=fuzz/esi.dict -max_total_time="$seconds" \
            -rss_limit_mb=2048 -timeout=10 -max_len=1048576 -artifact_prefix="$findings/" -print_final_stats=1 2>&1 |
            tail -n 12; then
        status=1
    fi
    if ls "$findings"/crash-* "$findings"/timeout-* "$findings"/oom-* >/dev/null 2>&1; then
        echo "!! $target left reproducers in $findings"
        status=1
    fi
done
exit $status
