#!/usr/bin/env bash
# Runs every command of docs/tutorial.md in a scratch copy of docs/tutorial/ (CI runs this).
# Needs: the release binary (cargo build --release) and a Python with tools/requirements.txt
# (PYTHON, default python3; its folder must also hold the `gmsh` command of the gmsh wheel).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
PYTHON=${PYTHON:-python3}
export PATH="$root/target/release:$(dirname "$PYTHON"):$PATH"
work=$(mktemp -d)
cp "$root/docs/tutorial/roller.geo" "$root/docs/tutorial/roller_on_steel.yaml" "$work/"
cd "$work"
# --- the tutorial's commands ---
gmsh roller.geo -1 -order 2 -format msh41 -o roller.msh
rollbem check roller_on_steel.yaml
rollbem run roller_on_steel.yaml
"$PYTHON" "$root/tools/inspect.py" out -o roller.png
"$PYTHON" "$root/tools/check_outputs.py" out
"$PYTHON" - <<'PY'
import pyvista as pv
reader = pv.get_reader("out/result.pvd")
block = reader.read()
print([block.get_block_name(i) for i in range(block.n_blocks)])
roller = pv.read("out/boundary_A.vtu")
print("largest displacement of the roller [mm]:", abs(roller["displacement"]).max())
PY
# --- end ---
test -s roller.png
cp roller.png "${TUTORIAL_PNG:-/dev/null}" 2>/dev/null || true
echo "tutorial: ok ($work)"
