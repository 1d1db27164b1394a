#!/usr/bin/env bash
# The one list of Debian packages cutaway needs. Idempotent and non-interactive:
# installs only what is missing, so a second run costs a few seconds.
set -euo pipefail

packages=(
  # build
  cmake g++ make pkg-config git
  # geometry (generators/ only)
  libcgal-dev libgmp-dev libmpfr-dev
  # graphics: headless EGL on Mesa llvmpipe, GLFW viewer, maths
  libegl-dev libgl1-mesa-dri libegl-mesa0 libepoxy-dev libglfw3-dev libglm-dev libimgui-dev xvfb xauth
  # images, seismic, formats, command line
  libpng-dev libstb-dev libsegyio-dev nlohmann-json3-dev libcli11-dev
  # animations: the ffmpeg program encodes H.264 MP4 (cutaway animate), ffprobe checks it in tests
  ffmpeg
  # tests, benchmarks, reference checks, fuzzing
  libgtest-dev libgmock-dev libbenchmark-dev libboost-test-dev clang libclang-rt-14-dev libomp-dev
  # simulator results (src/eclipse/: opm-common's EclIO; also the reference checks against EclipseGrid)
  # and OPM Flow, which writes the test cases and runs `generate --deck` decks
  libopm-common-dev libopm-simulators-bin
  # plots
  python3 python3-matplotlib python3-scipy python3-vtk9
  # distributed rendering (src/distributed/, CUTAWAY_MPI): OpenMPI and ParaView's IceT compositor
  libopenmpi-dev openmpi-bin paraview-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
