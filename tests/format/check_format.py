#!/usr/bin/env python3
"""Fails when a C++ file of compiler/ or tests/ is not laid out as the
tree's .clang-format says, naming each file and the first lines that differ.

`clang-format -i FILE` fixes one; docs/contributing.md says so. The small
projects under tests/mutation/fixture are left as written: their line
numbers are what the mutation runner's own tests count on.
"""
import difflib
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
LEFT_OUT = ('tests/mutation/fixture/',)


def clang_format():
    for name in ('clang-format-14', 'clang-format'):
        found = shutil.which(name)
        if found:
            return found
    sys.exit('clang-format is not installed (scripts/packages-test.txt lists it)')


def sources():
    for top in ('compiler', 'tests'):
        for p in sorted((ROOT / top).rglob('*')):
            rel = p.relative_to(ROOT).as_posix()
            if p.suffix in ('.cpp', '.hpp') and p.is_file() and not rel.startswith(LEFT_OUT):
                yield p


def main():
    tool = clang_format()
    if not (ROOT / '.clang-format').is_file():
        sys.exit(f'{ROOT}/.clang-format is missing')
    files = list(sources())
    bad = []
    for p in files:
        text = p.read_text(encoding='utf-8')
        r = subprocess.run([tool, f'--assume-filename={p}', '--style=file'], input=text, capture_output=True,
                           text=True, cwd=ROOT, check=False)
        if r.returncode != 0:
            bad.append(f'{p.relative_to(ROOT)}: clang-format failed: {r.stderr.strip()}')
        elif r.stdout != text:
            diff = list(difflib.unified_diff(text.splitlines(), r.stdout.splitlines(), lineterm='', n=0))[2:8]
            bad.append(f'{p.relative_to(ROOT)}: not as .clang-format lays it out (clang-format -i fixes it)\n  ' +
                       '\n  '.join(diff))
    for b in bad:
        print(b)
    print(f'{len(files)} files checked against .clang-format: {len(bad)} to format')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
