"""The verdicts of a module, kept per tree key, and the score table."""
import json
import pathlib
import time

STATUSES = ('killed', 'survived', 'not-covered', 'equivalent', 'uncompilable')


class Results:
    """<work>/results-<module>.json: the verdicts under one tree key, and
    the record of every run (its seed and sample). A verdict holds only for
    the tree it was judged on: when the key changes, the file is put aside
    and every mutant is judged again."""

    def __init__(self, work, module, key, reading=False):
        self.path = pathlib.Path(work) / f"results-{module.rstrip('/').replace('/', '_')}.json"
        data = json.loads(self.path.read_text()) if self.path.exists() else {}
        self.stale = bool(data) and data.get('key') != key
        if self.stale and not reading:
            self.path.rename(self.path.with_name(self.path.stem + f"-{data.get('key')}.json"))
            data = {}
        self.key = data.get('key', key)
        self.verdicts = data.get('results', {})
        self.runs = data.get('runs', [])

    def save(self):
        self.path.write_text(json.dumps({'key': self.key, 'results': self.verdicts, 'runs': self.runs},
                                        indent=1, sort_keys=True) + '\n')

    def record(self, mutant, verdict):
        self.verdicts[mutant.id] = dict(verdict, where=mutant.describe(), file=mutant.path, line=mutant.line,
                                        op=mutant.op, kind=mutant.kind, original=mutant.original,
                                        replacement=mutant.replacement)
        self.save()

    def start_run(self, **run):
        self.runs.append(dict(run, started=time.strftime('%Y-%m-%d %H:%M:%S')))
        self.save()


def load_equivalent(root):
    """tests/mutation/equivalent.txt: `<id> <reason>` per line."""
    path = pathlib.Path(root) / 'tests' / 'mutation' / 'equivalent.txt'
    out = {}
    if path.exists():
        for line in path.read_text().splitlines():
            line = line.strip()
            if line and not line.startswith('#'):
                mid, _, reason = line.partition(' ')
                out[mid] = reason.strip()
    return out


def status_of(verdict, equivalent, mid):
    s = verdict['status']
    return 'equivalent' if s in ('survived', 'not-covered') and mid in equivalent else s


def score(row):
    judged = row['killed'] + row['survived'] + row['not-covered']
    return f"{100.0 * row['killed'] / judged:.1f} %" if judged else "-"


def table(module, verdicts, mutants, equivalent):
    """(markdown table, totals, surviving mutants)."""
    by_file = {}
    for m in mutants:
        v = verdicts.get(m.id)
        if v is None:
            continue
        row = by_file.setdefault(m.path, dict.fromkeys(STATUSES, 0))
        row[status_of(v, equivalent, m.id)] += 1
    head = f"| {module} file | killed | survived | not covered | equivalent | uncompilable | score |"
    lines = [head, "|---|---|---|---|---|---|---|"]
    total = dict.fromkeys(STATUSES, 0)
    for path in sorted(by_file):
        row = by_file[path]
        for k in total:
            total[k] += row[k]
        lines.append(f"| {path} | " + " | ".join(str(row[k]) for k in STATUSES) + f" | {score(row)} |")
    lines.append("| **all** | " + " | ".join(str(total[k]) for k in STATUSES) + f" | {score(total)} |")
    survivors = [m for m in mutants if m.id in verdicts
                 and status_of(verdicts[m.id], equivalent, m.id) in ('survived', 'not-covered')]
    return '\n'.join(lines), total, survivors
