#!/usr/bin/env python3
"""Runs Microsoft's SARIF validator (sarif-multitool validate) on edsc's SARIF
for each corpus folder, given as a relative and as an absolute path: no error,
no warning. Exits 77 (skipped) when the validator is not installed
(scripts/npm-tools installs it where npm is present).

Under the sanitizers each corpus folder is a fixed sample of its files
(tests/corpus_sample.py), copied to a folder of the same name.

usage: validate_sarif.py [--sample N] EDSC NPM_TOOLS_DIR CORPUS_DIR...
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from corpus_sample import pop_sample_arg, sample  # noqa: E402

SKIP = 77


def validator(tools_dir):
    package = os.path.join(tools_dir, "node_modules", "@microsoft", "sarif-multitool")
    if shutil.which("node") is None or not os.path.isdir(package):
        return None
    # The package names the platform's self-contained executable.
    path = subprocess.run(["node", "-p", f"require({json.dumps(package)})"], capture_output=True, text=True,
                          check=True).stdout.strip()
    return path if os.access(path, os.X_OK) else None


def validate(tool, sarif_files, work):
    out = os.path.join(work, "validation.sarif")
    if os.path.exists(out):
        os.remove(out)
    # No culture data needed; a machine without libicu still runs it.
    env = dict(os.environ, DOTNET_SYSTEM_GLOBALIZATION_INVARIANT="1")
    run = subprocess.run([tool, "validate", "--level", "Error;Warning", "-o", out] + sarif_files,
                         capture_output=True, text=True, env=env, cwd=work)
    if not os.path.exists(out):
        sys.exit(f"the validator wrote no log (status {run.returncode}):\n{run.stdout}\n{run.stderr}")
    with open(out, encoding="utf-8-sig") as f:
        log = json.load(f)
    findings = [r for run_ in log["runs"] for r in run_.get("results", [])
                if r.get("level", "warning") in ("error", "warning")]
    return findings


def describe(finding):
    loc = finding["locations"][0]["physicalLocation"]
    message = finding["message"]
    text = message.get("text") or f"{message.get('id')} {message.get('arguments')}"
    return f"{loc['artifactLocation']['uri']}:{loc.get('region', {}).get('startLine')}: " \
           f"{finding['level']} {finding['ruleId']}: {text}"


def main():
    argv = sys.argv[1:]
    stride = pop_sample_arg(argv)
    edsc, tools_dir, corpora = os.path.abspath(argv[0]), os.path.abspath(argv[1]), argv[2:]
    tool = validator(tools_dir)
    if tool is None:
        print(f"SKIPPED: Microsoft's SARIF validator is not installed in {tools_dir} "
              "(needs node and npm; run scripts/npm-tools)")
        return SKIP

    # The sample lives beside the work folder, so "up" still goes through '..'.
    with tempfile.TemporaryDirectory(prefix="edsc-sarif-") as work, \
            tempfile.TemporaryDirectory(prefix="edsc-sarif-sample-") as sample_root:
        # The validator really judges: an absolute path with a uriBaseId is an error.
        bad = os.path.join(work, "bad.sarif")
        with open(bad, "w") as f:
            json.dump({"$schema": "https://json.schemastore.org/sarif-2.1.0.json", "version": "2.1.0",
                       "runs": [{"tool": {"driver": {"name": "t", "version": "1",
                                                     "informationUri": "https://example.com/"}},
                                 "results": [{"ruleId": "r", "message": {"text": "m."},
                                              "locations": [{"physicalLocation": {"artifactLocation": {
                                                  "uri": "/abs/x.eds", "uriBaseId": "SRCROOT"}}}]}]}]}, f)
        if not validate(tool, [bad], work):
            sys.exit("the validator found nothing wrong in a SARIF file with a known error")

        files = []
        for corpus in corpora:
            corpus = os.path.abspath(corpus)
            name = os.path.basename(corpus)
            if stride > 1:
                copy = os.path.join(sample_root, name)
                os.makedirs(copy)
                for f in sample(corpus, stride):
                    shutil.copy(f, copy)
                corpus = copy
            # Relative: from the folder holding the corpus, and from a sibling
            # (a path through '..'); absolute: from anywhere.
            cases = [("rel", os.path.dirname(corpus), name),
                     ("up", work, os.path.relpath(corpus, work)),
                     ("abs", work, corpus)]
            for kind, cwd, arg in cases:
                run = subprocess.run([edsc, "check", "--format=sarif", arg], capture_output=True, text=True,
                                     cwd=cwd)
                if run.returncode not in (0, 1):
                    sys.exit(f"edsc check {arg} failed ({run.returncode}): {run.stderr}")
                log = json.loads(run.stdout)
                results = log["runs"][0]["results"]
                if not results:
                    sys.exit(f"no results for {arg}: nothing to validate")
                uri = results[0]["locations"][0]["physicalLocation"]["artifactLocation"]
                if kind == "abs" and (not uri["uri"].startswith("file:///") or "uriBaseId" in uri):
                    sys.exit(f"absolute input {arg} gave {uri}, not a file:// URI")
                if kind != "abs" and (uri["uri"].startswith("file:") or uri.get("uriBaseId") != "SRCROOT"):
                    sys.exit(f"relative input {arg} gave {uri}, not a reference relative to SRCROOT")
                path = os.path.join(work, f"{name}-{kind}.sarif")
                with open(path, "w") as f:
                    f.write(run.stdout)
                files.append(path)
                print(f"{name} ({kind}, {arg}): {len(results)} results")

        findings = validate(tool, files, work)
        for f in findings[:50]:
            print(describe(f))
        if findings:
            print(f"FAILED: {len(findings)} validator errors/warnings")
            return 1
        print(f"sarif-multitool validate: {len(files)} logs, no errors, no warnings")
        return 0


if __name__ == "__main__":
    sys.exit(main())
