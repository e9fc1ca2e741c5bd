#!/usr/bin/env python3
"""Check that no folder of the library includes a folder of a higher layer.

The layers, from the driver down to the scene description (doc/architecture.md):
a folder may include its own layer and any layer below it, never one above.
Exit code 1 and one line per offending include otherwise.
"""
import pathlib
import re
import sys

LAYERS = [
    ["time"],
    ["analysis"],
    ["mechanisms"],
    ["mechanics", "io"],
    ["grid"],
    ["geometry"],
    ["level_set"],
    ["scene"],
]
RANK = {folder: rank for rank, names in enumerate(LAYERS) for folder in names}
INCLUDE = re.compile(r'#include\s*<levelsinter/([a-z_]+)/')


def folder_of(path, root):
    parts = path.relative_to(root).parts
    # include/levelsinter/FOLDER/... or source/FOLDER/...
    return parts[2] if parts[0] == "include" else parts[1]


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    files = sorted(list((root / "include" / "levelsinter").rglob("*.h")) +
                   [p for p in (root / "source").rglob("*.cc")
                    if p.parent != root / "source"])
    errors = []
    for path in files:
        folder = folder_of(path, root)
        if folder not in RANK:
            errors.append(f"{path.relative_to(root)}: folder '{folder}' has "
                          "no layer in scripts/check_layers.py")
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = INCLUDE.match(line.strip())
            if match and RANK.get(match.group(1), -1) < RANK[folder]:
                errors.append(f"{path.relative_to(root)}:{number}: "
                              f"'{folder}' includes the higher layer "
                              f"'{match.group(1)}'")
    for error in errors:
        print(error)
    print(f"{len(files)} files checked, {len(errors)} layer violations")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
