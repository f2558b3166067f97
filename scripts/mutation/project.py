"""The project a mutation run works on: its root, tests/mutation/config.json,
its modules and their mutants, and the copy of its tree the runs build."""
import fnmatch
import hashlib
import json
import os
import pathlib
import re
import shutil
import subprocess

from . import scan

SOURCE_SUFFIXES = ('.cpp', '.hpp')


class Project:
    def __init__(self, root):
        self.root = pathlib.Path(root).resolve()
        self.config = json.loads((self.root / 'tests' / 'mutation' / 'config.json').read_text())
        c = self.config
        self.modules = c['modules']
        self.generated_literal_files = set(c.get('generated_literals', []))
        self.templates = c.get('templates')  # {"dir", "suffix", "rendered_at": [file, text]}
        self.generated_judges = c.get('generated_judges', {'labels': [], 'tests': []})
        self.lock = c.get('lock', {'labels': [], 'file': None})
        self.support_targets = c.get('support_targets', [])
        self.library_target = c.get('library_target')
        self.key_ignore = c.get('key_ignore', [])

    def cmake_args(self, kind):
        shared = str((self.root / '..' / 'shared').resolve())
        return [a.replace('{shared}', shared).replace('{root}', str(self.root))
                for a in self.config.get('cmake_args', {}).get(kind, [])]

    # ---- modules and their mutants

    def is_template(self, rel):
        t = self.templates
        return bool(t) and rel.startswith(t['dir'].rstrip('/') + '/') and rel.endswith(t['suffix'])

    def module_files(self, module):
        module = module.rstrip('/')
        base = self.root / module
        if base.is_dir():
            files = [p for p in base.rglob('*') if p.is_file()]
        else:
            files = [p for p in self.root.glob(module + '*') if p.is_file()]
        out = []
        for p in files:
            rel = p.relative_to(self.root).as_posix()
            if p.suffix in SOURCE_SUFFIXES or self.is_template(rel):
                out.append(rel)
        return sorted(out)

    def mutants_of_file(self, rel, text=None):
        text = (self.root / rel).read_text() if text is None else text
        return scan.mutants_of(rel, text, generated_literals=rel in self.generated_literal_files,
                               template=self.is_template(rel))

    def module_mutants(self, module, ops=None):
        out = []
        for rel in self.module_files(module):
            out += [m for m in self.mutants_of_file(rel) if ops is None or m.op in ops]
        return out

    # ---- the files of the tree, and the key of their contents

    def files(self):
        """What git tracks or would track (untracked, not ignored: a new test
        not yet committed)."""
        r = subprocess.run(['git', 'ls-files', '-z', '--cached', '--others', '--exclude-standard'], cwd=self.root,
                           capture_output=True, text=True, check=True)
        return sorted(f for f in r.stdout.split('\0') if f and (self.root / f).is_file())

    def key(self):
        """A hash of the builds' options and every file the build and the
        tests read (not the runner, its results, nor prose): a coverage map or
        a test's verdict on the unmutated tree holds for as long as this does
        not change."""
        h = hashlib.sha1(json.dumps(self.config.get('cmake_args'), sort_keys=True).encode())
        for rel in self.files():
            if any(fnmatch.fnmatch(rel, pattern) for pattern in self.key_ignore):
                continue
            h.update(rel.encode() + b'\0' + hashlib.sha1((self.root / rel).read_bytes()).digest())
        return h.hexdigest()[:16]

    def commit(self):
        r = subprocess.run(['git', 'rev-parse', 'HEAD'], cwd=self.root, capture_output=True, text=True)
        return r.stdout.strip() if r.returncode == 0 else ''

    def sync(self, tree):
        """Copies the project's files into `tree`, only those that differ, so
        its builds stay incremental; files gone from the project go from it."""
        tree = pathlib.Path(tree)
        wanted = set(self.files())
        for rel in wanted:
            src, dst = self.root / rel, tree / rel
            data = src.read_bytes()
            if dst.is_file() and dst.read_bytes() == data:
                continue
            dst.parent.mkdir(parents=True, exist_ok=True)
            dst.write_bytes(data)
            shutil.copymode(src, dst)
        listed = tree / '.mutate-files'
        if listed.exists():
            for rel in set(listed.read_text().splitlines()) - wanted:
                (tree / rel).unlink(missing_ok=True)
        listed.write_text('\n'.join(sorted(wanted)) + '\n')

    def includers(self, rel):
        """The files that include header `rel` directly (by any suffix of its
        path, as the include paths allow)."""
        parts = rel.split('/')
        names = {'/'.join(parts[i:]) for i in range(len(parts))}
        pattern = re.compile(r'#include\s+"([^"]+)"')
        out = []
        for other in self.files():
            if not other.endswith(SOURCE_SUFFIXES) or other == rel:
                continue
            text = (self.root / other).read_text(errors='replace')
            if any(m.group(1) in names for m in pattern.finditer(text)):
                out.append(other)
        return out


def build_env():
    env = dict(os.environ)
    # The same ccache objects as the normal build where the sources agree.
    env.setdefault('CCACHE_BASEDIR', '/')
    env.setdefault('CCACHE_NOHASHDIR', 'true')
    if shutil.which('ccache'):
        env.setdefault('CMAKE_CXX_COMPILER_LAUNCHER', 'ccache')
    return env


def configure(source, build_dir, args):
    """Configures (again: the options may have changed) a build of `source`."""
    r = subprocess.run(['cmake', '-S', str(source), '-B', str(build_dir), '-G', 'Ninja', *args],
                       capture_output=True, text=True, env=build_env())
    if r.returncode != 0:
        raise SystemExit(f"configure of {build_dir} failed:\n{r.stdout}\n{r.stderr}")


def build(build_dir, targets, jobs, timeout=3600):
    """(ok, log tail). No targets: everything."""
    cmd = ['cmake', '--build', str(build_dir), '-j', str(jobs)]
    if targets:
        cmd += ['--target', *targets]
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=build_env())
    except subprocess.TimeoutExpired:
        return False, 'build timed out'
    return r.returncode == 0, (r.stdout + r.stderr)[-3000:]
