#!/bin/sh
# Peak memory and CPU time on a big vendor catalogue (issues 10 and 25): builds one ESI file of
# about TARGET_MB by merging the Devices (and Groups) of the Beckhoff catalogues in
# ../shared/corpus/esi into one EtherCATInfo, then reports the peak RSS of `esi-lint -j1` on it
# next to a bare pugixml parse of the same file (bench/bare_parse_peak.cpp) and the reader alone
# (bench/lint_stage read), each as a multiple of the file size, against the target of
# 3 x file + 30 MiB (all in MiB); and the CPU time (user + system) of `esi-lint -j1 --format json` against
# `lint_stage bare` on it, five runs of each in turn, against the target ratio of 1.6.
#   bench/big_catalogue_rss.sh [BUILD_DIR] [TARGET_MB]     (defaults: build 40)
# BUILD_DIR must be configured with -DESI_BUILD_BENCH=ON. The merged file is written to
# BUILD_DIR/bench-data/ (never to the repository). The corpus holds about 24 MB of Beckhoff
# catalogues, so above that the Devices are taken a second time (duplicate identities: esi-lint
# then also reports identity-duplicate, a few thousand findings, which is part of what it holds).
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
target_mb=${2:-40}
corpus=../shared/corpus/esi
if [ ! -d "$corpus" ]; then
    echo "big_catalogue_rss: $corpus is absent; nothing to measure"
    exit 0
fi
if ! cmake --build "$build" --target esi-lint bare_parse_peak lint_stage >/dev/null 2>&1; then
    echo "big_catalogue_rss: cannot build esi-lint, bare_parse_peak and lint_stage in $build" >&2
    echo "  (configure it with -DESI_BUILD_BENCH=ON)" >&2
    exit 2
fi

out_dir=$build/bench-data
mkdir -p "$out_dir"
merged=$out_dir/big_catalogue.xml
tmp=$merged.tmp
groups=$out_dir/big_catalogue.groups
devices=$out_dir/big_catalogue.devices
: >"$groups"
: >"$devices"
target_bytes=$((target_mb * 1000 * 1000))

# The Beckhoff catalogues with an EtherCATInfo root, largest first. Each has <Groups>, <Devices>
# and their end tags on lines of their own; the lines between are copied. Latin-1 files are
# converted so that the merged file is UTF-8 throughout.
files=$(for f in "$corpus"/Beckhoff__*.xml; do
    if head -c 4096 "$f" | grep -q '<EtherCATInfo'; then echo "$(wc -c <"$f") $f"; fi
done | sort -rn | cut -d' ' -f2-)
as_utf8() {
    if head -c 200 "$1" | grep -qi 'encoding="ISO-\?8859-1"'; then iconv -f ISO-8859-1 -t UTF-8 "$1"; else cat "$1"; fi
}
if [ -z "$files" ]; then
    echo "big_catalogue_rss: no Beckhoff EtherCATInfo catalogue in $corpus" >&2
    exit 2
fi
pass=0
while [ "$(wc -c <"$devices")" -lt "$target_bytes" ]; do
    pass=$((pass + 1))
    before=$(wc -c <"$devices")
    for f in $files; do
        [ "$(wc -c <"$devices")" -ge "$target_bytes" ] && break
        as_utf8 "$f" | tr -d '\r' | awk '/^[ \t]*<\/Devices>[ \t]*$/ { inside = 0 } inside { print } /^[ \t]*<Devices>[ \t]*$/ { inside = 1 }' >>"$devices"
        if [ "$pass" -eq 1 ]; then
            as_utf8 "$f" | tr -d '\r' | awk '/^[ \t]*<\/Groups>[ \t]*$/ { inside = 0 } inside { print } /^[ \t]*<Groups>[ \t]*$/ { inside = 1 }' >>"$groups"
        fi
    done
    if [ "$(wc -c <"$devices")" -eq "$before" ]; then
        echo "big_catalogue_rss: the catalogues in $corpus have no Devices to merge" >&2
        exit 2
    fi
done
{
    printf '<?xml version="1.0" encoding="UTF-8"?>\n'
    printf '<EtherCATInfo Version="1.2">\n\t<Vendor>\n\t\t<Id>2</Id>\n\t\t<Name>Beckhoff Automation GmbH &amp; Co. KG</Name>\n\t</Vendor>\n'
    printf '\t<Descriptions>\n\t\t<Groups>\n'
    cat "$groups"
    printf '\t\t</Groups>\n\t\t<Devices>\n'
    cat "$devices"
    printf '\t\t</Devices>\n\t</Descriptions>\n</EtherCATInfo>\n'
} >"$tmp"
rm -f "$groups" "$devices"
mv "$tmp" "$merged"

bytes=$(wc -c <"$merged")
device_count=$(grep -c '<Device[ >]' "$merged" || true)

# Peak RSS in kB of a command, from GNU time.
peak_kb() {
    /usr/bin/time -f '%M' -o "$out_dir/time.out" "$@" >/dev/null 2>"$out_dir/stderr.out" || true
    tail -n 1 "$out_dir/time.out"
}
bare_kb=$(peak_kb "$build/bench/bare_parse_peak" "$merged")
read_kb=$(peak_kb "$build/bench/lint_stage" read "$merged")
lint_kb=$(peak_kb "$build/cli/esi-lint" -j1 --format json --fail-on never "$merged")
rm -f "$out_dir/time.out" "$out_dir/stderr.out"

# CPU milliseconds (user + system) of a command, from bash's time (millisecond resolution).
cpu_ms() {
    bash -c 'TIMEFORMAT="%3U %3S"; { time "$@" >/dev/null 2>&1; } 2>&1' cpu_ms "$@" | awk '{ printf "%d\n", ($1 + $2) * 1000 }'
}
median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
"$build/cli/esi-lint" -j1 --format json --fail-on never "$merged" >/dev/null 2>&1 || true  # warm the page cache
: >"$out_dir/lint.ms"
: >"$out_dir/bare.ms"
for _ in 1 2 3 4 5; do
    cpu_ms "$build/cli/esi-lint" -j1 --format json --fail-on never "$merged" >>"$out_dir/lint.ms"
    cpu_ms "$build/bench/lint_stage" bare "$merged" >>"$out_dir/bare.ms"
done
lint_ms=$(median <"$out_dir/lint.ms")
bare_ms=$(median <"$out_dir/bare.ms")
rm -f "$out_dir/lint.ms" "$out_dir/bare.ms"

awk -v bytes="$bytes" -v devices="$device_count" -v passes="$pass" -v bare="$bare_kb" -v read="$read_kb" -v lint="$lint_kb" \
    -v lint_ms="$lint_ms" -v bare_ms="$bare_ms" 'BEGIN {
    # One unit throughout: MiB (GNU time reports KiB), the file included.
    mb = bytes / 1e6
    mib = bytes / 1048576
    printf "merged file: %s, %.1f MB = %.1f MiB, %d devices (%d pass%s over the Beckhoff catalogues)\n", "'"$merged"'", mb, mib, devices, passes, passes == 1 ? "" : "es"
    printf "%-34s %9s %8s\n", "peak RSS", "MiB", "x file"
    printf "%-34s %9.1f %8.2f\n", "bare pugixml parse", bare / 1024, bare * 1024 / bytes
    printf "%-34s %9.1f %8.2f\n", "reader only (lint_stage read)*", read / 1024, read * 1024 / bytes
    printf "%-34s %9.1f %8.2f\n", "esi-lint -j1", lint / 1024, lint * 1024 / bytes
    target = 3 * mib + 30
    printf "target: 3 x file + 30 MiB = %.1f MiB; esi-lint %s\n", target, lint / 1024 <= target ? "meets it" : "is over it"
    printf "* lint_stage keeps the file bytes besides the copies the reader makes: one file size more than esi-lint holds\n"
    printf "CPU time, median of 5 in turn: esi-lint -j1 --format json %d ms, lint_stage bare %d ms, ratio %.2f (target 1.6)\n", lint_ms, bare_ms, lint_ms / bare_ms
}'
