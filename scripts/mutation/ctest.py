"""One ctest test run alone, as CI's ctest runs it: one test, one process
(`ctest -R '^name$'`), with the test's own properties (timeout, skip rules,
working folder, environment). Tests of the labels the project config names
(network namespaces, ports) hold the shared lock for their run."""
import contextlib
import fcntl
import json
import os
import pathlib
import signal
import subprocess
import tempfile
import time
import xml.etree.ElementTree as ET

SPECIAL = set('^$.[]*+?()|\\')


def exact(name):
    """A ctest -R regular expression matching `name` and nothing else."""
    return '^' + ''.join('\\' + c if c in SPECIAL else c for c in name) + '$'


def list_tests(build_dir):
    """name -> {'command', 'labels', 'timeout'} for every test of the build."""
    r = subprocess.run(['ctest', '--test-dir', str(build_dir), '--show-only=json-v1'], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"ctest cannot list the tests of {build_dir}:\n{r.stderr}")
    out = {}
    for t in json.loads(r.stdout)['tests']:
        props = {p['name']: p['value'] for p in t.get('properties', [])}
        if props.get('DISABLED'):
            continue
        out[t['name']] = {'command': t.get('command', []), 'labels': props.get('LABELS', []),
                          'timeout': props.get('TIMEOUT')}
    return out


class Outcome:
    def __init__(self, status, seconds, detail=''):
        self.status = status  # pass, fail, skip, timeout, missing
        self.seconds = seconds
        self.detail = detail

    def __repr__(self):
        return f"Outcome({self.status}, {self.seconds:.1f} s)"


def _junit_outcome(path):
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, FileNotFoundError):
        return None, ''
    cases = root.findall('.//testcase')
    if not cases:
        return 'missing', 'no such test'
    case = cases[0]
    out = (case.findtext('system-out') or '')[-1500:]
    status = case.get('status')
    if status == 'run':
        return 'pass', out
    if status == 'notrun' and case.find('skipped') is not None:
        return 'skip', out
    return 'fail', out


@contextlib.contextmanager
def _held(lock, labels):
    """The shared lock, when one of the test's labels needs it; taken before
    the clock starts, so waiting for it is never read as a hang."""
    if not (lock and lock.get('file') and set(labels) & set(lock.get('labels', []))):
        yield
        return
    with open(lock['file'], 'a') as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def run(build_dir, name, labels=(), lock=None, env=None, watchdog=None):
    """Runs test `name` alone under ctest; `watchdog` seconds (if given) ends
    a hang sooner than the test's own TIMEOUT would."""
    with tempfile.TemporaryDirectory(prefix='edsc-mutate-ctest-') as tmp, _held(lock, labels):
        junit = pathlib.Path(tmp) / 'junit.xml'
        cmd = ['ctest', '--test-dir', str(build_dir), '-R', exact(name), '--no-tests=error',
               '--output-junit', str(junit)]
        t0 = time.time()
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             env=dict(os.environ, **(env or {})), start_new_session=True)
        try:
            text, _ = p.communicate(timeout=watchdog)
        except subprocess.TimeoutExpired:
            _end(p)
            return Outcome('timeout', time.time() - t0, f'no end after {watchdog:.0f} s')
        seconds = time.time() - t0
        status, detail = _junit_outcome(junit)
        if status is None:
            return Outcome('missing' if 'No tests were found' in text else 'fail', seconds, text[-1500:])
        return Outcome(status, seconds, detail or text[-1500:])


def _end(p):
    """Ends ctest and the test it runs (its session): TERM, then KILL."""
    for sig, wait in ((signal.SIGTERM, 10), (signal.SIGKILL, 10)):
        try:
            os.killpg(p.pid, sig)
        except ProcessLookupError:
            return
        try:
            p.wait(timeout=wait)
            return
        except subprocess.TimeoutExpired:
            continue
