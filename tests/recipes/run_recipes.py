#!/usr/bin/env python3
"""Runs the CI recipes a user copies (docs/ci.md) against the built edsc:

  run_recipes.py EDSC PROJECT_DIR pre-commit|github-action|gitlab

pre-commit: Debian's pre-commit runs the hooks of .pre-commit-hooks.yaml
(`pre-commit try-repo`) in a scratch git repository with a clean and a
broken EDS file. github-action and gitlab: the shell steps of action.yml and
packaging/gitlab-ci.yml run as the CI would run them (inputs at their
defaults, edsc already installed), and the SARIF they leave is checked.
Exit 77 (skipped) when a tool the recipe needs is missing.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

SKIP = 77


def sample_files(project):
    """The project's own level node EDS (checked clean by the suite) and the
    same with a ';' removed: a syntax error."""
    with open(os.path.join(project, "eds", "nodes", "level.eds")) as f:
        good = f.read()
    return good, re.sub(r"(ProdCode\s*=\s*\d+);", r"\1", good, count=1)


def fail(msg):
    print("FAILED: " + msg)
    sys.exit(1)


def run(cmd, cwd, env, shell=False):
    return subprocess.run(cmd, cwd=cwd, env=env, shell=shell, capture_output=True, text=True, timeout=300)


def scratch_repo(tmp, files, env):
    repo = os.path.join(tmp, "repo")
    os.makedirs(repo)
    for name, text in files.items():
        with open(os.path.join(repo, name), "w") as f:
            f.write(text)
    for cmd in (["git", "init", "-q"], ["git", "add", "."]):
        if run(cmd, repo, env).returncode != 0:
            fail(" ".join(cmd))
    return repo


def pre_commit(edsc_dir, project, tmp, env):
    GOOD, BROKEN = sample_files(project)
    if shutil.which("pre-commit") is None or shutil.which("git") is None:
        print("pre-commit or git not installed")
        return SKIP
    if not os.path.isdir(os.path.join(project, ".git")) and run(["git", "rev-parse"], project, env).returncode != 0:
        print("the project is not a git checkout: pre-commit cannot take its hooks")
        return SKIP
    env = dict(env, PRE_COMMIT_HOME=os.path.join(tmp, "cache"), GIT_AUTHOR_NAME="t", GIT_AUTHOR_EMAIL="t@t",
               GIT_COMMITTER_NAME="t", GIT_COMMITTER_EMAIL="t@t")
    repo = scratch_repo(tmp, {"good.eds": GOOD, "broken.eds": BROKEN, "notes.txt": "x\n"}, env)
    # The clean file passes both hooks; the broken one fails edsc-check.
    for hook, files, want in (("edsc-check", ["good.eds"], 0), ("edsc-check", ["broken.eds"], 1),
                              ("edsc-fmt", ["good.eds"], 0)):
        r = run(["pre-commit", "try-repo", project, hook, "--files"] + files, repo, env)
        if r.returncode != want:
            fail(f"pre-commit {hook} {files}: exit {r.returncode}, wanted {want}\n{r.stdout}{r.stderr}")
        if want == 1 and "syntax-missing-semicolon" not in r.stdout:
            fail("edsc-check did not show the finding:\n" + r.stdout)
    # A file that is not laid out canonically fails edsc-fmt.
    with open(os.path.join(repo, "good.eds"), "a") as f:
        f.write("[Params]\n Param1 =   0,,,;\n")
    r = run(["pre-commit", "try-repo", project, "edsc-fmt", "--files", "good.eds"], repo, env)
    if r.returncode != 1 or "not formatted" not in r.stdout:
        fail(f"edsc-fmt on an unformatted file: exit {r.returncode}\n{r.stdout}{r.stderr}")
    return 0


def check_sarif(path, want_results):
    with open(path) as f:
        sarif = json.load(f)
    if sarif.get("version") != "2.1.0":
        fail(f"{path} is not SARIF 2.1.0")
    results = sum(len(run_.get("results", [])) for run_ in sarif["runs"])
    if (results > 0) != want_results:
        fail(f"{path}: {results} results")


def shell_steps_of_action(project):
    import yaml
    with open(os.path.join(project, "action.yml")) as f:
        action = yaml.safe_load(f)
    defaults = {k: str(v.get("default", "")) for k, v in action["inputs"].items()}
    steps = {}
    for step in action["runs"]["steps"]:
        if "run" in step:
            script = re.sub(r"\$\{\{\s*inputs\.(\w+)\s*\}\}", lambda m: defaults[m.group(1)], step["run"])
            steps[step.get("id", step["name"])] = script
    return steps


def github_action(edsc_dir, project, tmp, env):
    GOOD, BROKEN = sample_files(project)
    try:
        import yaml  # noqa: F401
    except ImportError:
        print("python3-yaml not installed")
        return SKIP
    steps = shell_steps_of_action(project)
    for files, want_status in (({"good.eds": GOOD}, "0"), ({"good.eds": GOOD, "broken.eds": BROKEN}, "1")):
        work = tempfile.mkdtemp(dir=tmp)
        repo = scratch_repo(work, files, env)
        out = os.path.join(work, "github_output")
        open(out, "w").close()
        step_env = dict(env, GITHUB_ACTION_PATH=project, GITHUB_OUTPUT=out, GITHUB_PATH=os.path.join(work, "path"),
                        RUNNER_TEMP=work)
        # edsc is on PATH, so the install step only checks for it.
        for name in ("Install edsc", "check"):
            r = run(["bash", "-e", "-c", steps[name]], repo, step_env)
            if r.returncode != 0:
                fail(f"action step {name}: exit {r.returncode}\n{r.stdout}{r.stderr}")
        with open(out) as f:
            said = f.read()
        if f"status={want_status}" not in said:
            fail(f"the check step said {said!r}, wanted status={want_status}")
        check_sarif(os.path.join(repo, "edsc.sarif"), want_status == "1")
        r = run(["bash", "-c", steps["Fail on errors"].replace("${{ steps.check.outputs.status }}", want_status)],
                repo, step_env)
        if str(r.returncode) != want_status:
            fail("the last step's exit status")
    return 0


def gitlab(edsc_dir, project, tmp, env):
    GOOD, BROKEN = sample_files(project)
    try:
        import yaml
    except ImportError:
        print("python3-yaml not installed")
        return SKIP
    with open(os.path.join(project, "packaging", "gitlab-ci.yml")) as f:
        job = yaml.safe_load(f)["edsc-check"]
    variables = job["variables"]
    for files, want in (({"good.eds": GOOD}, 0), ({"broken.eds": BROKEN}, 1)):
        work = tempfile.mkdtemp(dir=tmp)
        repo = scratch_repo(work, files, env)
        # The job's script as one shell, as the runner runs it (before_script
        # installs the package; edsc is installed here already).
        r = run(["bash", "-c", "\n".join(job["script"])], repo, dict(env, **variables))
        if r.returncode != want:
            fail(f"gitlab job script: exit {r.returncode}, wanted {want}\n{r.stdout}{r.stderr}")
        check_sarif(os.path.join(repo, "edsc.sarif"), want == 1)
        for artifact in job["artifacts"]["paths"]:
            if not os.path.exists(os.path.join(repo, artifact)):
                fail("artifact missing: " + artifact)
    return 0


def main():
    edsc, project, recipe = sys.argv[1:4]
    edsc_dir = os.path.dirname(os.path.abspath(edsc))
    env = dict(os.environ, PATH=edsc_dir + os.pathsep + os.environ.get("PATH", ""), NO_COLOR="1")
    with tempfile.TemporaryDirectory() as tmp:
        status = {"pre-commit": pre_commit, "github-action": github_action, "gitlab": gitlab}[recipe](
            edsc_dir, project, tmp, env)
    if status == 0:
        print(f"{recipe}: 1 passed, 0 failed")
    sys.exit(status)


if __name__ == "__main__":
    main()
