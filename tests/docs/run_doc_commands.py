#!/usr/bin/env python3
"""Runs every command docs/*.md, README.md and the man pages show, as shown.

    run_doc_commands.py EDSC PROJECT_DIR SHARED_DIR OPENER_BINARY

The Markdown convention is in doc_blocks.py and docs/testing.md. The man
pages' EXAMPLES are the CLI model's (`edsc _model`), run as `edsc ...` lines
of a block are: accepted as written; an example that names a device's
address gets `edsc sim device.eds` there. Everything runs in a network
namespace of its own holding only a loopback (and, while OpENer runs, a veth pair
to OpENer's own namespace inside it), so the
addresses the docs name are reached inside it and no packet leaves it.
Commands that cannot run here are in not_run.txt with the reason; a listed
command the docs no longer show fails the test, so the list stays true.
"""
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import doc_blocks  # noqa: E402

HERE = Path(__file__).parent
# Files of the shared folder the docs' commands name, copied into each workspace.
SHARED_FILES = {
    "vendor.eds": "eds-corpus/kh-ko__NVM__eds_sample.txt.eds",  # a vendor's file with errors
    "buffer.tmp": "eds-corpus/kh-ko__NVM__eds_sample.txt.eds",
    "opener_sample_app.eds": "opener/data/opener_sample_app.eds",
    "startup.log": "captures/rightsight-42ef-startup.tsv",
}
DEVICE_IF = "edscdoc0"


def enter_namespace():
    """Re-runs this script in a network namespace of its own (root: a plain
    one; another user: inside a user namespace)."""
    if os.environ.get("EDSC_DOCS_NETNS") == "1":
        return
    env = dict(os.environ, EDSC_DOCS_NETNS="1")
    cmd = ["unshare", "--net"] + ([] if os.geteuid() == 0 else ["--map-root-user"])
    r = subprocess.run(cmd + [sys.executable, __file__] + sys.argv[1:], env=env)
    if r.returncode != 0 and shutil.which("unshare") is None:
        print("no `unshare` to make a network namespace with", file=sys.stderr)
    sys.exit(r.returncode)


def sh(cmd):
    subprocess.run(cmd, shell=True, check=True, stdout=subprocess.DEVNULL)


def wait_port(address, port, seconds=15):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        try:
            with socket.create_connection((address, port), timeout=0.5):
                return True
        except OSError:
            time.sleep(0.1)
    return False


class Runner:
    def __init__(self, edsc, project, shared, opener):
        self.edsc, self.project, self.shared, self.opener = edsc, Path(project), Path(shared), opener
        self.tmp = Path(tempfile.mkdtemp(prefix="edsc-docs-"))
        self.failures, self.ran, self.not_run_used = [], 0, set()
        self.not_run = self.read_not_run()
        self.addresses = set()
        bin_dir = self.tmp / "bin"
        bin_dir.mkdir()
        (bin_dir / "edsc").symlink_to(edsc)
        self.env = dict(os.environ, PATH=f"{bin_dir}:{os.environ['PATH']}", HOME=str(self.tmp / "home"))
        self.env.pop("NO_COLOR", None)
        self.n = 0

    def read_not_run(self):
        out = {}
        for line in (HERE / "not_run.txt").read_text().splitlines():
            if not line.strip() or line.startswith("#"):
                continue
            command, _, reason = line.partition(" -- ")
            out[command.strip()] = reason.strip()
        return out

    def workspace(self):
        """A fresh copy of tests/docs/workspace beside `../shared`, eds/ the project's."""
        self.n += 1
        root = self.tmp / f"run{self.n}"
        work = root / "work"
        shutil.copytree(HERE / "workspace", work, symlinks=True)
        shutil.copytree(self.project / "eds", work / "eds")
        (root / "shared").symlink_to(self.shared)
        # Copies, never links: a command that writes a file in place must not reach the corpus.
        for name, source in SHARED_FILES.items():
            shutil.copy(self.shared / source, work / name)
        shutil.copy(work / "device.eds", work / "dev.eds")
        shutil.copy(work / "device.eds", work / "eds/device.eds")  # ci.md's repository keeps its files in eds/
        shutil.copy(work / "eds/rightsight-42ef-diffuse.eds", work / "old.eds")
        shutil.copy(work / "eds/rightsight-42ef-diffuse.eds", work / "node.eds")  # a DeviceNet node
        shutil.copy(work / "eds/rightsight-42ef-3byte.eds", work / "new.eds")
        (work / "library").mkdir()
        for f in (work / "eds").glob("*.eds"):
            shutil.copy(f, work / "library")
        thesis = (work / "eds/networks/thesis.toml").read_text()
        (work / "plant.toml").write_text(thesis.replace('eds = "../', 'eds = "eds/'))
        # OpENer's EDS with Connection1's O->T size set to 33, as live.md makes it.
        shutil.copy(work / "opener_sample_app.eds", work / "opener-33.eds")
        subprocess.run([self.edsc, "edit", "opener-33.eds", "--in-place", "--set",
                        "Connection Manager.Connection1.ot_size=33"], cwd=work, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        # live.md's library: OpENer's EDS and the corpus (read only: links).
        lib = work / "lib"
        lib.mkdir()
        shutil.copy(work / "opener_sample_app.eds", lib)
        for f in sorted((self.shared / "eds-corpus").iterdir()):
            (lib / f.name).symlink_to(f)
        home = Path(self.env["HOME"])
        for d in (".local/share/bash-completion/completions", ".zfunc", ".config/fish/completions"):
            (home / d).mkdir(parents=True, exist_ok=True)
        return work

    def add_address(self, address):
        if address in self.addresses or address.startswith("127."):
            return
        sh(f"ip addr add {address}/32 dev lo")
        self.addresses.add(address)

    def start_opener(self, address, cwd, log):
        """OpENer in a namespace of its own behind a veth pair (a scanner and a
        device on one host would both want UDP 2222), at `address`; this
        side takes the other address of its /31."""
        host = address.rsplit(".", 1)[0] + "." + str(int(address.rsplit(".", 1)[1]) ^ 1)
        sh(f"ip link del {DEVICE_IF} 2>/dev/null || true")
        sh(f"ip link add {DEVICE_IF} type veth peer name {DEVICE_IF}d && ip addr add {host}/31 dev {DEVICE_IF}"
           f" && ip link set {DEVICE_IF} up")
        ready = cwd / "device-ready"
        script = (f"while [ ! -e {ready} ]; do sleep 0.05; done; ip link set lo up && "
                  f"ip addr add {address}/31 dev {DEVICE_IF}d && ip link set {DEVICE_IF}d up && "
                  f"exec {self.opener} {DEVICE_IF}d")
        p = self.start(["unshare", "--net", "sh", "-c", script], cwd, log)
        # The link moves into the child's namespace once it has one of its own.
        mine, end = os.readlink("/proc/self/ns/net"), time.monotonic() + 10
        while p.poll() is None and os.readlink(f"/proc/{p.pid}/ns/net") == mine and time.monotonic() < end:
            time.sleep(0.01)
        sh(f"ip link set {DEVICE_IF}d netns {p.pid}")
        ready.touch()
        return p

    def start(self, argv, cwd, log):
        return subprocess.Popen(argv, cwd=cwd, env=self.env, stdin=subprocess.DEVNULL, stdout=log,
                                stderr=subprocess.STDOUT, start_new_session=True)

    @staticmethod
    def stop(p):
        if p.poll() is None:
            os.killpg(p.pid, 15)
            try:
                p.wait(5)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, 9)
                p.wait()

    def start_device(self, kind, address, cwd, eds="device.eds"):
        log = open(cwd / f"device-{address}.log", "w")
        if kind == "opener":
            p = self.start_opener(address, cwd, log)
        else:
            self.add_address(address)
            p = self.start([self.edsc, "sim", eds, "--address", address], cwd, log)
        if not wait_port(address, 44818):
            self.stop(p)
            raise RuntimeError(f"{kind} did not answer at {address}:44818; its log: {(cwd / log.name).read_text()}")
        return p

    def run(self, text, cwd, where, want_status, want_output):
        self.ran += 1
        try:
            r = subprocess.run(["sh", "-c", text], cwd=cwd, env=self.env, stdin=subprocess.DEVNULL,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
            out, status = r.stdout.decode("utf-8", "replace"), r.returncode
        except subprocess.TimeoutExpired:
            out, status = "(killed after 120 s)", -1
        problems = []
        if status not in want_status:
            problems.append(f"exit status {status}, the docs say {'/'.join(map(str, sorted(want_status)))}")
        if want_output is not None and not matches(want_output, out):
            problems.append("output differs from the docs'")
        if problems:
            shown = "\n".join("    | " + l for l in want_output) if want_output is not None else "    (not shown)"
            gave = out.rstrip("\n").split("\n")
            gave = gave[:40] + ([f"    ({len(gave) - 40} more lines)"] if len(gave) > 40 else [])
            self.failures.append(f"{where}: $ {text}\n  " + "; ".join(problems) + f"\n  the docs:\n{shown}\n"
                                 f"  edsc gave:\n" + "\n".join("    | " + l for l in gave))

    def block(self, b):
        kind = b.marker.split()
        if kind and kind[0] == "illustrative":
            return
        cwd = self.workspace()
        background = []
        try:
            if kind and kind[0] == "device":
                background.append(self.start_device(kind[1], kind[2], cwd))
            elif kind:
                self.failures.append(f"{b.path}:{b.line}: unknown marker 'docs-test: {b.marker}'")
                return
            for c in b.commands:
                where = f"{b.path}:{c.line}"
                if c.text in self.not_run:
                    self.not_run_used.add(c.text)
                    continue
                if c.background:
                    log = open(cwd / f"background-{c.line}.log", "w")
                    p = self.start(["sh", "-c", "exec " + c.text], cwd, log)
                    background.append(p)
                    m = re.search(r"--address (\S+)", c.text)
                    if m and not wait_port(m.group(1), 44818):
                        self.failures.append(f"{where}: $ {c.text} &: nothing answered at {m.group(1)}:44818")
                        return
                    continue
                self.run(c.text, cwd, where, c.status, c.output)
        except RuntimeError as e:
            self.failures.append(f"{b.path}:{b.line}: {e}")
        finally:
            for p in background:
                self.stop(p)

    def markdown(self):
        files = sorted((self.project / "docs").glob("*.md")) + [self.project / "README.md"]
        for f in files:
            rel = str(f.relative_to(self.project))
            for b in doc_blocks.read(rel, f.read_text()):
                self.block(b)

    def man_examples(self):
        model = json.loads(subprocess.run([self.edsc, "_model"], stdout=subprocess.PIPE, check=True).stdout)
        examples = []

        def walk(c):
            examples.extend((c["path"], e["command"]) for e in c.get("examples", []))
            for s in c["subcommands"]:
                walk(s)

        walk(model)
        if len(examples) < 20:
            self.failures.append(f"the CLI model has {len(examples)} examples; the man pages show more")
        for path, text in examples:
            where = f"man edsc-{path.replace(' ', '-')} (EXAMPLES)"
            if text in self.not_run:
                self.not_run_used.add(text)
                continue
            cwd = self.workspace()
            devices = []
            try:
                for address in re.findall(r"\b(\d+\.\d+\.\d+\.\d+)\b", text):
                    if not text.startswith("edsc sim "):
                        devices.append(self.start_device("sim", address, cwd))
                if re.match(r"edsc (sim|lsp)\b", text):
                    self.server(text, cwd, where)
                else:
                    self.run(text, cwd, where, {0, 1}, None)
            except RuntimeError as e:
                self.failures.append(f"{where}: {e}")
            finally:
                for p in devices:
                    self.stop(p)

    def server(self, text, cwd, where):
        """A command that serves until stopped: it must still run after a
        second (or have ended with 0), and is then stopped."""
        self.ran += 1
        log = open(cwd / "server.log", "w")
        # Standard input stays open: an LSP server ends (1) when it closes unasked.
        p = subprocess.Popen(["sh", "-c", "exec " + text], cwd=cwd, env=self.env, stdin=subprocess.PIPE, stdout=log,
                             stderr=subprocess.STDOUT, start_new_session=True)
        time.sleep(1)
        status = p.poll()
        self.stop(p)
        if status not in (None, 0):
            self.failures.append(f"{where}: $ {text}\n  ended with {status}: {(cwd / 'server.log').read_text()}")


def matches(expected, actual):
    """The docs' lines against the output: `...` alone any lines, `...` in a
    line any text, a run of spaces any run of spaces."""
    lines = actual.rstrip("\n").split("\n") if actual.strip() else []
    pattern = []
    for e in expected:
        if e.strip() == "...":
            pattern.append(r"(?:[^\n]*\n)*?")
            continue
        pieces = [" +".join(re.escape(w) for w in re.split(r" +", p)) for p in e.rstrip().split("...")]
        pattern.append(r"[^\n]*?".join(pieces) + r"\n")
    text = "".join(l.rstrip() + "\n" for l in lines)
    return re.fullmatch("".join(pattern), text, re.S) is not None


def main():
    enter_namespace()
    edsc, project, shared, opener = sys.argv[1:5]
    sh("ip link set lo up")
    r = Runner(edsc, project, shared, opener)
    try:
        r.markdown()
        r.man_examples()
    finally:
        shutil.rmtree(r.tmp, ignore_errors=True)
    for command in sorted(set(r.not_run) - r.not_run_used):
        r.failures.append(f"not_run.txt lists a command no page shows: {command}")
    for f in r.failures:
        print(f + "\n")
    print(f"{r.ran} commands run, {len(r.not_run_used)} listed as not runnable here, {len(r.failures)} failures")
    return 1 if r.failures or r.ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
