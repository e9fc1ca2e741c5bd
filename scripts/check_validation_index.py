#!/usr/bin/env python3
"""Check that doc/validation.md and doc/validation_data/ trace to the tests.

    check_validation_index.py SOURCE_DIR BUILD_DIR [CTEST]

The registered tests are read from `CTEST --show-only=json-v1` run in
BUILD_DIR. Fails (exit code 1, one line per problem) if
- a CSV in doc/validation_data/ (outside archive/) is written by no
  registered test: its name (or, for a CSV.levelN.csv neck history, CSV) is
  no test's `--csv` argument;
- a PNG there is not shown or named in doc/validation.md;
- doc/validation.md names a data file (x.csv, x.png, with {a,b} lists,
  {k} or * wildcards and levelN) that matches no file in doc/validation_data/
  (archive/x for the archive; a name with another folder, such as
  parameter_files/x.csv, from the repository's root), or a script
  scripts/x.py that does not exist;
- a "CSV:", "Plot:" or "Source:" line of doc/validation.md names in
  backticks a test (a name without a file extension, * and {a,b} allowed)
  that is not registered;
- a row of the opening table ("## At a glance") names in its last column
  a test that is not registered, or in its first column, in parentheses
  at the end, a section that no heading (or bold paragraph) of the
  document begins with.
"""
import fnmatch
import json
import pathlib
import re
import subprocess
import sys

DATA_FILE = re.compile(r"(?<![\w./-])[A-Za-z0-9_*{][A-Za-z0-9_.{},*+/-]*"
                       r"\.(?:csv|png)\b")
SCRIPT = re.compile(r"scripts/[A-Za-z0-9_]+\.py")
LEVEL_SERIES = re.compile(r"\.level\d+\.csv$")
# Names in the text that are not files of doc/validation_data/: the
# application's output and the placeholders of command lines.
NOT_DATA = {"metrics.csv", "timing.csv", "OUT.png", "FILE.csv", "FILE.levelN.csv",
            "A.csv", "B.csv"}


def registered_tests(build_dir, ctest):
    """Test name -> command list, from ctest's JSON listing."""
    listing = subprocess.run([ctest, "--show-only=json-v1"], cwd=build_dir,
                             check=True, capture_output=True, text=True)
    tests = {}
    for test in json.loads(listing.stdout)["tests"]:
        tests[test["name"]] = test.get("command")
    return tests


def csv_outputs(tests, errors):
    """File names (without directory) that the tests write with --csv."""
    names = set()
    for name, command in tests.items():
        if command is None:
            errors.append(f"test {name} has no command in ctest's listing "
                          "(its executable is not built)")
            continue
        for i, arg in enumerate(command[:-1]):
            if arg == "--csv":
                names.add(pathlib.PurePath(command[i + 1]).name)
    return names


def expand(pattern):
    """{a,b} lists expanded; {k} placeholders and levelN as wildcards."""
    match = re.search(r"\{([^{}]*)\}", pattern)
    if match is None:
        return [re.sub(r"level[NK]\b", "level*", pattern)]
    head, tail = pattern[:match.start()], pattern[match.end():]
    items = match.group(1).split(",") if "," in match.group(1) else ["*"]
    return [p for item in items for p in expand(head + item + tail)]


def test_names(text):
    """Backticked test names in text (* and {a,b} allowed)."""
    return [name for name in re.findall(r"`([^`]+)`", text)
            if re.fullmatch(r"\w[\w*{},.-]*", name)
            and not re.search(r"\.(csv|png|py)$", name)]


def check_glance_table(doc, tests, errors):
    """The opening table: its tests registered, its sections present."""
    start = next((i for i, line in enumerate(doc)
                  if line.startswith("## At a glance")), None)
    if start is None:
        errors.append("doc/validation.md: no opening table "
                      "('## At a glance')")
        return
    titles = [re.sub(r"^(#+ |\*\*)", "", line) for line in doc
              if line.startswith("#") or line.startswith("**")]
    rows = 0
    for number, line in enumerate(doc[start + 1:], start + 2):
        if line.startswith("#"):
            break
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if not line.startswith("| ") or len(cells) < 4 or \
                cells[0] == "check":
            continue
        rows += 1
        section = re.search(r"\(([^()]*)\)$", cells[0])
        if section is None or not any(title.startswith(section.group(1))
                                      for title in titles):
            errors.append(f"doc/validation.md:{number}: the check names no "
                          "section of the document in parentheses")
        names = test_names(cells[-1])
        if not names:
            errors.append(f"doc/validation.md:{number}: the check names no "
                          "test")
        for name in names:
            if not any(fnmatch.filter(tests, p) for p in expand(name)):
                errors.append(f"doc/validation.md:{number}: names test "
                              f"{name}, which is not registered")
    if rows == 0:
        errors.append("doc/validation.md: the opening table has no rows")


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    build_dir = sys.argv[2]
    ctest = sys.argv[3] if len(sys.argv) > 3 else "ctest"
    data = root / "doc" / "validation_data"
    doc_path = root / "doc" / "validation.md"
    doc = doc_path.read_text().splitlines()
    errors = []

    tests = registered_tests(build_dir, ctest)
    written = csv_outputs(tests, errors)
    text = "\n".join(doc)
    for path in sorted(p for p in data.iterdir() if p.is_file()):
        name = path.name
        if name.endswith(".csv"):
            if LEVEL_SERIES.sub("", name) not in written and name not in written:
                errors.append(f"doc/validation_data/{name}: no registered test "
                              "writes it (move it to archive/ with a line in "
                              "archive/README.md, or register its study)")
        elif name.endswith(".png"):
            if name not in text:
                errors.append(f"doc/validation_data/{name}: not shown or named "
                              "in doc/validation.md")
        else:
            errors.append(f"doc/validation_data/{name}: neither CSV nor PNG")

    stored = [p.relative_to(data).as_posix()
              for p in data.rglob("*") if p.is_file()]
    for number, line in enumerate(doc, 1):
        for token in DATA_FILE.findall(line):
            name = re.sub(r"^(doc/)?(validation_data/)?", "", token)
            if name in NOT_DATA:
                continue
            if "/" in name and not name.startswith("archive/"):
                # A file elsewhere in the repository, e.g. parameter_files/.
                if not (root / name).is_file():
                    errors.append(f"doc/validation.md:{number}: names "
                                  f"{token}, which does not exist")
                continue
            for pattern in expand(name):
                if not fnmatch.filter(stored, pattern):
                    errors.append(f"doc/validation.md:{number}: names "
                                  f"{token}, no file doc/validation_data/"
                                  f"{pattern}")
        for script in SCRIPT.findall(line):
            if not (root / script).is_file():
                errors.append(f"doc/validation.md:{number}: names {script}, "
                              "which does not exist")
        if line.lstrip().startswith(("CSV:", "Plot:", "Source:")):
            for name in test_names(line):
                if not any(fnmatch.filter(tests, p) for p in expand(name)):
                    errors.append(f"doc/validation.md:{number}: names test "
                                  f"{name}, which is not registered")

    check_glance_table(doc, tests, errors)

    for error in errors:
        print(error)
    if errors:
        return 1
    print(f"{len(stored)} files in doc/validation_data/, "
          f"{len(written)} CSV names written by {len(tests)} tests: "
          "all traced")
    return 0


if __name__ == "__main__":
    sys.exit(main())
