#!/bin/sh
# esi-sim over a veth pair in a user and network namespace (no privileges needed):
#  1. the round trip of one LRW frame through esi-sim (bench/esi_sim_frames.cpp --veth), median
#     and 99th percentile of 10,000 frames, for one slave and for the sample line;
#  2. the time SOEM 2.x needs from ecx_init to OP (the esi-sim tests' master, built in the test
#     tree as tests/esi_soem_master), for one sample and for samples/networks/line.yaml.
# Usage, from the repository: bench/esi_sim_veth.sh [BUILD_DIR]   (default build)
set -eu
build=${1:-build}
sim=$build/cli/esi-sim
bench=$build/bench/esi_sim_frames
master=$build/tests/esi_soem_master
for source in samples/digital-io-8.yaml samples/networks/line.yaml; do
    unshare -rn sh -c "
        ip link add v0 type veth peer name v1 && ip link set v0 up && ip link set v1 up
        $sim --iface v1 $source 2>/dev/null & pid=\$!
        sleep 1
        echo '== $source'
        $bench --veth v0 10000
        if [ -x $master ]; then
            $master v0 --cycles 10 --state-timeout-ms 3000 | sed -n 's/.*\"op\":\([a-z]*\),\"to_op_ms\":\([0-9.]*\).*/SOEM ecx_init to OP: \2 ms (OP reached: \1)/p'
        fi
        kill \$pid; wait \$pid 2>/dev/null || true"
done
