#!/usr/bin/env python3
"""Checks every #include "room/..." of compiler/ against compiler/layers.txt.

A room may include its own headers and those of the rooms the table lets it
use (the rooms on its line, and the rooms those may use). Fails, naming the
file and the line, on an include the table does not allow; fails too when a
folder of compiler/ is not in the table, when a room's line names a room
declared above it (the table reads top to bottom), or when the table breaks
one of its own `never` lines. compiler/CMakeLists.txt (cmake/layers.cmake)
reads the same table to link each room's library.

    check_layers.py COMPILER_DIR     # exit 0 when every include is allowed
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*"([A-Za-z0-9_]+)/([^"]+)"')
# compiler/deps holds fmt's compiled part (the edsc_fmt library): no header
# of edsc, no room.
NOT_ROOMS = {'deps'}
SOURCES = ('.hpp', '.cpp', '.h', '.def', '.inc')


def read_table(path):
    """(rooms top to bottom, {room: [uses]}, [(room, [never])], problems)."""
    rooms, uses, never, problems = [], {}, [], []
    for n, raw in enumerate(path.read_text().splitlines(), 1):
        line = raw.split('#', 1)[0].strip()
        if not line:
            continue
        m = re.fullmatch(r'(never\s+)?([a-z_]+):\s*(.*)', line)
        if not m:
            problems.append(f'{path}:{n}: not a line of the table: {raw}')
            continue
        names = m.group(3).split()
        if m.group(1):
            never.append((m.group(2), names, n))
        elif m.group(2) in uses:
            problems.append(f'{path}:{n}: {m.group(2)} has a line already')
        else:
            rooms.append(m.group(2))
            uses[m.group(2)] = names
    return rooms, uses, never, problems


def reachable(uses, room):
    """The rooms `room` may use, directly or through the rooms it uses."""
    seen, todo = set(), list(uses.get(room, []))
    while todo:
        r = todo.pop()
        if r not in seen:
            seen.add(r)
            todo.extend(uses.get(r, []))
    return seen


def check_table(path, rooms, uses, never):
    problems = []
    for i, room in enumerate(rooms):
        for used in uses[room]:
            if used not in uses:
                problems.append(f'{path}: {room} uses {used}, which has no line')
            elif rooms.index(used) <= i:
                problems.append(f'{path}: {room} uses {used}, declared above it (the table reads top to bottom)')
    for room, names, n in never:
        for name in sorted(set(names) & reachable(uses, room)):
            problems.append(f'{path}:{n}: the table lets {room} use {name}, which its never line forbids')
    return problems


def check_includes(compiler, uses):
    problems, counted = [], 0
    folders = sorted(p for p in compiler.iterdir() if p.is_dir())
    names = {p.name for p in folders}
    for folder in folders:
        if folder.name in NOT_ROOMS:
            continue
        if folder.name not in uses:
            problems.append(f'{folder}: a room of compiler/ with no line in layers.txt')
            continue
        allowed = reachable(uses, folder.name) | {folder.name}
        for f in sorted(folder.iterdir()):
            if f.suffix not in SOURCES:
                continue
            for n, line in enumerate(f.read_text(errors='replace').splitlines(), 1):
                m = INCLUDE.match(line)
                if not m or m.group(1) not in names | set(uses):
                    continue
                counted += 1
                if m.group(1) not in allowed:
                    problems.append(f'{f}:{n}: {folder.name} includes {m.group(1)}/{m.group(2)}, '
                                    f'but layers.txt lets {folder.name} use only '
                                    f'{" ".join(sorted(allowed - {folder.name})) or "nothing"}')
    return problems, counted


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[-1].strip(), file=sys.stderr)
        return 2
    compiler = pathlib.Path(argv[1])
    table = compiler / 'layers.txt'
    rooms, uses, never, problems = read_table(table)
    problems += check_table(table, rooms, uses, never)
    found, counted = check_includes(compiler, uses)
    problems += found
    for p in problems:
        print(p)
    print(f'{counted} includes of a room checked against {len(rooms)} rooms: '
          f'{len(problems)} problem{"" if len(problems) == 1 else "s"}')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
