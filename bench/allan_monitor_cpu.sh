#!/usr/bin/env bash
# allan_monitor's CPU share at a high input rate: the emulator node publishes /imu/raw at RATE_HZ
# (default 2000) into allan_monitor on a private roscore; the node's utime + stime from
# /proc/<pid>/stat over SECONDS_MEASURED (default 60) after a warm-up, as a share of one core, and
# its CPU per sample over its whole life (samples from the report it writes on shutdown). Not a
# test: run by hand in a sourced workspace.   usage: bench/allan_monitor_cpu.sh [seconds=60] [rate_hz=2000]
set -euo pipefail
seconds_measured=${1:-60}
rate_hz=${2:-2000}
report=$(mktemp -d)
source "$(dirname "$0")/private_roscore.sh" 11500
rosrun imu_lab allan_monitor _report_dir:="$report" _plot:=false > /dev/null 2>&1 & monitor=$!
pids=("$monitor" "${pids[@]}")
rosrun imu_lab imu_emulator _rate_hz:="$rate_hz" _publish_truth:=false _publish_increments:=false \
  > /dev/null 2>&1 & emulator=$!
pids=("$emulator" "${pids[@]}")

cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }   # utime + stime, in clock ticks

sleep 10  # warm-up (tau0 fixed after 1000 samples) and connections
ticks_start=$(cpu_ticks "$monitor"); emulator_start=$(cpu_ticks "$emulator")
start=$(date +%s.%N)
sleep "$seconds_measured"
ticks_end=$(cpu_ticks "$monitor"); emulator_end=$(cpu_ticks "$emulator")
elapsed=$(echo "$(date +%s.%N) - $start" | bc -l)
kill -INT "$emulator"; kill -INT "$monitor"; wait "$monitor" || true  # the monitor writes its report
samples=$(awk '/^samples:/ {print $2}' "$report/allan_summary.yaml")
hz=$(getconf CLK_TCK)
/usr/bin/python3 - "$ticks_start" "$ticks_end" "$emulator_start" "$emulator_end" "$samples" "$elapsed" "$hz" \
  "$rate_hz" <<'PY'
import sys
t0, t1, e0, e1, samples, elapsed, hz, rate = map(float, sys.argv[1:])
print(f"allan_monitor at {rate:.0f} Hz input: {100 * (t1 - t0) / hz / elapsed:.1f} % of one core over {elapsed:.1f} s "
      f"(emulator: {100 * (e1 - e0) / hz / elapsed:.1f} %)")
print(f"samples received in its life: {samples:.0f}; CPU per sample over its life: {1e6 * t1 / hz / samples:.1f} us")
PY
