#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Every source file of Tessella starts with its licence, as two SPDX lines
(https://spdx.org/licenses/AGPL-3.0-or-later.html; LICENSE has the text).

  scripts/licence_headers.py --check [--root DIR]   list files without them (exit 1 if any)
  scripts/licence_headers.py --add [--root DIR]     add them where missing

Which files: the ones git tracks (and untracked ones it does not ignore) with a
source ending below; data, docs, configs and test fixtures are not code.
A script's `#!` line stays first; the header goes right after it.
"""

import argparse
import pathlib
import subprocess
import sys

COPYRIGHT = "SPDX-FileCopyrightText: 2026 The Tessella developers"
LICENCE = "SPDX-License-Identifier: AGPL-3.0-or-later"

# comment leader by file ending or name
SLASH = {".cpp", ".hpp", ".h", ".cc", ".c"}
HASH = {".py", ".sh", ".cmake", ".smk"}
HASH_NAMES = {"CMakeLists.txt", "Snakefile", "run"}  # run: .ci/run
SKIP_DIRS = ("tests/data/", "build/", "docs/")


def leader(path: pathlib.Path):
    if path.suffix in SLASH:
        return "//"
    if path.suffix in HASH or path.name in HASH_NAMES:
        return "#"
    return None


def source_files(root: pathlib.Path):
    try:
        listed = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"], cwd=root,
                                check=True, capture_output=True, text=True).stdout.split("\n")
    except (OSError, subprocess.CalledProcessError):  # not a git checkout (a source archive): every file
        listed = [str(p.relative_to(root)) for p in root.rglob("*") if not p.name.startswith(".")]
    for name in sorted(set(filter(None, listed))):
        if name.startswith(SKIP_DIRS):
            continue
        path = root / name
        if path.name == "run" and path.parent.name != ".ci":
            continue
        if leader(path) and path.is_file():
            yield path


def has_header(lines, mark):
    head = lines[:4]
    return f"{mark} {COPYRIGHT}" in head and f"{mark} {LICENCE}" in head


def add_header(path: pathlib.Path, mark: str) -> None:
    text = path.read_text(encoding="utf-8")
    lines = text.split("\n")
    header = [f"{mark} {COPYRIGHT}", f"{mark} {LICENCE}"]
    at = 1 if lines and lines[0].startswith("#!") else 0
    path.write_text("\n".join(lines[:at] + header + lines[at:]), encoding="utf-8")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--check", action="store_true", help="list files without the header; exit 1 if any")
    mode.add_argument("--add", action="store_true", help="add the header where it is missing")
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent, type=pathlib.Path)
    args = parser.parse_args()

    missing = []
    for path in source_files(args.root):
        mark = leader(path)
        lines = path.read_text(encoding="utf-8").split("\n")
        if not has_header(lines, mark):
            missing.append(path)
            if args.add:
                add_header(path, mark)
    relative = [str(p.relative_to(args.root)) for p in missing]
    if args.add:
        print(f"added the licence header to {len(missing)} files")
        return 0
    if missing:
        print(f"{len(missing)} source files lack the two SPDX lines ('{COPYRIGHT}', '{LICENCE}') at the top; "
              "run scripts/licence_headers.py --add:")
        for name in relative:
            print("  " + name)
        return 1
    print("every source file carries the licence header")
    return 0


if __name__ == "__main__":
    sys.exit(main())
