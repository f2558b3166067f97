#!/usr/bin/env python3
"""What `edsc net map --format=svg` shows, read from the parsed SVG tree.

    check_map_svg.py EDSC PROJECT_DIR

For the thesis network and for a small network with a block across a row
end, the expected bytes of every node are worked out by hand from the layout
rules (docs/network.md, "Layout"); the geometry (grid left, pixels per byte,
row height) is measured from the free cells of the SVG itself, so the check
is of where each box is relative to the grid, not of copied coordinates.
Each box must carry its node's label, the legend must list the nodes in MAC
order with the colour of their boxes.
"""
import pathlib
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

NS = '{http://www.w3.org/2000/svg}'
FAILURES = []


def expect(cond, what):
    if not cond:
        FAILURES.append(what)


def svg_of(edsc, network):
    r = subprocess.run([edsc, 'net', 'map', str(network), '--format=svg'], capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        sys.exit(f"net map {network} failed ({r.returncode}): {r.stderr}")
    return ET.fromstring(r.stdout)


def num(e, k):
    return float(e.get(k))


def images(root):
    """Per image ('Input', 'Output'): its title, its free cells and its node
    boxes, in document order. An image is everything from its title on."""
    out, current = {}, None
    for e in root:
        cls = e.get('class', '')
        if e.tag == NS + 'text' and cls == 'title' and e.text.split(' ')[0] in ('Input', 'Output'):
            current = out.setdefault(e.text.split(' ')[0], {'title': e.text, 'free': [], 'boxes': [], 'labels': []})
        elif e.tag == NS + 'text' and cls == 'title':
            current = None  # the legend
        elif current is None:
            continue
        elif e.tag == NS + 'rect' and cls == 'free':
            current['free'].append(e)
        elif e.tag == NS + 'rect' and cls == 'node':
            current['boxes'].append(e)
        elif e.tag == NS + 'text' and cls == 'label':
            current['labels'].append(e)
    return out


def legend(root):
    """(swatch colour, text) per legend line, in order."""
    out, inside, swatch = [], False, None
    for e in root:
        if e.tag == NS + 'text' and e.get('class') == 'title':
            inside = e.text == 'Nodes'
        elif inside and e.tag == NS + 'rect':
            swatch = e.get('fill')
        elif inside and e.tag == NS + 'text':
            out.append((swatch, e.text))
    return out


def check_image(name, image, capacity, want):
    """want: [(mac, node name, first byte, bytes)] in image order."""
    free = image['free']
    # 32 bytes (8 DWords) a row: ceil(capacity / 32) rows, the last one shorter.
    rows = (capacity + 31) // 32
    expect(len(free) == rows, f"{name}: {len(free)} rows of free cells, want {rows}")
    if not free:
        return {}
    left, top = num(free[0], 'x'), num(free[0], 'y')
    byte_w, row_h = num(free[0], 'width') / 32, num(free[0], 'height')
    expect(num(free[-1], 'width') == byte_w * (capacity - 32 * (rows - 1)), f"{name}: last row width")
    for r, cell in enumerate(free):
        expect(num(cell, 'y') == top + r * row_h and num(cell, 'x') == left, f"{name}: row {r} is not under row {r - 1}")
    # A block across a row end is drawn as one box a row.
    pieces = []
    for mac, node, first, size in want:
        at = first
        while at < first + size:
            end = min(first + size, (at // 32 + 1) * 32)
            pieces.append((mac, node, at, end - at))
            at = end
    boxes = image['boxes']
    expect(len(boxes) == len(pieces), f"{name}: {len(boxes)} boxes, want {len(pieces)}")
    colours = {}
    for (mac, node, at, size), box in zip(pieces, boxes):
        x, y, w, h = (num(box, k) for k in ('x', 'y', 'width', 'height'))
        where = f"{name} MAC {mac} byte {at}"
        expect(x == left + (at % 32) * byte_w, f"{where}: x {x}, want byte column {at % 32}")
        expect(y == top + (at // 32) * row_h, f"{where}: y {y}, want row {at // 32}")
        expect(w == size * byte_w and h == row_h, f"{where}: {w}x{h}, want {size} bytes by one row")
        title = box.find(NS + 'title')
        expect(title is not None and title.text.startswith(f"MAC {mac} {node}: "), f"{where}: title {title}")
        colours.setdefault(mac, set()).add(box.get('fill'))
    # Every box's label (when drawn) is its node's, inside the box; each node
    # is labelled at least once per image.
    labelled = set()
    for label in image['labels']:
        lx, ly = num(label, 'x'), num(label, 'y')
        inside = [(mac, node) for (mac, node, at, size), box in zip(pieces, boxes)
                  if num(box, 'x') <= lx < num(box, 'x') + num(box, 'width')
                  and num(box, 'y') <= ly <= num(box, 'y') + num(box, 'height')]
        if not inside:
            continue  # the reserved band's label
        mac, node = inside[0]
        expect(label.text in (str(mac), f"{mac} {node}"), f"{name}: label {label.text!r} in MAC {mac}'s box")
        labelled.add(mac)
    expect(labelled == {mac for mac, *_ in want}, f"{name}: labelled {sorted(labelled)}")
    return colours


def check_network(edsc, network, want_in, want_out, nodes):
    root = svg_of(edsc, network)
    got = images(root)
    expect(set(got) == {'Input', 'Output'}, f"{network}: images {sorted(got)}")
    colours = {}
    for name, want, words in (('Input', want_in, 246), ('Output', want_out, 182)):
        used = sum(size for *_, size in want)
        expect(got[name]['title'].endswith(f"({words} words): {used} of 360 slave bytes used"),
               f"{name}: title {got[name]['title']!r}")
        for mac, c in check_image(name, got[name], 360, want).items():
            colours.setdefault(mac, set()).update(c)
    lines = legend(root)
    expect([t.split(' ')[1] for _, t in lines] == [str(mac) for mac, _ in nodes], f"legend order {lines}")
    for (swatch, text), (mac, node) in zip(lines, nodes):
        expect(text.startswith(f"MAC {mac} {node}"), f"legend line {text!r}")
        # A node's boxes, in both images, have its legend colour.
        expect(colours.get(mac, {swatch}) == {swatch}, f"MAC {mac}: boxes {colours.get(mac)}, legend {swatch}")


def main():
    edsc, project = sys.argv[1], pathlib.Path(sys.argv[2])
    # The thesis network, dword alignment from DWord 0 (docs/network.md):
    # inputs RightSight 3 bytes at 0, temperature 1 at 4, discrete 3 at 8,
    # level 1 at 12, PanelView 12 at 16; output PanelView 8 at 0.
    check_network(edsc, project / 'eds' / 'networks' / 'thesis.toml',
                  [(2, 'rightsight', 0, 3), (8, 'temperature', 4, 1), (9, 'discrete', 8, 3), (10, 'level', 12, 1),
                   (12, 'panelview', 16, 12)],
                  [(12, 'panelview', 0, 8)],
                  [(2, 'rightsight'), (8, 'temperature'), (9, 'discrete'), (10, 'level'), (12, 'panelview')])
    # Word alignment. wide is fixed at DWord 7 (bytes 28-35, across the end
    # of row 0); a (5) at 0-4, b (3) from the even 6: 6-8, c (30) from 10
    # would hit wide at 28, so after it at 36-65 (row 1 and into row 2).
    # Output: b 2 bytes at 0, c 1 at 2.
    with tempfile.TemporaryDirectory() as tmp:
        net = pathlib.Path(tmp) / 'wrap.toml'
        node = '[[node]]\nmac = {}\nname = "{}"\nconnections = [{{ type = "poll", input = {}, output = {} }}]\n{}\n'
        net.write_text('[network]\nkind = "devicenet"\nbaud = 125\n\n[scanner]\nprofile = "1769-SDN"\nmac = 0\n'
                       'alignment = "word"\n\n' + node.format(3, 'a', 5, 0, '') + node.format(4, 'b', 3, 2, '') +
                       node.format(5, 'c', 30, 1, '') + node.format(7, 'wide', 8, 0, 'input_dword = 7'))
        check_network(edsc, net, [(3, 'a', 0, 5), (4, 'b', 6, 3), (7, 'wide', 28, 8), (5, 'c', 36, 30)],
                      [(4, 'b', 0, 2), (5, 'c', 2, 1)], [(3, 'a'), (4, 'b'), (5, 'c'), (7, 'wide')])
    for f in FAILURES:
        print('FAIL', f)
    print(f"{len(FAILURES)} failures")
    return 1 if FAILURES else 0


if __name__ == '__main__':
    sys.exit(main())
