#!/usr/bin/env python3
"""Runs `edsc diff --format=json` on the RightSight pair (both ways), on a file
against itself, and on each corpus file against the next one (many kinds of
difference), and validates every output against docs/diff-json.schema.json.
Under the sanitizers the corpus is a fixed sample (tests/corpus_sample.py).
Usage: validate_diff.py [--sample N] EDSC SCHEMA PROJECT_DIR CORPUS_DIR"""
import json
import pathlib
import subprocess
import sys

import jsonschema

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from corpus_sample import pop_sample_arg, sample  # noqa: E402


def main() -> int:
    argv = sys.argv[1:]
    stride = pop_sample_arg(argv)
    edsc, schema_path = argv[0], pathlib.Path(argv[1])
    project, corpus = pathlib.Path(argv[2]), pathlib.Path(argv[3])
    schema = json.loads(schema_path.read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    old, new = project / "eds/rightsight-42ef-diffuse.eds", project / "eds/rightsight-42ef-3byte.eds"
    pairs = [(old, new), (new, old), (old, old)]
    files = sample(corpus, stride)
    pairs += list(zip(files, files[1:]))
    failures = checked = kinds = 0
    seen = set()
    for a, b in pairs:
        run = subprocess.run([edsc, "diff", "--format=json", str(a), str(b)], capture_output=True)
        if run.returncode == 2:
            continue  # a file with syntax errors: refused, nothing to validate
        if run.returncode not in (0, 1):
            print(f"{a.name} {b.name}: edsc exited {run.returncode}: {run.stderr.decode(errors='replace')}")
            failures += 1
            continue
        doc = json.loads(run.stdout)
        errors = list(validator.iter_errors(doc))
        for e in errors[:3]:
            print(f"{a.name} {b.name}: {'/'.join(map(str, e.absolute_path))}: {e.message[:200]}")
        failures += 1 if errors else 0
        breaking = doc["summary"]["breaking"]
        if (run.returncode == 1) != (breaking > 0):
            print(f"{a.name} {b.name}: exit {run.returncode} with {breaking} breaking differences")
            failures += 1
        seen.update(d["kind"] for d in doc["differences"])
        checked += 1
    print(f"{checked - failures}/{checked} diffs valid; {len(seen)} kinds of difference seen")
    return 1 if failures or checked < 10 else 0


if __name__ == "__main__":
    sys.exit(main())
