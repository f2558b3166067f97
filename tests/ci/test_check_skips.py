#!/usr/bin/env python3
"""scripts/check-skips fails a ctest run that skipped a test its list does not
allow: skips_fixture/ is built and run under ctest (GTEST_SKIP inside a
GoogleTest test, a SKIP_RETURN_CODE), and its junit report is checked
against skip lists with and without those tests.

Usage: test_check_skips.py PROJECT_ROOT
"""
import pathlib
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

ROOT = pathlib.Path(sys.argv.pop(1) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
LISTED = "Guard.SkipsListed  the fixture's own reason\nscript.* skips by its exit status\n"


class CheckSkips(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix='edsc-skips-test-')
        tmp = pathlib.Path(cls.tmp.name)
        build = tmp / 'build'
        subprocess.run(['cmake', '-S', str(ROOT / 'tests' / 'ci' / 'skips_fixture'), '-B', str(build), '-G', 'Ninja'],
                       check=True, capture_output=True)
        subprocess.run(['cmake', '--build', str(build)], check=True, capture_output=True)
        cls.junit = tmp / 'junit.xml'
        cls.ctest = subprocess.run(['ctest', '--test-dir', str(build), '--output-junit', str(cls.junit)],
                                   capture_output=True, text=True)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def guard(self, skips_text):
        skips = pathlib.Path(self.tmp.name) / 'skips.txt'
        skips.write_text(skips_text)
        return subprocess.run([sys.executable, str(ROOT / 'scripts' / 'check-skips'), str(self.junit), str(skips)],
                              capture_output=True, text=True)

    def test_ctest_passes_a_run_with_skips_and_reports_gtest_skip_as_skipped(self):
        self.assertEqual(self.ctest.returncode, 0, self.ctest.stdout)
        cases = {c.get('name'): c for c in ET.parse(self.junit).getroot().iter('testcase')}
        self.assertIsNotNone(cases['Guard.SkipsUnlisted'].find('skipped'))
        self.assertEqual(cases['Guard.Passes'].get('status'), 'run')

    def test_a_skip_the_list_does_not_name_fails_with_what_the_test_said(self):
        r = self.guard(LISTED)
        self.assertEqual(r.returncode, 1, r.stdout)
        self.assertIn('SKIPPED and not allowed: Guard.SkipsUnlisted: named by no skip list', r.stdout)
        self.assertNotIn('not allowed: Guard.SkipsListed', r.stdout)
        self.assertNotIn('not allowed: script.exits_77', r.stdout)

    def test_every_skip_listed_passes(self):
        r = self.guard(LISTED + "Guard.SkipsUnlisted  allowed now\n")
        self.assertEqual(r.returncode, 0, r.stdout)

    def test_a_listed_skip_without_a_reason_fails(self):
        r = self.guard(LISTED + "Guard.SkipsUnlisted\n")
        self.assertEqual(r.returncode, 1, r.stdout)
        self.assertIn('has no reason', r.stdout)


if __name__ == '__main__':
    unittest.main(verbosity=2)
