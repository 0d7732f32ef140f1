#!/usr/bin/env python3
"""Checks that two experiment output folders hold the same results.

    python3 scripts/slurm/same_results.py SINGLE_RUN_DIR MERGED_DIR

results.json must be equal value for value (floats compared exactly, as
parsed from the JSON text), leaving out what depends on when, where and how
the run was started rather than on what it computed: every `*time_s` field,
`command` (the argv) and `git_hash`; a `file` field (the reference cache's
path, which lies beside the run's folder) is compared by its file name only. Every image (`*.exr`,
`*.png`) of the first folder must exist in the second with the same bytes. Prints each
difference (at most 20) and exits 1 if there is any.
"""

import json
import sys
from pathlib import Path

IGNORED_KEYS = {"command", "git_hash"}
MAX_SHOWN = 20


def ignored(key):
    return key in IGNORED_KEYS or key.endswith("time_s")


def differences(a, b, path="results.json"):
    """Yields a line for every place where the JSON values a and b differ."""
    if isinstance(a, dict) and isinstance(b, dict):
        for key in sorted(set(a) | set(b)):
            if ignored(key):
                continue
            if key not in a or key not in b:
                yield f"{path}.{key}: only in {'the first' if key in a else 'the second'}"
            elif key == "file" and isinstance(a[key], str) and isinstance(b[key], str):
                if Path(a[key]).name != Path(b[key]).name:
                    yield f"{path}.{key}: {a[key]!r} against {b[key]!r}"
            else:
                yield from differences(a[key], b[key], f"{path}.{key}")
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            yield f"{path}: {len(a)} items against {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            yield from differences(x, y, f"{path}[{i}]")
    elif type(a) is not type(b) or a != b:
        yield f"{path}: {a!r} against {b!r}"


def image_differences(first, second):
    images = sorted(p for p in first.iterdir() if p.suffix in (".exr", ".png"))
    if not images:
        yield f"{first}: no images"
    for image in images:
        other = second / image.name
        if not other.is_file():
            yield f"{image.name}: missing from {second}"
        elif image.read_bytes() != other.read_bytes():
            yield f"{image.name}: bytes differ"


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    first, second = Path(argv[1]), Path(argv[2])
    try:
        a = json.loads((first / "results.json").read_text())
        b = json.loads((second / "results.json").read_text())
    except (OSError, ValueError) as err:
        print(f"same_results: {err}", file=sys.stderr)
        return 1
    found = list(differences(a, b)) + list(image_differences(first, second))
    for line in found[:MAX_SHOWN]:
        print(f"same_results: {line}", file=sys.stderr)
    if found:
        print(f"same_results: {len(found)} difference(s) between {first} and {second}", file=sys.stderr)
        return 1
    print(f"same_results: {second} equals {first} (results.json times aside, every image)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
