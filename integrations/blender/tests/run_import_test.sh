#!/bin/sh
# integrations/blender/tests/run_import_test.sh — the Blender add-on's import test (CTest
# `blender_import`): synthesizes two example scenes with the built CLI as `make demo`
# does (scripts/demo: bananas_3d with physics, spaghetti_3d on the plate), then imports
# them, a fixture of mixed element kinds and three exemplars (2D and 3D) in Blender and
# checks the result (check_import.py); then animated files keyed per frame
# (check_animation_import.py).
#
#   run_import_test.sh TESSERA_CLI SOURCE_DIR WORK_DIR
#
# Exit 0: passed; 77: skipped (blender is not available and cannot be installed; CTest
# reports the test as skipped); anything else: failed.
set -eu
if [ $# -ne 3 ]; then
  echo "usage: $0 TESSERA_CLI SOURCE_DIR WORK_DIR" >&2
  exit 2
fi
cli=$1
src=$2
work=$3
mkdir -p "$work"

skip() {
  echo "SKIPPED: blender not available: $1"
  exit 77
}

# Blender: on PATH, else installed with apt-get when that is possible without a password.
if ! command -v blender >/dev/null 2>&1; then
  if ! command -v apt-get >/dev/null 2>&1; then
    skip "not on PATH, and there is no apt-get to install it"
  fi
  if [ "$(id -u)" -eq 0 ]; then
    sudo=""
  elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    sudo="sudo -n"
  else
    skip "not on PATH, and installing it needs root or passwordless sudo"
  fi
  echo "blender is not on PATH: installing it (apt-get install blender; log in $work/apt.log)"
  export DEBIAN_FRONTEND=noninteractive
  if ! $sudo apt-get install -y -qq --no-install-recommends blender >"$work/apt.log" 2>&1; then
    $sudo apt-get update -qq >>"$work/apt.log" 2>&1 || true
    $sudo apt-get install -y -qq --no-install-recommends blender >>"$work/apt.log" 2>&1 ||
      skip "apt-get install blender failed: $(tail -n 1 "$work/apt.log")"
  fi
  command -v blender >/dev/null 2>&1 || skip "still not on PATH after apt-get install blender"
fi
if ! version=$(blender --version 2>&1); then
  skip "'blender --version' fails: $(echo "$version" | tail -n 1)"
fi
echo "$version" | head -n 1

# Outputs of the demo (scripts/demo, "scene" runs), a few seconds each.
scenes="$src/examples/scenes"
"$cli" synth "$scenes/bananas_3d.json" -o "$work/bananas_3d.json" --domain box:16,16,1.4 --physics --seed 1 --quiet
"$cli" synth "$scenes/spaghetti_3d.json" -o "$work/spaghetti_3d.json" --domain "mesh:$scenes/plate.obj" --seed 1 --quiet

TESSERA_CLI=$cli blender --background --factory-startup --python-exit-code 1 \
  --python "$src/integrations/blender/tests/check_import.py" -- \
  "$work/bananas_3d.json" "$work/spaghetti_3d.json" "$src/integrations/blender/tests/data/mixed_3d.json" \
  "$scenes/carrots_2d.json" "$src/examples/two_class_2d.json" "$src/examples/sticks_2d.json"

# Animated files, keyed per frame: a fixture of every element kind (written by the check),
# a synthesized animation and its exemplar.
"$cli" synth "$src/examples/dynamic/drifting_lattice_2d.json" -o "$work/drift_anim.json" --frames 6 --scale 1.2 --seed 1 --quiet
blender --background --factory-startup --python-exit-code 1 \
  --python "$src/integrations/blender/tests/check_animation_import.py" -- \
  "$work" "$work/drift_anim.json" "$src/examples/dynamic/drifting_lattice_2d.json"
