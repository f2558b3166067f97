"""The commands the documentation shows, read from its code blocks.

The convention (docs/testing.md, "Commands in the documentation"):

- A code block (indented by four spaces, or fenced) holds commands when a
  line of it starts with `$ ` and names edsc, or starts with `edsc `.
- `$ COMMAND` is run by sh in a fresh copy of tests/docs/workspace; the
  lines after it, up to the next `$ ` line, are its output (standard output
  and standard error as they interleave). A last line `[N]` is its exit
  status when not 0. A line `...` stands for any lines, `...` inside a line
  for any text, and runs of spaces match runs of spaces. A command ending in
  ` &` runs in the background until the block ends; its output is not read.
- A line `edsc ...` in a block without `$` lines is run for the command
  alone: it must be accepted as written (exit 0, or 1 for findings in its
  input); its output is not shown, so not compared.
- `<!-- docs-test: illustrative -->` on the line before a block: synopses
  with placeholders, or output without its command; not run.
  `<!-- docs-test: device opener ADDRESS -->`: OpENer runs at ADDRESS while
  the block runs.
- tests/docs/not_run.txt lists the commands that cannot run here, each with
  the reason.
"""
import re
from dataclasses import dataclass, field

MARKER = re.compile(r"^<!--\s*docs-test:\s*(.*?)\s*-->\s*$")


@dataclass
class Command:
    text: str            # as shown, without `$ `
    line: int            # 1-based line in the file
    output: list | None  # expected lines; None: not compared
    status: set          # accepted exit statuses
    background: bool = False


@dataclass
class Block:
    path: str
    line: int
    marker: str
    lines: list = field(default_factory=list)  # (line number, text without the block's indent)
    commands: list = field(default_factory=list)


def _blocks(path, text):
    lines = text.split("\n")
    out, i, marker = [], 0, ""
    while i < len(lines):
        line = lines[i]
        m = MARKER.match(line.strip())
        if m:
            marker = m.group(1)
            i += 1
            continue
        if line.startswith("```"):
            b = Block(path, i + 1, marker)
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                b.lines.append((i + 1, lines[i]))
                i += 1
            out.append(b)
            marker = ""
            i += 1
            continue
        prev_blank = i == 0 or lines[i - 1].strip() == "" or MARKER.match(lines[i - 1].strip())
        if line.startswith("    ") and line.strip() and prev_blank and not _in_list(lines, i):
            b = Block(path, i + 1, marker)
            while i < len(lines) and (lines[i].startswith("    ") or lines[i].strip() == ""):
                b.lines.append((i + 1, lines[i][4:]))
                i += 1
            while b.lines and not b.lines[-1][1].strip():
                b.lines.pop()
            out.append(_dedent(b))
            marker = ""
            continue
        if line.strip():
            marker = ""
        i += 1
    return out


def _dedent(b):
    """A block inside a list item is indented further: its common indent goes."""
    indent = min((len(t) - len(t.lstrip(" ")) for _, t in b.lines if t.strip()), default=0)
    b.lines = [(n, t[indent:]) for n, t in b.lines]
    return b


def _in_list(lines, i):
    """An indented paragraph that continues a list item is not a code block."""
    j = i - 1
    while j >= 0 and lines[j].strip() == "":
        j -= 1
    return j >= 0 and bool(re.match(r"^\s*([-*+]|\d+\.)\s", lines[j])) and not lines[j].startswith("    ")


def _names_edsc(text):
    return re.search(r"(^|[|;&(\s])edsc(\s|$)", text) is not None


def is_command_block(b):
    for _, t in b.lines:
        s = t.strip()
        if (s.startswith("$ ") and _names_edsc(s[2:])) or s.startswith("edsc "):
            return True
    return False


def _joined(lines, k):
    """A command and its continuation lines (ending in a backslash)."""
    n, text = lines[k]
    parts = [text.strip()]
    while parts[-1].endswith("\\") and k + 1 < len(lines):
        k += 1
        parts[-1] = parts[-1][:-1].rstrip()
        parts.append(lines[k][1].strip())
    return " ".join(parts), k


def parse_commands(b):
    lines = b.lines
    prompt = any(t.strip().startswith("$ ") for _, t in lines)
    k = 0
    while k < len(lines):
        n, t = lines[k]
        s = t.strip()
        if prompt and s.startswith("$ "):
            text, used = _joined([(n, s[2:])] + lines[k + 1:], 0)
            k += used
            out = []
            k += 1
            while k < len(lines) and not lines[k][1].strip().startswith("$ "):
                out.append(lines[k][1].rstrip())
                k += 1
            while out and not out[-1].strip():
                out.pop()
            status = {0}
            if out and re.fullmatch(r"\[\d+\]", out[-1].strip()):
                status = {int(out.pop().strip()[1:-1])}
            bg = text.endswith("&") and not text.endswith("&&")
            if bg:
                text = text[:-1].rstrip()
            b.commands.append(Command(text, n, None if bg else out, status, bg))
            continue
        if not prompt and s.startswith("edsc "):
            text, k = _joined(lines, k)
            b.commands.append(Command(text, n, None, {0, 1}))
        k += 1
    return b


def read(path, text):
    """The command blocks of one Markdown file, parsed."""
    return [parse_commands(b) for b in _blocks(path, text) if is_command_block(b)]
