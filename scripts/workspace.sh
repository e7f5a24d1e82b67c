# Sourced by the other scripts: where the catkin workspace lives and how to build it.
# The workspace is git-ignored .ws/ by default; its src/imu_lab/ holds one link per top-level
# entry of this repository. (Linking the repository itself would put .ws inside its own src/:
# rosrun's `find -L` then loops.)
IMU_LAB_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
IMU_LAB_WS=${IMU_LAB_WS:-$IMU_LAB_ROOT/.ws}

# Debian's python3 has the ROS modules; a pyenv python3 on PATH does not.
IMU_LAB_CATKIN_ARGS=(
  -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3
  -DCMAKE_BUILD_TYPE=Release -DCATKIN_ENABLE_TESTING=ON
)
# A rebuild after a checkout, and a build in a second clone or worktree, reuse earlier compiles.
# The compiler sees sources through the workspace's links, so paths relative to the repository
# root are the same in every clone.
if command -v ccache >/dev/null; then
  IMU_LAB_CATKIN_ARGS+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$IMU_LAB_ROOT}
  export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-5G}
fi

imu_lab_link_sources() {
  local package="$IMU_LAB_WS/src/imu_lab" entry name
  [[ -L "$package" ]] && rm "$package"  # an older layout linked the whole repository
  mkdir -p "$package"
  for entry in "$package"/*; do  # links to entries the repository no longer has
    [[ -L "$entry" && ! -e "$entry" ]] && rm "$entry"
  done
  for entry in "$IMU_LAB_ROOT"/*; do
    name=$(basename "$entry")
    [[ "$name" == report ]] && continue
    ln -sfn "$entry" "$package/$name"
  done
}

imu_lab_build() {
  imu_lab_link_sources
  (cd "$IMU_LAB_WS" && catkin_make -j"${IMU_LAB_JOBS:-2}" "${IMU_LAB_CATKIN_ARGS[@]}" "$@")
}

imu_lab_source() {
  # setup.bash reads unset variables; relax nounset while sourcing it.
  set +u
  # shellcheck disable=SC1091
  source "$IMU_LAB_WS/devel/setup.bash"
  set -u
}
