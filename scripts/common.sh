# Shared by scripts/run and scripts/test: install what is missing, configure, build.
# Sourced, not executed.

IMPULSE_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
IMPULSE_PACKAGES=(cmake g++ make ccache pkg-config libeigen3-dev libgtest-dev libbenchmark-dev
  libasio-dev libprotobuf-dev protobuf-compiler libsdl2-dev libimgui-dev libcli11-dev
  nlohmann-json3-dev fonts-dejavu-core python3-protobuf
  xvfb libbox2d-dev libchipmunk-dev clang libclang-rt-14-dev)

install_missing_packages() {
  local missing=()
  for package in "${IMPULSE_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "installing: ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# configure_and_build BUILD_DIR [extra cmake args...]
configure_and_build() {
  local build_dir=$1
  shift
  cmake -S "$IMPULSE_ROOT" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  cmake --build "$build_dir" -j 2
}
