#!/usr/bin/env python3
"""Runs `edsc dump --json` on every corpus file and validates the output
against docs/dump-json.schema.json; under the sanitizers on a fixed sample
(tests/corpus_sample.py). Usage: validate_dump.py [--sample N] EDSC SCHEMA CORPUS_DIR..."""
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
    corpora = [pathlib.Path(a) for a in argv[2:]]
    schema = json.loads(schema_path.read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    files = []
    for corpus in corpora:
        here = sample(corpus, stride)
        if not here:
            print(f"no .eds files in {corpus}")
            return 1
        files += here
    failures = 0
    for f in files:
        run = subprocess.run([edsc, "dump", "--json", str(f)], capture_output=True)
        if run.returncode != 0:
            print(f"{f.name}: edsc exited {run.returncode}: {run.stderr.decode(errors='replace')}")
            failures += 1
            continue
        doc = json.loads(run.stdout)
        errors = list(validator.iter_errors(doc))
        for e in errors[:3]:
            print(f"{f.name}: {'/'.join(map(str, e.absolute_path))}: {e.message[:200]}")
        failures += 1 if errors else 0
    print(f"{len(files) - failures}/{len(files)} dumps valid")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
