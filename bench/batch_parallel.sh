#!/usr/bin/env bash
# scripts/batch over JOBS emulated recordings (default 6, tactical MEMS at rest, DURATION_S each,
# default 600 s at 200 Hz): the wall time with one job at a time and with every core, their
# ratio, and one job's CPU over its wall time (from the serial pass: user + sys of the jobs over
# their wall time; at 1.5 or more a job already uses the cores on its own). Not a test: run by
# hand in a sourced workspace, on a machine nobody else is loading.
#   usage: bench/batch_parallel.sh [jobs=6] [duration_s=600]
set -euo pipefail
jobs=${1:-6}
duration_s=${2:-600}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
recordings=()
for k in $(seq 1 "$jobs"); do
  rosrun imu_lab emulate --profile tactical_mems --duration-s "$duration_s" --rate-hz 200 --seed "$k" --no-truth \
    --out "$work/run$k.bag" > /dev/null
  recordings+=("$work/run$k.bag")
done
measure() {  # wall, user+sys of the children, for one batch run
  local out=$1 parallel=$2
  /usr/bin/python3 - "$root/scripts/batch" "$out" "$parallel" "${recordings[@]}" <<'PY'
import os, subprocess, sys, time
batch, out, parallel, recordings = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
start = time.monotonic(); before = os.times()
subprocess.run([batch, "-o", out, "-j", parallel, *recordings, "--", "--no-plot"], check=True,
               stderr=subprocess.DEVNULL)
wall = time.monotonic() - start; after = os.times()
cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
print(wall, cpu)
PY
}
read -r serial_wall serial_cpu < <(measure "$work/serial" 1)
cores=$(nproc)
read -r parallel_wall parallel_cpu < <(measure "$work/parallel" "$cores")
/usr/bin/python3 - "$jobs" "$duration_s" "$cores" "$serial_wall" "$serial_cpu" "$parallel_wall" "$parallel_cpu" <<'PY'
import sys
jobs, duration, cores = int(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3])
serial_wall, serial_cpu, parallel_wall, parallel_cpu = map(float, sys.argv[4:])
print(f"batch of {jobs} allan jobs ({duration:.0f} s at 200 Hz each) on {cores} cores:")
print(f"  serial (-j 1): {serial_wall:.1f} s wall; one job's CPU over its wall time: {serial_cpu / serial_wall:.2f} cores")
print(f"  parallel (-j {cores}): {parallel_wall:.1f} s wall, {parallel_cpu / parallel_wall / cores * 100:.0f} % of the "
      f"{cores} cores")
print(f"  ratio parallel / serial wall time: {parallel_wall / serial_wall:.2f}")
PY
