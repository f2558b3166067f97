#!/usr/bin/env python3
"""SHA-256 of every command's output on every corpus file, against a manifest.

Speed work must not change a byte of what edsc writes. The manifest
(tests/identity/manifest.tsv) holds, for each file of each corpus and each
command below, the digest of its standard output (or the files it writes)
and its exit status, recorded from a build before the work began.

    output_digests.py generate EDSC MANIFEST CORPUS...   # write the manifest
    output_digests.py compare  EDSC MANIFEST CORPUS...   # exit 1 on any change

Commands run in the corpus folder on the bare file name, so the digests do
not depend on where the corpora are. --sample N takes every N-th file.
"""
import argparse
import concurrent.futures
import hashlib
import os
import subprocess
import sys
import tempfile

# name -> arguments before the file name; "{out}" is a fresh folder's page.
COMMANDS = {
    "check-text": ["check", "--color", "never", "-j", "1"],
    "check-json": ["check", "--format", "json", "-j", "1"],
    "dump-json": ["dump", "--json"],
    "header": ["header", "-o", "-"],
    "fmt": ["fmt"],
    "doc-html": ["doc", "-o", "-"],
    "doc-md": ["doc", "--format", "md", "-o", "{out}"],
}


def digest(edsc, corpus, name, command):
    with tempfile.TemporaryDirectory() as tmp:
        page = os.path.join(tmp, "page.md")
        args = [edsc] + [page if a == "{out}" else a for a in command] + [name]
        run = subprocess.run(args, cwd=corpus, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, env={**os.environ, "LC_ALL": "C"})
        h = hashlib.sha256()
        h.update(run.stdout)
        h.update(b"\0stderr\0" + run.stderr)
        # Files the command wrote (the Markdown page and its SVG maps).
        for root, _, files in sorted(os.walk(tmp)):
            for f in sorted(files):
                path = os.path.join(root, f)
                h.update(b"\0" + os.path.relpath(path, tmp).encode() + b"\0")
                with open(path, "rb") as data:
                    h.update(data.read())
        return h.hexdigest(), run.returncode


def records(edsc, corpora, sample, jobs):
    work = []
    for corpus in corpora:
        label = os.path.basename(os.path.normpath(corpus))
        files = sorted(f for f in os.listdir(corpus) if f.endswith(".eds"))
        for name in files[::sample]:
            for command in COMMANDS:
                work.append((label, corpus, name, command))
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        results = pool.map(lambda w: digest(edsc, w[1], w[2], COMMANDS[w[3]]), work)
        return {(w[0], w[2], w[3]): r for w, r in zip(work, results)}


def read_manifest(path):
    out = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            corpus, name, command, sha, status = line.rstrip("\n").split("\t")
            out[(corpus, name, command)] = (sha, int(status))
    return out


def main():
    p = argparse.ArgumentParser()
    p.add_argument("mode", choices=["generate", "compare"])
    p.add_argument("edsc")
    p.add_argument("manifest")
    p.add_argument("corpora", nargs="+")
    p.add_argument("--sample", type=int, default=1)
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    a = p.parse_args()
    got = records(os.path.abspath(a.edsc), [os.path.abspath(c) for c in a.corpora], a.sample, a.jobs)
    if a.mode == "generate":
        with open(a.manifest, "w", encoding="utf-8") as f:
            f.write("# corpus\tfile\tcommand\tsha256 of stdout, stderr and written files\texit status\n")
            f.write("# Regenerate only when an output is meant to change: tests/identity/output_digests.py\n")
            for key in sorted(got):
                sha, status = got[key]
                f.write(f"{key[0]}\t{key[1]}\t{key[2]}\t{sha}\t{status}\n")
        print(f"{len(got)} digests written to {a.manifest}")
        return 0
    want = read_manifest(a.manifest)
    bad = 0
    for key in sorted(got):
        if key not in want:
            print(f"not in the manifest: {' '.join(key)}")
            bad += 1
        elif want[key] != got[key]:
            print(f"changed: {' '.join(key)}: {want[key][0][:12]} exit {want[key][1]}"
                  f" -> {got[key][0][:12]} exit {got[key][1]}")
            bad += 1
    if a.sample == 1:
        for key in sorted(set(want) - set(got)):
            print(f"no longer produced: {' '.join(key)}")
            bad += 1
    print(f"{len(got)} outputs compared, {bad} differ")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
