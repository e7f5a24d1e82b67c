#!/bin/bash
# One allan analysis per recording as a Slurm array job; merge the results afterwards with
# scripts/merge_results (the same step as after scripts/batch). RECORDINGS is a text file with one
# recording per line (a bag, or the split files of one joined with commas). Submit:
#
#   n=$(wc -l < recordings.txt)
#   sbatch --array=0-$((n - 1)) scripts/slurm_array_example.sh recordings.txt results
#   # when the array has finished:
#   scripts/merge_results -o merged results/*
#
# Each task reads line SLURM_ARRAY_TASK_ID (from 0) and writes results/<name>/ and its job.log;
# the tasks share nothing, so they run the same way as plain processes on one machine
# (test/ros/test_batch_scripts.cpp runs them so). The workspace must be sourced on the nodes
# (e.g. `source .ws/devel/setup.bash` in your job's environment).
#SBATCH --job-name=imu_lab_allan
#SBATCH --cpus-per-task=1
#SBATCH --output=slurm-%A_%a.out
set -euo pipefail
recordings=${1:?usage: slurm_array_example.sh RECORDINGS_FILE OUT_DIR [-- ALLAN ARGUMENTS]}
out=${2:?usage: slurm_array_example.sh RECORDINGS_FILE OUT_DIR [-- ALLAN ARGUMENTS]}
shift 2
[[ ${1:-} == "--" ]] && shift
task=${SLURM_ARRAY_TASK_ID:?not run as a Slurm array task (set SLURM_ARRAY_TASK_ID to run one by hand)}
recording=$(sed -n "$((task + 1))p" "$recordings")
[[ -n $recording ]] || { echo "slurm_array_example: no line $((task + 1)) in $recordings" >&2; exit 2; }
first=$(basename "${recording%%,*}")
name=${first%.bag}
mkdir -p "$out/$name"
IFS=, read -r -a files <<< "$recording"
rosrun imu_lab allan "${files[@]}" -o "$out/$name" "$@" > "$out/$name/job.log" 2>&1
