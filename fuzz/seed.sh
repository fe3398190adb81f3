#!/bin/sh
# Fills the seed corpora of the fuzz targets from the repository's cases and test meshes:
# cases/*.yaml for case_parse; the sections (after the $MeshFormat header) of the ASCII and
# binary meshes of tests/data/msh and meshes/ for msh_ascii and msh_binary, and the regression
# inputs of tests/data/msh/fuzz/ (earlier findings, sections only) for the target they belong to.
set -e
cd "$(dirname "$0")"
mkdir -p corpus/case_parse corpus/msh_ascii corpus/msh_binary
cp ../cases/*.yaml corpus/case_parse/
for f in ../tests/data/msh/*.msh ../meshes/*.msh; do
  name=$(basename "$f")
  # Drop the first three lines ($MeshFormat, version, $EndMeshFormat; binary files keep their
  # byte-order mark on the version line's successor, so drop four lines there).
  if head -2 "$f" | grep -q '^4.1 1 8'; then
    tail -n +5 "$f" > "corpus/msh_binary/$name"
  elif head -2 "$f" | grep -q '^4.1 0 8'; then
    tail -n +4 "$f" > "corpus/msh_ascii/$name"
  fi
done
for f in ../tests/data/msh/fuzz/*_ascii.sections; do cp "$f" corpus/msh_ascii/; done
for f in ../tests/data/msh/fuzz/*_binary.sections; do cp "$f" corpus/msh_binary/; done
