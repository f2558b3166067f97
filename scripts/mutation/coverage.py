"""Which tests execute each line: a coverage build (gcc --coverage, its own
build folder), every ctest test run alone in it with its own counters
(GCOV_PREFIX: the test and every process it starts, `edsc` included, write
their counts under a folder of that test), read back with gcov.

The map is kept on disk under the key of the tree's contents and built again
when that changes."""
import concurrent.futures
import gzip
import hashlib
import json
import pathlib
import shutil
import subprocess
import threading
import time

from . import ctest
from . import project as proj


class CoverageMap:
    def __init__(self, data):
        self.data = data
        self.tests = data['tests']
        self.lines = {f: {int(k): set(v) for k, v in lines.items()} for f, lines in data['lines'].items()}
        self.executable = {f: set(v) for f, v in data['executable'].items()}
        self.functions = {f: [tuple(r) for r in v] for f, v in data['functions'].items()}

    def names(self, indices):
        return {self.tests[i]['name'] for i in indices}

    def of_line(self, rel, line):
        """Tests that execute the line, or None when the line holds no code."""
        if line not in self.executable.get(rel, ()):
            return None
        return self.lines.get(rel, {}).get(line, set())

    def function_at(self, rel, line):
        inside = [r for r in self.functions.get(rel, ()) if r[0] <= line <= r[1]]
        return min(inside, key=lambda r: r[1] - r[0]) if inside else None

    def of_range(self, rel, first, last):
        out = set()
        for line, tests in self.lines.get(rel, {}).items():
            if first <= line <= last:
                out |= tests
        return out

    def of_file(self, rel):
        out = set()
        for tests in self.lines.get(rel, {}).values():
            out |= tests
        return out

    def known(self, rel):
        return rel in self.executable


def map_path(work, key):
    return pathlib.Path(work) / f"coverage-{key}.json.gz"


def load(work, key):
    path = map_path(work, key)
    if not path.exists():
        return None
    with gzip.open(path, 'rt') as f:
        return CoverageMap(json.load(f))


def build_map(project, tree, work, key, jobs, log=print):
    """Builds the coverage build of `tree`, runs each test alone in it and
    writes the map. Returns it."""
    work = pathlib.Path(work)
    build_dir = work / 'coverage-build'
    runs = work / 'coverage-runs'
    shutil.rmtree(runs, ignore_errors=True)
    t0 = time.time()
    proj.configure(tree, build_dir, project.cmake_args('coverage'))
    ok, text = proj.build(build_dir, [], jobs, timeout=4 * 3600)
    if not ok:
        raise SystemExit(f"the coverage build fails:\n{text}")
    built = time.time() - t0
    log(f"coverage build: {built:.0f} s")
    tests = ctest.list_tests(build_dir)
    names = sorted(tests)
    data = {'lines': {}, 'executable': {}, 'functions': {}}
    merged = threading.Lock()
    records = [None] * len(names)
    reader = Reader(pathlib.Path(tree).resolve())

    def one(i):
        name = names[i]
        prefix = runs / str(i)
        prefix.mkdir(parents=True)
        outcome = ctest.run(build_dir, name, tests[name]['labels'], project.lock,
                            env={'GCOV_PREFIX': str(prefix), 'GCOV_PREFIX_STRIP': '0'})
        t1 = time.time()
        found = reader.read(prefix)
        shutil.rmtree(prefix, ignore_errors=True)
        with merged:
            for rel, (covered, executable, functions) in found.items():
                lines = data['lines'].setdefault(rel, {})
                for line in covered:
                    lines.setdefault(str(line), []).append(i)
                data['executable'].setdefault(rel, set()).update(executable)
                data['functions'].setdefault(rel, set()).update(functions)
        exe = pathlib.Path(tests[name]['command'][0]) if tests[name]['command'] else None
        records[i] = {'name': name, 'labels': tests[name]['labels'], 'status': outcome.status,
                      'seconds': round(outcome.seconds, 2), 'gcov_seconds': round(time.time() - t1, 2),
                      'target': exe.name if exe and str(exe).startswith(str(build_dir)) else None}
        return i

    t0 = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for done, i in enumerate(pool.map(one, range(len(names))), 1):
            r = records[i]
            if done % 25 == 0 or r['status'] != 'pass':
                log(f"  coverage {done}/{len(names)} {r['name']}: {r['status']} ({r['seconds']} s, "
                    f"gcov {r['gcov_seconds']} s)")
    data['executable'] = {f: sorted(v) for f, v in data['executable'].items()}
    data['functions'] = {f: sorted(v) for f, v in data['functions'].items()}
    data.update({'key': key, 'tests': records, 'build_seconds': round(built),
                 'run_seconds': round(time.time() - t0), 'built_at': time.strftime('%Y-%m-%d %H:%M:%S')})
    log(f"coverage runs: {len(names)} tests in {data['run_seconds']} s, {reader.gcov_runs} gcov runs")
    with gzip.open(map_path(work, key), 'wt') as f:
        json.dump(data, f)
    return CoverageMap(json.loads(json.dumps(data)))


class Reader:
    """Reads the .gcda files a test left under its prefix folder. gcov's
    answer for an object depends only on its notes and its arc counters, and
    most objects of a test executable ran only their start-up (the same
    counters in every test of that executable), so each distinct set of
    counters of an object goes through gcov once."""

    def __init__(self, tree):
        self.tree = tree
        self.known = {}  # (object, counters digest) -> {source: (lines run, lines with code, function ranges)}
        self.lock = threading.Lock()
        self.gcov_runs = 0

    def read(self, prefix, batch=40):
        """{source relative to the tree: (lines run, lines with code, function
        ranges)} from the .gcda files under `prefix`."""
        found, todo = {}, []
        for gcda in prefix.rglob('*.gcda'):
            original = pathlib.Path('/') / gcda.relative_to(prefix)
            gcno = original.with_suffix('.gcno')
            if not gcno.exists():
                continue
            key = (str(original), counters_digest(gcda))
            with self.lock:
                cached = self.known.get(key)
            if cached is not None:
                merge(found, cached)
                continue
            link = gcda.with_suffix('.gcno')
            if not link.exists():
                link.symlink_to(gcno)
            todo.append((key, gcda))
        for k in range(0, len(todo), batch):
            part = dict(todo[k:k + batch])
            by_gcda = self.gcov([g for g in part.values()], prefix)
            with self.lock:
                self.gcov_runs += 1
                for key, gcda in part.items():
                    self.known[key] = by_gcda.get(str(gcda), {})
            for gcda in part.values():
                merge(found, by_gcda.get(str(gcda), {}))
        return found

    def gcov(self, gcdas, prefix):
        # Only the tree's own sources (-s makes them relative, -r leaves out
        # the rest): the system's and libraries' headers are most of the
        # output and none of the mutants.
        r = subprocess.run(['gcov', '--json-format', '--stdout', '--relative-only', '--source-prefix', str(self.tree),
                            *map(str, gcdas)], cwd=prefix, capture_output=True, text=True)
        out = {}
        for line in r.stdout.splitlines():
            if not line.startswith('{'):
                continue
            doc = json.loads(line)
            cwd = pathlib.Path(doc.get('current_working_directory', '/'))
            one = out.setdefault(doc.get('data_file', ''), {})
            for f in doc.get('files', []):
                rel = self.relative(cwd, f['file'])
                if rel is None:
                    continue
                covered, executable, functions = one.setdefault(rel, (set(), set(), set()))
                for ln in f.get('lines', []):
                    executable.add(ln['line_number'])
                    if ln['count'] > 0:
                        covered.add(ln['line_number'])
                for fn in f.get('functions', []):
                    functions.add((fn['start_line'], fn['end_line']))
        return out


    def relative(self, cwd, name):
        """The tree-relative path of a source gcov names: relative to the
        compiler's folder (paths made relative by ccache) or, prefix elided,
        to the tree."""
        for path in (cwd / name, self.tree / name.lstrip('/')):
            try:
                return path.resolve().relative_to(self.tree).as_posix()
            except ValueError:
                continue
        return None


def merge(found, more):
    for rel, (covered, executable, functions) in more.items():
        a, b, c = found.setdefault(rel, (set(), set(), set()))
        a |= covered
        b |= executable
        c |= functions


GCDA_MAGIC = 0x67636461
OBJECT_SUMMARY = 0xa1000000  # runs and the largest count: not what a line's count depends on


def counters_digest(gcda):
    """A digest of the arc counters of a .gcda file (not its run count):
    what gcov's line counts depend on besides the notes."""
    data = gcda.read_bytes()
    if len(data) < 16 or int.from_bytes(data[0:4], 'little') != GCDA_MAGIC:
        return hashlib.sha1(data).hexdigest()
    h = hashlib.sha1(data[4:16])  # version, stamp, checksum
    pos = 16
    while pos + 8 <= len(data):
        tag = int.from_bytes(data[pos:pos + 4], 'little')
        length = int.from_bytes(data[pos + 4:pos + 8], 'little')
        if tag != OBJECT_SUMMARY:
            h.update(data[pos:pos + 8 + length])
        pos += 8 + length
    return h.hexdigest()
