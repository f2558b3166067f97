"""Judging one mutant as CI would.

Its judges are the tests that execute its line (the coverage map), each run
alone under ctest. A judge must have passed alone on the unmutated build
(known good, kept per test under the tree's key). A mutant is killed when a
judge fails on it twice in a row (a failure, a hang, or a skip CI would not
allow); a judge that fails once and then passes is a flake, noted, not a kill.
"""
import concurrent.futures
import fnmatch
import json
import pathlib
import re
import time

from . import ctest
from . import project as proj


class KnownGood:
    """Each test's verdict alone on the unmutated build, under the tree's key."""

    def __init__(self, work, key):
        self.path = pathlib.Path(work) / f"known-good-{key}.json"
        self.verdicts = json.loads(self.path.read_text()) if self.path.exists() else {}

    def save(self):
        self.path.write_text(json.dumps(self.verdicts, indent=1, sort_keys=True) + '\n')

    def good(self, name):
        return self.verdicts.get(name, {}).get('status') == 'pass'

    def seconds(self, name):
        return self.verdicts.get(name, {}).get('seconds')

    def establish(self, build_dir, names, tests, lock, jobs=1, log=print):
        """Runs alone on the unmutated build each test not yet judged there,
        `jobs` at a time (those needing the lock take it in turn)."""
        todo = sorted(n for n in names if n not in self.verdicts)
        if todo:
            log(f"running {len(todo)} tests alone on the unmutated build (known good, kept for this tree)")

        def one(name):
            return name, ctest.run(build_dir, name, tests.get(name, {}).get('labels', ()), lock)

        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            for k, (name, o) in enumerate(pool.map(one, todo), 1):
                self.verdicts[name] = {'status': o.status, 'seconds': round(o.seconds, 2)}
                if o.status != 'pass':
                    log(f"  [{k}/{len(todo)}] {name}: {o.status} on the unmutated build: not a judge")
                self.save()

    def mark_flaky(self, name):
        self.verdicts[name] = dict(self.verdicts.get(name, {}), status='flaky')
        self.save()


def load_skips(root):
    """tests/skips.txt: the tests CI allows to skip (name or pattern, reason)."""
    path = pathlib.Path(root) / 'tests' / 'skips.txt'
    out = []
    if path.exists():
        for line in path.read_text().splitlines():
            line = line.strip()
            if line and not line.startswith('#'):
                out.append(line.split()[0])
    return out


def candidates(project, cmap, mutant, policy):
    """(scope, set of test names) that can tell the mutant apart."""
    rel, line = mutant.path, mutant.line
    if mutant.kind == 'generated':
        if project.is_template(rel):
            rel, anchor = project.templates['rendered_at']
            text = (project.root / rel).read_text()
            line = text.count('\n', 0, max(text.find(anchor), 0)) + 1
        span = cmap.function_at(rel, line)
        found = cmap.of_range(rel, *span) if span else set()
        names = cmap.names(found)
        if policy == 'build-run':
            names = {n for n in names if builds_generated(project, cmap, n)}
        return 'emitting function', names
    covered = cmap.of_line(rel, line)
    if covered is not None:
        return 'line', cmap.names(covered)
    span = cmap.function_at(rel, line)
    if span:
        return 'function', cmap.names(cmap.of_range(rel, *span))
    found = cmap.of_file(rel)
    if rel.endswith('.hpp'):
        for other in project.includers(rel):
            found |= cmap.of_file(other)
    return 'file', cmap.names(found)


def builds_generated(project, cmap, name):
    judges = project.generated_judges
    labels = next((t['labels'] for t in cmap.tests if t['name'] == name), [])
    return bool(set(labels) & set(judges.get('labels', []))) or any(
        re.search(p, name) for p in judges.get('tests', []))


class Judge:
    def __init__(self, project, tree, build_dir, tests, known, jobs, log=print):
        self.project, self.tree, self.build_dir = project, pathlib.Path(tree), build_dir
        self.tests, self.known, self.jobs, self.log = tests, known, jobs, log
        self.skips = load_skips(tree)

    def order(self, names):
        """Cheapest first, by the time each took alone on the unmutated build."""
        return sorted(names, key=lambda n: (self.known.seconds(n) or 1e9, n))

    def failed(self, outcome, name):
        if outcome.status in ('fail', 'timeout', 'missing'):
            return True
        # A skip not listed in tests/skips.txt fails CI.
        return outcome.status == 'skip' and not any(fnmatch.fnmatch(name, p) for p in self.skips)

    def targets_for(self, name):
        exe = self.tests.get(name, {}).get('command', [None])[0]
        targets = list(self.project.support_targets)
        if exe and str(exe).startswith(str(self.build_dir)):
            targets.append(pathlib.Path(exe).name)
        return targets

    def judge(self, mutant, judges, scope):
        """The verdict on one mutant (a dict for the results)."""
        t0 = time.time()
        path = self.tree / mutant.path
        original = path.read_text()
        path.write_text(mutant.apply(original))
        ran, flaky, built = [], [], set()
        try:
            ok, log = proj.build(self.build_dir, [self.project.library_target] if self.project.library_target else [],
                                 self.jobs, 1800)
            status, by = ('uncompilable', '') if not ok else (None, '')
            why = log.strip().splitlines()[-1] if not ok and log.strip() else ''
            for name in (self.order(judges) if ok else []):
                targets = [t for t in self.targets_for(name) if t not in built]
                if targets:
                    ok, log = proj.build(self.build_dir, targets, self.jobs, 1800)
                    if not ok:
                        status, why = 'uncompilable', log.strip().splitlines()[-1] if log.strip() else ''
                        break
                    built.update(targets)
                watchdog = max(60.0, 5 * (self.known.seconds(name) or 60))
                first = ctest.run(self.build_dir, name, self.tests[name]['labels'], self.project.lock,
                                  watchdog=watchdog)
                ran.append(name)
                if not self.failed(first, name):
                    continue
                again = ctest.run(self.build_dir, name, self.tests[name]['labels'], self.project.lock,
                                  watchdog=watchdog)
                if self.failed(again, name):
                    status, by, why = 'killed', name, f"{first.status}: {first.detail.strip()[-300:]}"
                    break
                flaky.append(name)
            if status is None:
                status = 'survived' if judges else 'not-covered'
        finally:
            path.write_text(original)
        return {'status': status, 'killed_by': by, 'why': why, 'scope': scope, 'judges': len(judges),
                'ran': len(ran), 'flaky': flaky, 'seconds': round(time.time() - t0, 1)}
