#!/usr/bin/env python3
"""Convert SVG pictures (rollbem's contact.svg) to PNG with cairosvg.

usage: svg_to_png.py IN.svg OUT.png [IN.svg OUT.png ...] [--scale S]

CI regenerates docs/img/contact_*.png with it from the shipped cases' runs (.ci/run), so the
pictures in docs/outputs.md are what rollbem draws now. Needs the Python environment of
tools/requirements.txt (cairosvg, which uses the system's libcairo).
"""
import argparse
import os
import sys

# Keep tools/ (with its inspect.py, named like the standard library's module) off the path.
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]

import cairosvg  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+", metavar="IN.svg OUT.png", help="pairs of input SVG and output PNG")
    parser.add_argument("--scale", type=float, default=1.0, help="pixels per SVG unit (default 1)")
    args = parser.parse_args()
    if len(args.files) % 2:
        parser.error("give the files in pairs: IN.svg OUT.png")
    for svg, png in zip(args.files[::2], args.files[1::2]):
        cairosvg.svg2png(url=svg, write_to=png, scale=args.scale, background_color="white")
        if os.path.getsize(png) == 0:
            sys.exit(f"svg_to_png: {png} is empty")
        print(f"{svg} -> {png}")


if __name__ == "__main__":
    main()
