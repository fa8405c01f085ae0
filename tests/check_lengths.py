#!/usr/bin/env python3
"""No source file over 600 lines (the developers' guide: one concept per short file).

Checked: the code of the repository (C++, Python, JavaScript, shell, CMake, HTML, CSS) under
the top folders and at the root; not the docs, data, or what a build or npm writes
(build*/, web/node_modules/, web/dist/). Prints one line per file that is too long, with its
length, and exits 1 if there is any. `--root DIR` checks another tree, which must hold solver/
(exit 2 otherwise: an empty folder would pass); the self-test writes one with a file one line
too long and one at the limit.
"""
import argparse
import os
import sys
import tempfile
from pathlib import Path

LIMIT = 600
CODE_SUFFIXES = {".cpp", ".hpp", ".h", ".py", ".js", ".mjs", ".sh", ".cmake", ".html", ".css"}
CODE_NAMES = {"CMakeLists.txt", "Dockerfile"}
SKIPPED_DIRS = {".git", "node_modules", "dist", "__pycache__"}


def code_files(root):
    for folder, dirs, files in os.walk(root):
        rel = Path(folder).relative_to(root)
        dirs[:] = [d for d in dirs
                   if d not in SKIPPED_DIRS and not (rel == Path(".") and d.startswith("build"))]
        for name in files:
            if Path(name).suffix in CODE_SUFFIXES or name in CODE_NAMES:
                yield Path(folder) / name


def too_long(root):
    found = []
    for path in code_files(root):
        with open(path, encoding="utf-8", errors="replace") as f:
            n = sum(1 for _ in f)
        if n > LIMIT:
            found.append((path.relative_to(root), n))
    return sorted(found)


def is_project_tree(root):
    """An empty or wrong folder would have no files to find and pass: it is refused."""
    return (root / "solver").is_dir()


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        (root / "solver").mkdir()
        (root / "solver" / "long.cpp").write_text("x\n" * (LIMIT + 1))
        (root / "solver" / "at_limit.py").write_text("x\n" * LIMIT)
        (root / "build-x").mkdir()
        (root / "build-x" / "generated.cpp").write_text("x\n" * (2 * LIMIT))
        if is_project_tree(root / "build-x"):
            print("self-test: a folder without solver/ was taken for the project's tree")
            return 1
        found = [str(p) for p, _ in too_long(root)]
        if found != [os.path.join("solver", "long.cpp")]:
            print("self-test: expected only solver/long.cpp, found %s" % found)
            return 1
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", default=str(Path(__file__).resolve().parent.parent))
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    root = Path(args.root)
    if not is_project_tree(root):
        print("--root %s: not the project's tree (no solver/ folder in it)" % root)
        return 2
    found = too_long(root)
    for path, n in found:
        print("%s: %d lines (at most %d: split it by concept)" % (path, n, LIMIT))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
