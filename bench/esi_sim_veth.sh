#!/bin/sh
# esi-sim over a veth pair in a user and network namespace (no privileges needed): the round trip
# of one LRW frame through esi-sim (bench/esi_sim_frames.cpp --veth), median and 99th percentile
# of 10,000 frames, for one slave and for the sample line.
# Usage, from the repository: bench/esi_sim_veth.sh [BUILD_DIR]   (default build)
set -eu
build=${1:-build}
sim=$build/cli/esi-sim
bench=$build/bench/esi_sim_frames
for source in samples/digital-io-8.yaml samples/networks/line.yaml; do
    unshare -rn sh -c "
        ip link add v0 type veth peer name v1 && ip link set v0 up && ip link set v1 up
        $sim --iface v1 $source 2>/dev/null & pid=\$!
        sleep 1
        echo '== $source'
        $bench --veth v0 10000
        kill \$pid; wait \$pid 2>/dev/null || true"
done
