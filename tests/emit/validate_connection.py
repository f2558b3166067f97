#!/usr/bin/env python3
"""Runs `edsc connection --format json` on every corpus file (a fixed sample
under the sanitizers, tests/corpus_sample.py) and on the docs' configured
adapter with --set, and validates each output against
docs/connection-json.schema.json; then checks what the schema cannot say:
each direction's wire size is its data plus the headers it announces, and
the network parameters carry that size.
Usage: validate_connection.py [--sample N] EDSC SCHEMA PROJECT_DIR CORPUS_DIR..."""
import json
import pathlib
import subprocess
import sys

import jsonschema

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from corpus_sample import pop_sample_arg, sample  # noqa: E402


def sizes_agree(name, c):
    """The reasons the announced sizes contradict each other; empty when they agree."""
    out = []
    for key in ("o_to_t", "t_to_o"):
        d = c[key]
        if not d["used"]:
            continue
        wire = d["data_size"] + (2 if d["sequence_count"] else 0) + (4 if d["run_idle"] else 0)
        if wire != d["wire_size"]:
            out.append(f"{name} Connection{c['number']} {key}: wire_size {d['wire_size']} is not {wire}")
        if d["network_parameters_32"] & 0xFFFF != d["wire_size"]:
            out.append(f"{name} Connection{c['number']} {key}: 32-bit parameters do not carry the size")
        p16 = d["network_parameters_16"]
        if p16 is not None and p16 & 0x1FF != d["wire_size"]:
            out.append(f"{name} Connection{c['number']} {key}: 16-bit parameters do not carry the size")
    return out


def main() -> int:
    argv = sys.argv[1:]
    stride = pop_sample_arg(argv)
    edsc, schema_path, project = argv[0], pathlib.Path(argv[1]), pathlib.Path(argv[2])
    schema = json.loads(schema_path.read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    configured = project / "tests/docs/workspace/configured.eds"
    runs = [(configured, ["--set", "Filter Time=20", "--set", "Mode=Fast"])]
    for corpus in argv[3:]:
        runs += [(f, []) for f in sample(pathlib.Path(corpus), stride)]
    failures = checked = connections = 0
    for f, extra in runs:
        run = subprocess.run([edsc, "connection", str(f), "--format", "json", *extra], capture_output=True)
        if run.returncode == 1 and not run.stdout:
            continue  # no connection, or syntax errors: refused with a diagnostic, nothing to validate
        if run.returncode != 0:
            print(f"{f.name}: edsc exited {run.returncode}: {run.stderr.decode(errors='replace')[:300]}")
            failures += 1
            continue
        doc = json.loads(run.stdout)
        problems = [f"{f.name}: {'/'.join(map(str, e.absolute_path))}: {e.message[:200]}"
                    for e in validator.iter_errors(doc)]
        for c in doc["connections"]:
            problems += sizes_agree(f.name, c)
        for p in problems[:3]:
            print(p)
        failures += 1 if problems else 0
        checked += 1
        connections += len(doc["connections"])
    set_fields = json.loads(subprocess.run([edsc, "connection", str(configured), "--format", "json", *runs[0][1]],
                                           capture_output=True).stdout)["connections"][0]["configuration"]["fields"]
    if not all(x["set"] for x in set_fields):
        print("configured.eds: the --set fields are not marked set")
        failures += 1
    print(f"{checked - failures}/{checked} outputs valid, {connections} connections")
    return 1 if failures or checked < 10 else 0


if __name__ == "__main__":
    sys.exit(main())
