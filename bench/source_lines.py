#!/usr/bin/env python3
"""Lines of C++ code (.h and .cpp) at a git revision: per file and per
folder, counting the lines that hold code once comments are removed
(/* ... */ and // ...; a "//" inside a string literal is taken for a
comment, which GRFLOW's sources do not have) and blank lines dropped.

usage: source_lines.py [--rev REV] PATH...     (default REV: HEAD)

For example the adapters before and after issue 40:
    python3 bench/source_lines.py --rev bf1f6c7 src/GRFLOW src/LIGGGHTS
    python3 bench/source_lines.py src/GRFLOW src/LIGGGHTS
Standard library only; run from inside the repository.
"""
import argparse
import re
import subprocess
import sys


def code_lines(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return sum(1 for line in text.splitlines() if re.sub(r"//.*", "", line).strip())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rev", default="HEAD")
    ap.add_argument("paths", nargs="+")
    args = ap.parse_args()
    files = subprocess.run(["git", "ls-tree", "-r", "--name-only", args.rev, "--"] + args.paths,
                           capture_output=True, text=True, check=True).stdout.split()
    files = [f for f in files if f.endswith((".h", ".cpp"))]
    if not files:
        raise SystemExit(f"source_lines.py: no .h or .cpp file under {args.paths} at {args.rev}")
    folders = {}
    for f in files:
        text = subprocess.run(["git", "show", f"{args.rev}:{f}"], capture_output=True,
                              text=True, check=True).stdout
        n = code_lines(text)
        folder = f.rsplit("/", 1)[0]
        folders[folder] = folders.get(folder, 0) + n
        print(f"{n:6d} {f}")
    for folder, n in sorted(folders.items()):
        print(f"{n:6d} {folder}/ (total)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
