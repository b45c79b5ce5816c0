#!/usr/bin/env bash
# Installs vkpt's build and test dependencies from Debian 12 (bookworm) packages.
# Needs root (or sudo). Safe to run again: apt-get skips what is installed.
set -euo pipefail

packages=(
  build-essential cmake pkg-config      # compiler and build
  libvulkan-dev mesa-vulkan-drivers     # Vulkan loader + lavapipe (software Vulkan on the CPU)
  vulkan-validationlayers vulkan-tools  # validation layer for tests, vulkaninfo
  glslang-tools spirv-tools             # GLSL -> SPIR-V at build time, spirv-val
  libglm-dev                            # vector math shared by C++ and GLSL headers
  libtinygltf-dev nlohmann-json3-dev    # glTF loading and schema checks
  libstb-dev libtinyexr-dev             # PNG and EXR writers
  libwebp-dev                           # EXT_texture_webp textures
  libdraco-dev libmeshoptimizer-dev     # KHR_draco_mesh_compression, EXT_meshopt_compression
  pybind11-dev python3-dev              # the Python module (import vkpt)
  python3-numpy                         # its arrays
  python3-pytest python3-venv           # its tests, and installing it into a virtual environment
  python3-setuptools python3-wheel      # its wheel (cmake --build build --target wheel)
  python3-mypy                          # its type stubs' tests (stubtest, mypy)
  libgtest-dev                          # tests
  colord-data                           # tests: the CIE 1931 matching functions (iridescence, dispersion)
  libglfw3-dev libimgui-dev             # the viewer's window (vkpt --interactive) and its overlay
  xvfb xdotool x11-utils imagemagick    # tests: the viewer on a virtual X server, input sent, pixels read
  libembree-dev                         # vkpt-bench compares against Embree
  libopenmpi-dev openmpi-bin            # optional: mpirun -n N vkpt shares a frame (tests use it)
  clang-format                          # scripts/check-format.sh
  clang-14 libclang-rt-14-dev           # the loader fuzzer: clang++ and libFuzzer's runtime
  llvm-14                               # llvm-symbolizer: sanitizer reports with file:line
  ccache                                # CI: the build without MPI reuses the plain build's objects
)
# (g++'s AddressSanitizer and UBSan runtimes, libasan8 and libubsan1, come with g++.)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages are installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
