#!/usr/bin/env python3
"""The layer check (check_layers.py) on small trees made here: it passes a tree
whose includes the table allows and fails, naming the file and the line, on
each way a tree or its table can break the layers."""
import pathlib
import subprocess
import sys
import tempfile

CHECK = pathlib.Path(__file__).with_name('check_layers.py')

TABLE = """\
# top to bottom
live:  cip model
model: base
cip:   base
base:
never cip: model live
"""


def make_tree(root, table=TABLE, files=None):
    compiler = root / 'compiler'
    (compiler / 'deps').mkdir(parents=True)
    (compiler / 'deps' / 'glue.cpp').write_text('#include "live/x.hpp"\n')  # not a room: never read
    (compiler / 'layers.txt').write_text(table)
    files = files or {}
    base = {
        'base/result.hpp': '#pragma once\n',
        'cip/codec.hpp': '#pragma once\n#include "base/result.hpp"\n#include <vector>\n',
        'model/device.hpp': '#pragma once\n#include "base/result.hpp"\n',
        'live/session.cpp': '#include "live/session.hpp"\n#include "cip/codec.hpp"\n#include "model/device.hpp"\n'
                            '#include "grammar/eds_grammar.hpp"\n',
    }
    for name, text in {**base, **files}.items():
        (compiler / name).parent.mkdir(parents=True, exist_ok=True)
        (compiler / name).write_text(text)
    return compiler


def run(compiler):
    r = subprocess.run([sys.executable, str(CHECK), str(compiler)], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def expect(failures, what, compiler, status, *words):
    got, out = run(compiler)
    if got != status:
        failures.append(f'{what}: exit {got}, expected {status}:\n{out}')
    for w in words:
        if w not in out:
            failures.append(f'{what}: the report lacks {w!r}:\n{out}')


def main():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        expect(failures, 'allowed includes', make_tree(tmp / 'ok'), 0, '0 problems')
        # A room includes a header of a room above it: named by file and line.
        bad = make_tree(tmp / 'up', files={'cip/encap.cpp': '#include "cip/codec.hpp"\n#include "live/session.hpp"\n'})
        expect(failures, 'include from above', bad, 1,
               f'{bad}/cip/encap.cpp:2: cip includes live/session.hpp', 'lets cip use only base')
        # A room beside it, not below it, is no more allowed.
        side = make_tree(tmp / 'side', files={'model/visit.hpp': '#include "cip/codec.hpp"\n'})
        expect(failures, 'include from beside', side, 1, f'{side}/model/visit.hpp:1: model includes cip/codec.hpp')
        # A folder the table does not know.
        extra = make_tree(tmp / 'extra', files={'net/socket.hpp': '#pragma once\n'})
        expect(failures, 'room without a line', extra, 1, f'{extra}/net: a room of compiler/ with no line')
        # The table itself breaks a never line.
        loose = make_tree(tmp / 'never', table=TABLE.replace('cip:   base', 'cip:   base model'))
        expect(failures, 'never line', loose, 1, 'the table lets cip use model, which its never line forbids')
        # The table names a room above the line that uses it.
        upside = make_tree(tmp / 'order', table=TABLE.replace('model: base', 'model: base live'))
        expect(failures, 'order', upside, 1, 'model uses live, declared above it')
    for f in failures:
        print(f)
    print(f'{len(failures)} failure{"" if len(failures) == 1 else "s"}')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
