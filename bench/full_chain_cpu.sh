#!/usr/bin/env bash
# CPU of the stream chain (launch/full_chain.launch: emulator -> thermal_compensator ->
# calibration_corrector -> strapdown_navigator, allan_monitor on /imu/raw; rviz off) at RATE_HZ
# (default 1000), once as separate node processes and once as nodelets in one manager
# (nodelets:=true), one after the other in this one run on a private roscore. For each: the
# utime + stime of every process roslaunch started (/proc/<pid>/stat) over SECONDS_MEASURED
# (default 60) after a warm-up, then their ratio. The sensor and its models are the thermal
# test's (test/data/thermal); the alignment is shortened so the navigator navigates throughout.
# Not a test: run by hand in a sourced workspace.   usage: bench/full_chain_cpu.sh [seconds=60] [rate_hz=1000]
set -euo pipefail
seconds_measured=${1:-60}
rate_hz=${2:-1000}
data=$(rospack find imu_lab)/test/data
source "$(dirname "$0")/private_roscore.sh" 11900

cpu_ticks() {  # utime + stime of the given processes, in clock ticks
  local total=0 pid
  for pid in "$@"; do total=$((total + $(awk '{print $14 + $15}' "/proc/$pid/stat"))); done
  echo "$total"
}

# Prints "<cpu seconds> <process count> <wall seconds measured> <samples allan_monitor received in
# its life> <life in seconds> <navigator aligned: 1/0>" for one way of running the chain.
measure_chain() {
  local nodelets=$1 launch children start_ticks end_ticks start end born samples aligned
  born=$(date +%s.%N)
  roslaunch imu_lab full_chain.launch rviz:=false nodelets:="$nodelets" rate_hz:="$rate_hz" \
    profile:="$data/thermal/uncompensated_mems_gyro.yaml" \
    thermal_model:="$data/thermal/model_uncompensated_mems_gyro.yaml" \
    calibration:="$data/calibration_example.yaml" alignment_duration_s:=2 \
    allan_report_dir:="$ROS_HOME/allan_report_$nodelets" > "$ROS_HOME/launch_$nodelets.log" 2>&1 &
  launch=$!
  pids=("$launch" "${pids[@]}")
  sleep 15  # start-up, connections, alignment
  mapfile -t children < <(pgrep -P "$launch")
  start_ticks=$(cpu_ticks "${children[@]}"); start=$(date +%s.%N)
  sleep "$seconds_measured"
  end_ticks=$(cpu_ticks "${children[@]}"); end=$(date +%s.%N)
  kill -INT "$launch"; wait "$launch" || true  # allan_monitor writes its report on shutdown
  # Did the chain keep up? (No subscriber is added while measuring: it would cost the chain CPU.)
  samples=$(awk '/^samples:/ {print $2}' "$ROS_HOME/allan_report_$nodelets/allan_summary.yaml")
  aligned=$(grep -c "alignment: roll" "$ROS_HOME/launch_$nodelets.log" || true)
  echo "$(echo "($end_ticks - $start_ticks) / $(getconf CLK_TCK)" | bc -l) ${#children[@]} $(echo "$end - $start" | bc -l)" \
    "$samples $(echo "$end - $born" | bc -l) $aligned"
}

read -r -a processes < <(measure_chain false)
read -r -a nodelets < <(measure_chain true)
/usr/bin/python3 - "$rate_hz" "${processes[@]}" "${nodelets[@]}" <<'PY'
import sys
rate = float(sys.argv[1])
def line(label, cpu, count, wall, samples, life, aligned):
    return (f"  {label} ({count:.0f} processes): {cpu:6.2f} s in {wall:.1f} s ({100 * cpu / wall:.1f} % of one core); "
            f"allan_monitor got {samples:.0f} samples in {life:.0f} s of life, navigator {'aligned' if aligned else 'NOT ALIGNED'}")
p = list(map(float, sys.argv[2:8]))
n = list(map(float, sys.argv[8:14]))
print(f"full chain at {rate:.0f} Hz, CPU seconds of all its processes over the measured interval:")
print(line("separate nodes", *p))
print(line("one nodelet manager and its loaders", *n))
print(f"  separate nodes / nodelets: {(p[0] / p[2]) / (n[0] / n[2]):.2f}x")
PY
