"""The CI smoke: each mutant of tests/mutation/smoke.txt, applied in place in
an existing build, must be killed by the test named beside it, judged as a
full run judges (the test alone under ctest, passing on the unmutated build,
failing twice on the mutant)."""
import pathlib
import sys
import time

from . import ctest
from . import project as proj
from .judge import Judge, KnownGood


def read_list(root):
    listed = []
    for line in (pathlib.Path(root) / 'tests' / 'mutation' / 'smoke.txt').read_text().splitlines():
        line = line.strip()
        if line and not line.startswith('#'):
            module, mid, test = line.split()[:3]
            listed.append((module, mid, test))
    return listed


def restore_leftovers(root, backup):
    """Puts back the files a killed smoke run left mutated."""
    if not backup.is_dir():
        return
    for saved in backup.rglob('*'):
        if saved.is_file():
            rel = saved.relative_to(backup)
            (root / rel).write_bytes(saved.read_bytes())
            print(f"restored {rel} from an interrupted smoke run", flush=True)
            saved.unlink()


class _NoCache(KnownGood):
    def __init__(self):
        self.verdicts = {}

    def save(self):
        pass


def run(project, build_dir, work, jobs):
    build_dir = pathlib.Path(build_dir).resolve()
    if not (build_dir / 'build.ninja').exists():
        sys.exit(f"{build_dir} is not a configured build (run scripts/build first)")
    backup = pathlib.Path(work) / 'smoke-restore'
    restore_leftovers(project.root, backup)
    started = time.time()
    tests = ctest.list_tests(build_dir)
    known = _NoCache()
    # In place: the build's sources are the project's own files.
    judge = Judge(project, project.root, build_dir, tests, known, jobs, log=lambda *_: None)
    listed, failures, touched = read_list(project.root), [], set()
    mutants = {}
    for module, _, _ in listed:
        if module not in mutants:
            mutants[module] = {m.id: m for m in project.module_mutants(module)}
    for module, mid, test in listed:
        m = mutants[module].get(mid)
        if m is None or test not in tests:
            failures.append(f"{module} {mid}: " + ("no such mutant any more (the source changed: update smoke.txt)"
                                                    if m is None else f"no test {test}"))
            continue
        touched.update(judge.targets_for(test))
        ok, log = proj.build(build_dir, judge.targets_for(test), jobs)
        if not ok:
            sys.exit(f"the unmutated build fails:\n{log}")
        known.establish(build_dir, [test], tests, project.lock, log=lambda *_: None)
        if not known.good(test):
            failures.append(f"{mid}: {test} does not pass on the unmutated build")
            continue
        saved = backup / m.path
        saved.parent.mkdir(parents=True, exist_ok=True)
        saved.write_bytes((project.root / m.path).read_bytes())
        try:
            verdict = judge.judge(m, {test}, 'named')
        finally:
            saved.unlink()
        status = verdict['status']
        print(f"{status:12} {m.id} {m.describe()} ({verdict['seconds']:.0f} s) {verdict['killed_by']}"[:200],
              flush=True)
        if status != 'killed':
            failures.append(f"{m.id} {m.describe()}: {status}" + (f" (flaky: {verdict['flaky']})"
                                                                   if verdict['flaky'] else ''))
    # What the mutants rebuilt is built again from the restored sources.
    ok, log = proj.build(build_dir, sorted(touched | {project.library_target} - {None}), jobs)
    if not ok:
        failures.append(f"the unmutated build fails after the smoke:\n{log}")
    print(f"smoke: {len(listed)} mutants in {time.time() - started:.0f} s, {len(failures)} not killed")
    for f in failures:
        print('  ' + f)
    return 1 if failures else 0
