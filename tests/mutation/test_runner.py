#!/usr/bin/env python3
"""scripts/mutate judges as CI does, on the tiny project of fixture/:

- a mutant seen only through state an earlier case left in the same process
  (lib/counter.cpp reset()) is not killed: each test runs alone;
- a test that fails once and passes when run again (fake.flaky) kills nothing;
- a mutant of a header (lib/counter.hpp) is made and judged;
- a mutant of the C a raw string generates (lib/emit.cpp) is made and killed
  by the test that compiles and runs that C, not by a text comparison;
- a mutant no test executes is "not covered";
- the smoke fails for a listed mutant its test does not kill alone.

It also checks that edsc's own headers, emitter literals and templates give
mutants. Usage: test_runner.py PROJECT_ROOT
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(sys.argv.pop(1) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
MUTATE = ROOT / 'scripts' / 'mutate'
FIXTURE = ROOT / 'tests' / 'mutation' / 'fixture'


def mutate(*args, env=None, root=None):
    cmd = [sys.executable, str(MUTATE), *args] + (['--root', str(root)] if root else [])
    return subprocess.run(cmd, capture_output=True, text=True, env=dict(os.environ, **(env or {})))


def listing(module, root=None):
    """{where: id} of the module's mutants."""
    r = mutate(module, '--list', root=root)
    if r.returncode != 0:
        raise AssertionError(r.stdout + r.stderr)
    return {line.split(' ', 1)[1]: line.split(' ', 1)[0] for line in r.stdout.splitlines()[:-1]}


def find(mutants, where):
    ids = [mid for w, mid in mutants.items() if w.startswith(where)]
    if len(ids) != 1:
        raise AssertionError(f"one mutant at {where}: {ids}")
    return ids[0]


class EdscMutants(unittest.TestCase):
    def test_a_header_has_mutants(self):
        self.assertTrue(any(w.startswith('compiler/cip/bytes.hpp:') for w in listing('compiler/cip')))

    def test_the_c_and_cmake_of_the_opener_emitters_literals_have_mutants(self):
        opener = listing('compiler/emit/opener_')
        self.assertTrue(any(w.startswith('compiler/emit/opener_render.cpp:') and ' gen-' in w for w in opener))

    def test_the_header_templates_have_mutants(self):
        self.assertTrue(any(w.startswith('templates/header_cip.mustache:') for w in listing('templates')))


    def test_every_mutant_of_the_ci_smoke_still_exists(self):
        # An edit that moves a listed line changes its mutant's id; said here,
        # in the suite, rather than at CI's last step.
        listed = [line.split()[:2] for line in (ROOT / 'tests' / 'mutation' / 'smoke.txt').read_text().splitlines()
                  if line.strip() and not line.lstrip().startswith('#')]
        self.assertTrue(listed)
        ids = {}
        for module, mid in listed:
            if module not in ids:
                ids[module] = set(listing(module).values())
            self.assertTrue(mid in ids[module], f"{module} {mid} of tests/mutation/smoke.txt: no such mutant any more "
                                            f"(list the new id with scripts/mutate {module} --list)")

    def test_all_judges_every_module_of_the_config_in_turn(self):
        r = mutate('--all', '--list')
        self.assertEqual(r.returncode, 0, r.stderr)
        listed = [line[3:] for line in r.stdout.splitlines() if line.startswith('== ')]
        config = json.loads((ROOT / 'tests' / 'mutation' / 'config.json').read_text())
        self.assertEqual(listed, config['modules'])


class TreeKey(unittest.TestCase):
    """A coverage map or a known-good verdict holds for one key: the tree's
    files and the builds' options, not the runner's config nor prose."""

    def key_after(self, change):
        """The key of the fixture (the config and prose ignored, as edsc's
        config does) before and after `change(root)`."""
        with tempfile.TemporaryDirectory(prefix='edsc-mutation-key-') as tmp:
            root = pathlib.Path(tmp) / 'project'
            shutil.copytree(FIXTURE, root)
            subprocess.run(['git', 'init', '-q'], cwd=root, check=True)
            edit_config(root, lambda c: c.update(key_ignore=['*.md', 'tests/mutation/*']))
            before = project_key(root)
            change(root)
            return before, project_key(root)

    def test_the_key_changes_with_the_builds_options(self):
        before, after = self.key_after(
            lambda root: edit_config(root, lambda c: c['cmake_args']['release'].append('-DFAKE_OPTION=1')))
        self.assertNotEqual(before, after)

    def test_the_key_changes_with_a_source_not_with_prose_nor_the_config(self):
        before, after = self.key_after(lambda root: (root / 'notes.md').write_text('prose\n'))
        self.assertEqual(before, after)
        before, after = self.key_after(lambda root: edit_config(root, lambda c: c.update(about='the fixture')))
        self.assertEqual(before, after)
        before, after = self.key_after(lambda root: (root / 'lib' / 'more.cpp').write_text('int x;\n'))
        self.assertNotEqual(before, after)


def edit_config(root, change):
    path = root / 'tests' / 'mutation' / 'config.json'
    config = json.loads(path.read_text())
    change(config)
    path.write_text(json.dumps(config))


def project_key(root):
    r = subprocess.run([sys.executable, '-c', 'import sys; sys.dont_write_bytecode = True; sys.path.insert(0, sys.argv[1]); '
                        'from mutation import project; print(project.Project(sys.argv[2]).key())',
                        str(ROOT / 'scripts'), str(root)], capture_output=True, text=True, check=True)
    return r.stdout.strip()


class FixtureRun(unittest.TestCase):
    """One run of scripts/mutate on chosen mutants of the fixture."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix='edsc-mutation-test-')
        tmp = pathlib.Path(cls.tmp.name)
        cls.root = tmp / 'project'
        shutil.copytree(FIXTURE, cls.root)
        git = ['git', '-c', 'user.name=test', '-c', 'user.email=test@example.invalid']
        subprocess.run(['git', 'init', '-q'], cwd=cls.root, check=True)
        subprocess.run(['git', 'add', '-A'], cwd=cls.root, check=True)
        subprocess.run([*git, 'commit', '-qm', 'fixture'], cwd=cls.root, check=True)
        mutants = listing('lib', cls.root)
        cls.ids = {
            'state': find(mutants, 'lib/counter.cpp:12:3 while-if'),
            'flaky': find(mutants, 'lib/counter.cpp:18:31 const: `2` -> `3`'),
            'killed': find(mutants, 'lib/counter.cpp:15:30 const: `2` -> `3`'),
            'header': find(mutants, 'lib/counter.hpp:10:37 rel-boundary'),
            'generated': find(mutants, 'lib/emit.cpp:4:41 gen-rel-boundary'),
            'uncovered': find(mutants, 'lib/counter.cpp:21:32 const: `7` -> `8`'),
        }
        cls.flaky_runs = tmp / 'flaky-runs'
        cls.result = mutate('lib', '--work', str(tmp / 'work'), '--mutant', ','.join(cls.ids.values()),
                         env={'FAKE_FLAKY_COUNTER': str(cls.flaky_runs)}, root=cls.root)
        print(cls.result.stdout[-4000:], cls.result.stderr[-2000:])
        results = tmp / 'work' / 'results-lib.json'
        verdicts = json.loads(results.read_text())['results'] if results.exists() else {}
        cls.v = {k: verdicts.get(mid, {}) for k, mid in cls.ids.items()}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_run_ends_well(self):
        self.assertEqual(self.result.returncode, 0)

    def test_a_mutant_killed_only_through_state_an_earlier_test_left_is_not_killed(self):
        self.assertEqual(self.v['state'].get('status'), 'survived')

    def test_a_test_that_fails_once_on_a_mutant_and_then_passes_is_a_flake(self):
        self.assertEqual(self.v['flaky'].get('status'), 'survived')
        self.assertEqual(self.v['flaky'].get('flaky'), ['fake.flaky'])
        self.assertGreaterEqual(int(self.flaky_runs.read_text()), 4)  # map, unmutated, mutant twice

    def test_a_test_that_fails_alone_kills(self):
        self.assertEqual(self.v['killed'].get('killed_by'), 'fake.half')

    def test_a_header_mutant_is_judged(self):
        self.assertEqual(self.v['header'].get('killed_by'), 'fake.small')

    def test_generated_c_is_judged_by_the_test_that_builds_and_runs_it(self):
        # fake.text, a text comparison, is cheaper and would kill it first.
        self.assertEqual(self.v['generated'].get('killed_by'), 'fake.compile_generated')

    def test_a_mutant_no_test_runs_is_not_covered(self):
        self.assertEqual(self.v['uncovered'].get('status'), 'not-covered')

    def smoke(self, lines):
        build = self.root / 'build'
        if not (build / 'build.ninja').exists():
            subprocess.run(['cmake', '-S', str(self.root), '-B', str(build), '-G', 'Ninja'], check=True,
                           capture_output=True)
            subprocess.run(['cmake', '--build', str(build)], check=True, capture_output=True)
        (self.root / 'tests' / 'mutation' / 'smoke.txt').write_text(''.join(line + '\n' for line in lines))
        r = mutate('--smoke', '--work', str(self.root / 'smoke-work'), root=self.root)
        self.assertEqual(subprocess.run(['git', 'diff', '--quiet'], cwd=self.root).returncode, 0,
                         'the smoke leaves the sources as they were')
        return r

    def test_the_smoke_passes_when_the_named_test_kills_alone(self):
        r = self.smoke([f"lib {self.ids['header']} fake.small"])
        self.assertEqual(r.returncode, 0, r.stdout)

    def test_the_smoke_fails_when_the_named_test_kills_only_after_another(self):
        r = self.smoke([f"lib {self.ids['header']} fake.small", f"lib {self.ids['state']} fake.second"])
        self.assertEqual(r.returncode, 1, r.stdout)
        self.assertIn(f"{self.ids['state']} lib/counter.cpp:12:3 while-if", r.stdout)


if __name__ == '__main__':
    unittest.main(verbosity=2)
