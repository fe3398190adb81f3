#!/usr/bin/env bash
# Runs docs/tutorial.md as written, as CI does: every ```sh block of the page, in order, in one
# shell (`bash -e`), starting in the root of a fresh copy of the repository (the files git
# would commit: tracked and untracked-but-not-ignored), then checks what the page quotes:
#   * every line of the ```text block after the page's "tools/tutorial.sh checks" comment appears
#     in the output of the commands (so the quoted run cannot go stale);
#   * every line of the ```yaml block is in docs/tutorial/roller_on_steel.yaml;
# and copies the picture the page makes (docs/tutorial/roller.png) to docs/img/tutorial.png.
#
# Usage: bash tools/tutorial.sh [WORK_DIR]   (default target/tutorial; CI's python clients then
# use WORK_DIR/repo/.venv, the environment the tutorial's set-up made).
# The copy lives at a fixed place and its `target` is a link to this repository's target/, so
# the tutorial's `cargo build --release` finds the build up to date instead of starting cold: a
# cache, as a CI runner would keep one; the commands themselves run unchanged.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$root/target/tutorial}
page=$root/docs/tutorial.md
copy=$work/repo
rm -rf "$copy"
mkdir -p "$copy"
(cd "$root" && git ls-files -z --cached --others --exclude-standard \
  | while IFS= read -r -d '' f; do [ -e "$f" ] && printf '%s\0' "$f"; done \
  | tar --null -T - -cf -) | tar -xf - -C "$copy"
target_dir=$(cd "$root/target" && pwd)
ln -s "$target_dir" "$copy/target"

# The page's sh blocks, in order, verbatim; each is echoed before it runs.
awk '/^```sh$/ {on = 1; body = ""; next}
     on && /^```$/ {on = 0; n++
       printf "cat <<\x27__TUTORIAL_BLOCK__\x27\n# --- docs/tutorial.md, sh block %d ---\n%s__TUTORIAL_BLOCK__\n%s", n, body, body
       next}
     on {body = body $0 "\n"}' "$page" > "$work/tutorial_commands.sh"
echo "tutorial: running the sh blocks of docs/tutorial.md in $copy"
(cd "$copy" && env -u VIRTUAL_ENV -u PYTHONSAFEPATH bash -e -o pipefail "$work/tutorial_commands.sh") 2>&1 \
  | tee "$work/tutorial_output.txt"

# The quoted output.
awk '/tools\/tutorial.sh checks/ {armed = 1; next} armed && /^```text$/ {on = 1; next}
     on && /^```$/ {exit} on' "$page" > "$work/quoted_output.txt"
test -s "$work/quoted_output.txt" || { echo "tutorial: no checked output block found in $page"; exit 1; }
missing=0
while IFS= read -r line; do
  if ! grep -qxF -- "$line" "$work/tutorial_output.txt"; then
    echo "tutorial: quoted line not in the output: $line"
    missing=1
  fi
done < "$work/quoted_output.txt"
[ "$missing" = 0 ] || { echo "tutorial: docs/tutorial.md quotes output the commands no longer print"; exit 1; }

# The quoted case.
strip() { sed -e 's/[[:space:]]*#.*$//' -e 's/[[:space:]]*$//' -e '/^$/d' "$@"; }
awk '/^```yaml$/ {on = 1; next} on && /^```$/ {exit} on' "$page" | strip > "$work/quoted_case.txt"
strip "$root/docs/tutorial/roller_on_steel.yaml" > "$work/case.txt"
if ! grep -vxF -f "$work/case.txt" "$work/quoted_case.txt" > "$work/case_diff.txt"; then :; fi
if [ -s "$work/case_diff.txt" ]; then
  echo "tutorial: lines of the page's yaml block not in docs/tutorial/roller_on_steel.yaml:"
  cat "$work/case_diff.txt"
  exit 1
fi

test -s "$copy/docs/tutorial/roller.png"
cp "$copy/docs/tutorial/roller.png" "$root/docs/img/tutorial.png"
echo "tutorial: ok (ran in $copy; docs/img/tutorial.png regenerated)"
