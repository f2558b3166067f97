#!/usr/bin/env python3
"""Runs `edsc dump --json` on every corpus file and validates the output
against docs/dump-json.schema.json; under the sanitizers on a fixed sample
(tests/corpus_sample.py). Python's jsonschema takes most of the time (about
0.25 s a dump), so the files are shared among the machine's cores.
Usage: validate_dump.py [--sample N] EDSC SCHEMA CORPUS_DIR..."""
import concurrent.futures
import json
import os
import pathlib
import subprocess
import sys

import jsonschema

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from corpus_sample import pop_sample_arg, sample  # noqa: E402

_validator = None


def _start(schema):
    global _validator
    _validator = jsonschema.Draft202012Validator(schema)


def check(edsc, f):
    """The problems of one file's dump (empty when it is valid)."""
    run = subprocess.run([edsc, "dump", "--json", str(f)], capture_output=True)
    if run.returncode != 0:
        return [f"{f.name}: edsc exited {run.returncode}: {run.stderr.decode(errors='replace')}"]
    doc = json.loads(run.stdout)
    return [f"{f.name}: {'/'.join(map(str, e.absolute_path))}: {e.message[:200]}"
            for e in list(_validator.iter_errors(doc))[:3]]


def main() -> int:
    argv = sys.argv[1:]
    stride = pop_sample_arg(argv)
    edsc, schema_path = argv[0], pathlib.Path(argv[1])
    corpora = [pathlib.Path(a) for a in argv[2:]]
    schema = json.loads(schema_path.read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    files = []
    for corpus in corpora:
        here = sample(corpus, stride)
        if not here:
            print(f"no .eds files in {corpus}")
            return 1
        files += here
    with concurrent.futures.ProcessPoolExecutor(max_workers=os.cpu_count() or 1, initializer=_start,
                                                initargs=(schema,)) as pool:
        results = list(pool.map(check, [edsc] * len(files), files))
    failures = 0
    for problems in results:
        for p in problems:
            print(p)
        failures += 1 if problems else 0
    print(f"{len(files) - failures}/{len(files)} dumps valid")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
