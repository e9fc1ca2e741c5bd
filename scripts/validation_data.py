"""The rule for files a study writes into doc/validation_data.

A committed history there can be the product of hours of runs (the
154-particle coupled run: 50 steps in several sittings); a rerun of its
study test that stops earlier (12 steps) must not replace it. So a study
refuses to replace a file in a validation_data folder that holds more data
rows than the one it would write, unless LEVELSINTER_REPLACE_SHORTER=1 is
set in the environment (doc/validation.md, "The paper's 154-particle
packings"). Outside a
validation_data folder (a build tree) files are replaced as usual.

    import validation_data
    validation_data.refuse_shorter(path, rows)   # before writing anything
"""
import os
import sys
from pathlib import Path

ENVIRONMENT = "LEVELSINTER_REPLACE_SHORTER"


def header_and_rows(path):
    """The header and the non-empty lines after it of CSV file path."""
    with open(path) as f:
        lines = [line for line in f.read().splitlines() if line.strip()]
    return (lines[0] if lines else ""), lines[1:]


def refuse_shorter(path, rows):
    """Exit with a message if path is in a validation_data folder and holds
    more data rows than rows (a number, or the rows to be written), unless
    LEVELSINTER_REPLACE_SHORTER=1. Call before writing any output, so that
    a refused study leaves its plots as they were too."""
    path = Path(path)
    count = rows if isinstance(rows, int) else len(rows)
    if "validation_data" not in path.resolve().parts[:-1] or \
            not path.is_file() or os.environ.get(ENVIRONMENT) == "1":
        return
    header, old = header_and_rows(path)
    if len(old) <= count:
        return
    last = f"{header.split(',')[0]} {old[-1].split(',')[0]}"
    sys.exit(f"{Path(sys.argv[0]).name}: error: '{path}' holds {len(old)} "
             f"rows (the last: {last}); this run gives {count}. A "
             f"shorter history does not replace a longer one: nothing was "
             f"written. Set {ENVIRONMENT}=1 to replace it.")
