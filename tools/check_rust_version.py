#!/usr/bin/env python3
"""Check that Cargo.toml's `rust-version` covers every locked dependency.

Reads `cargo metadata` (the lock file's resolution for the given target platforms) and compares
each package's own `rust_version` with rollbem's. Exits 1, naming the packages, when a locked
dependency needs a newer Rust than Cargo.toml promises; 0 otherwise (with a note when the promise
is above every dependency's need: rollbem's own code may need it, which `cargo clippy` checks
through its `incompatible_msrv` lint). Needs only cargo and the standard library: no other
toolchain is installed, the declared versions are compared.
"""
import argparse
import json
import subprocess
import sys

PLATFORMS = ["x86_64-unknown-linux-gnu", "aarch64-apple-darwin", "x86_64-pc-windows-msvc"]


def version(text):
    parts = [int(x) for x in text.split(".")]
    return tuple(parts + [0] * (3 - len(parts)))


def needs(platform):
    """(rust_version, name, version) of every package resolved for `platform`."""
    meta = json.loads(
        subprocess.run(
            ["cargo", "metadata", "--format-version", "1", "--locked", "--filter-platform", platform],
            check=True,
            capture_output=True,
            text=True,
        ).stdout
    )
    resolved = {node["id"] for node in meta["resolve"]["nodes"]}
    root = meta["resolve"]["root"]
    own = next(p for p in meta["packages"] if p["id"] == root)
    deps = [
        (version(p["rust_version"]), p["name"], p["version"])
        for p in meta["packages"]
        if p["id"] in resolved and p["id"] != root and p.get("rust_version")
    ]
    return version(own["rust_version"]), deps


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--platform", action="append", help=f"target triple (default: {', '.join(PLATFORMS)})")
    platforms = ap.parse_args().platform or PLATFORMS
    declared, highest, problems = None, None, []
    for platform in platforms:
        declared, deps = needs(platform)
        for need, name, ver in deps:
            if need > declared:
                problems.append(f"{name} {ver} needs Rust {'.'.join(map(str, need))} ({platform})")
        top = max(deps)
        highest = top if highest is None else max(highest, top)
    shown = ".".join(map(str, declared))
    if highest and highest[0] < declared:
        print(f"note: rust-version {shown} is above what any locked dependency needs")
    for p in problems:
        print("FAIL", p)
    print(f"rust-version {shown}: highest locked need {highest[1]} {highest[2]} "
          f"(Rust {'.'.join(map(str, highest[0]))}), {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
