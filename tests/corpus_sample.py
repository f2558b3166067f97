"""The corpus sample of the Python validators, the same files as
tests/corpus_dirs.hpp's corpora::sample(): in each corpus folder (sorted) the
first file and every N-th after it, plus the two files with syntax errors.
N is the environment's EDSC_CORPUS_SAMPLE when set to a positive number, else
the build's (the --sample N argument CMake passes: 1 in Release, 8 under the
sanitizers). docs/testing.md says why."""
import os
import pathlib

BROKEN = {"kh-ko__NVM__eds_sample.txt.eds", "rossmann-engineering__EEIP.NET__fanucrobot0202.eds"}


def stride(build_default: int) -> int:
    try:
        n = int(os.environ.get("EDSC_CORPUS_SAMPLE", ""))
        if n > 0:
            return n
    except ValueError:
        pass
    return max(build_default, 1)


def pop_sample_arg(argv: list) -> int:
    """Removes `--sample N` from argv and returns the stride to use."""
    default = 1
    if "--sample" in argv:
        at = argv.index("--sample")
        default = int(argv[at + 1])
        del argv[at:at + 2]
    return stride(default)


def sample(folder: pathlib.Path, n: int) -> list:
    files = sorted(pathlib.Path(folder).glob("*.eds"))
    return [f for i, f in enumerate(files) if i % n == 0 or f.name in BROKEN]
