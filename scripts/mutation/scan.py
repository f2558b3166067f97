"""Where a mutant may go, and the mutants of a file.

C++ (.cpp, .hpp): operators on code only (not comments, strings or
preprocessor lines). Generated text: the string literals of the files the
project config names (the C and CMake an emitter writes) and the header
templates (.mustache) get the same kind of operators inside the text they
generate, so what they change is the generated program, not the emitter.
"""
import hashlib
import re

SWAPS = {'<': '<=', '<=': '<', '>': '>=', '>=': '>', '==': '!=', '!=': '==', '&&': '||', '||': '&&'}


class Mutant:
    def __init__(self, path, text, start, end, replacement, op, kind='code'):
        self.path = path  # relative to the project root
        self.start, self.end = start, end
        self.original = text[start:end]
        self.replacement = replacement
        self.op = op
        self.kind = kind  # 'code', or 'generated': inside text the program writes out
        self.line = text.count('\n', 0, start) + 1
        self.column = start - (text.rfind('\n', 0, start) + 1) + 1
        # Stable while the rest of the file changes: the line's text, the
        # column, and how many identical lines come before it.
        line_text = context_line(text, start)
        earlier = text.count('\n' + line_text + '\n', 0, start)
        key = f"{path}|{op}|{line_text}|{self.column}|{replacement}|{earlier}"
        self.id = hashlib.sha1(key.encode()).hexdigest()[:10]

    def describe(self):
        return f"{self.path}:{self.line}:{self.column} {self.op}: `{self.original}` -> `{self.replacement}`"

    def apply(self, text):
        return text[:self.start] + self.replacement + text[self.end:]


def context_line(text, at):
    a = text.rfind('\n', 0, at) + 1
    b = text.find('\n', at)
    return text[a:b if b >= 0 else len(text)]


def _blank(mask, a, b):
    for k in range(a, b):
        mask[k] = False


def cpp_scan(text):
    """(mask, literals): mask[i] is True where text[i] is C++ code (not a
    comment, a string or char literal, or a preprocessor line); literals are
    the string literals as (content start, content end, raw delimiter or None)."""
    mask = [True] * len(text)
    literals = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == '#':
            j = text.find('\n', i)
            j = n if j < 0 else j
            _blank(mask, i, j)
            i = j
            continue
        if c == '\n':
            line_start = True
            i += 1
            continue
        if not c.isspace():
            line_start = False
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            _blank(mask, i, j)
            i = j
            continue
        if text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            _blank(mask, i, j)
            i = j
            continue
        m = re.match(r'R"([^(\s]*)\(', text[i:i + 20]) if c == 'R' and (i == 0 or not text[i - 1].isalnum()) else None
        if m:
            end = text.find(')' + m.group(1) + '"', i)
            j = n if end < 0 else end + len(m.group(1)) + 2
            literals.append((i + m.end(), n if end < 0 else end, m.group(1)))
            _blank(mask, i, j)
            i = j
            continue
        if c in '"\'':
            # A digit separator (1'000) is not a char literal.
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == '\\' else 1
            if c == '"':
                literals.append((i + 1, min(j, n), None))
            j = min(j + 1, n)
            _blank(mask, i, j)
            i = j
            continue
        i += 1
    return mask, literals


def in_mask(mask, start, end):
    return all(mask[start:end])


# ---- operators

def _binary_ops(text, add, prefix=''):
    # Binary operators written with a space on each side (the project's
    # style, and the generated code's), so template brackets, ->, << and T&&
    # stay out.
    for m in re.finditer(r'(?<=\s)(<=|>=|==|!=|&&|\|\||<|>)(?=\s)', text):
        op = m.group(1)
        kind = 'eq' if op in ('==', '!=') else 'logic' if op in ('&&', '||') else 'rel-boundary'
        add(m.start(1), m.end(1), SWAPS[op], prefix + kind)


def _negations(text, add, prefix=''):
    # Unary minus: after an operator, a comma, an opening bracket or `return`.
    for m in re.finditer(r'(?:[=(,?:]|\breturn)\s*(-)(?=[\w(])', text):
        add(m.start(1), m.end(1), '', prefix + 'drop-neg')
    for m in re.finditer(r'!(?!=)(?=[\w(*])', text):
        add(m.start(), m.end(), '', prefix + 'drop-neg')


def _constants(text, add, prefix=''):
    for m in re.finditer(r'(?<![\w.])(\d+)(?:[uU]|[uU]?[lL]{1,2}|[lL]{1,2}[uU])?(?![\w.\'])', text):
        value = int(m.group(1))
        if m.group(1).startswith('0') and value != 0:
            continue  # octal-looking: leave it
        add(m.start(1), m.end(1), str(value + 1), prefix + 'const')
        if value > 0:
            add(m.start(1), m.end(1), str(value - 1), prefix + 'const')
    # Hexadecimal, in its own width and case (a CIP code, a status, a mask).
    for m in re.finditer(r'(?<![\w.])0([xX])([0-9a-fA-F]+)(?:[uU]|[uU]?[lL]{1,2})?(?![\w.\'])', text):
        digits = m.group(2)
        value = int(digits, 16)
        upper = not re.search('[a-f]', digits)
        for v in (value + 1, value - 1):
            if v < 0:
                continue
            s = f"{v:0{len(digits)}X}" if upper else f"{v:0{len(digits)}x}"
            add(m.start(), m.start() + 2 + len(digits), f"0{m.group(1)}{s}", prefix + 'const')


def code_mutants(path, text):
    mask, _ = cpp_scan(text)
    out = []

    def add(start, end, replacement, op):
        if in_mask(mask, start, end):
            out.append(Mutant(path, text, start, end, replacement, op))

    _binary_ops(text, add)
    for m in re.finditer(r'\bwhile \(', text):
        # Not the `while` of a do-while.
        before = text[:m.start()].rstrip()
        if before.endswith('}') and re.search(r'\bdo\s*\{[^{}]*\}$', before[-400:]):
            continue
        add(m.start(), m.start() + 5, 'if', 'while-if')
    _negations(text, add)
    _constants(text, add)
    for m in re.finditer(r'\bif \([^\n]*\) (continue;|return[^;\n]*;)', text):
        add(m.start(1), m.end(1), '{}', 'drop-guard')
    for m in re.finditer(r'\b\w+\(([A-Za-z_]\w*), ([A-Za-z_]\w*)\)', text):
        a, b = m.group(1), m.group(2)
        if a != b:
            add(m.start(1), m.end(2), f'{b}, {a}', 'swap-args')
    return out


# ---- generated text: C (and header templates) and CMake

def _c_text_mask(text, start, end, mask, escapes):
    """Marks as mutable the generated C in text[start:end], leaving out its
    comments, string and char literals, #include lines, mustache tags and,
    inside an ordinary C++ literal, escape sequences and fmt fields."""
    i = start
    line_start = True
    while i < end:
        c = text[i]
        if escapes and c == '\\':
            i += 2
            continue
        if line_start and text.startswith('#include', i):
            j = text.find('\n', i, end)
            i = end if j < 0 else j
            continue
        line_start = c == '\n' or (line_start and c in ' \t')
        if text.startswith('/*', i):
            j = text.find('*/', i + 2, end)
            i = end if j < 0 else j + 2
            continue
        if text.startswith('//', i):
            j = text.find('\n', i, end)
            i = end if j < 0 else j
            continue
        if text.startswith('{{', i):
            j = text.find('}}', i, end)
            i = end if j < 0 else j + 2
            continue
        if escapes and c == '{':
            j = text.find('}', i, end)
            i = end if j < 0 else j + 1
            continue
        if c in '"\'':
            j = i + 1
            while j < end and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            i = min(j + 1, end)
            continue
        mask[i] = True
        i += 1


def _cmake_text_mask(text, start, end, mask):
    i = start
    while i < end:
        c = text[i]
        if c == '#':
            j = text.find('\n', i, end)
            i = end if j < 0 else j
            continue
        if c == '"':
            j = i + 1
            while j < end and text[j] != '"':
                j += 2 if text[j] == '\\' else 1
            i = min(j + 1, end)
            continue
        mask[i] = True
        i += 1


CMAKE_WORDS = re.compile(r'^\s*(cmake_minimum_required|project|set|if|include|add_subdirectory|option|target_\w+|'
                         r'set_property|include_directories)\(', re.M)


def is_cmake(text, start, end, delimiter):
    body = text[start:end]
    return (delimiter or '').lower() == 'cmake' or bool(CMAKE_WORDS.search(body)) or body.lstrip().startswith('# ')


def generated_mutants(path, text, spans):
    """Mutants inside generated text: spans are (start, end, language, escapes)
    with language 'c' or 'cmake'."""
    c_mask, cmake_mask = [False] * len(text), [False] * len(text)
    for start, end, language, escapes in spans:
        if language == 'cmake':
            _cmake_text_mask(text, start, end, cmake_mask)
        else:
            _c_text_mask(text, start, end, c_mask, escapes)
    either = [a or b for a, b in zip(c_mask, cmake_mask)]
    out = []

    def adder(mask):
        def add(start, end, replacement, op):
            if in_mask(mask, start, end) and '\n' not in text[start:end]:
                out.append(Mutant(path, text, start, end, replacement, op, kind='generated'))
        return add

    _binary_ops(text, adder(c_mask), 'gen-')
    _negations(text, adder(c_mask), 'gen-')
    _constants(text, adder(either), 'gen-')
    # CMake's words (and a C literal that becomes one): a dropped NOT, ON and
    # OFF swapped, AND and OR swapped.
    for m in re.finditer(r'\bNOT ', text):
        adder(cmake_mask)(m.start(), m.end(), '', 'gen-drop-not')
    for m in re.finditer(r'\b(ON|OFF|AND|OR)\b', text):
        other = {'ON': 'OFF', 'OFF': 'ON', 'AND': 'OR', 'OR': 'AND'}[m.group(1)]
        adder(either)(m.start(), m.end(), other, 'gen-word')
    return out


def literal_spans(text):
    """The string literals of a C++ file as generated-text spans."""
    _, literals = cpp_scan(text)
    spans = []
    for start, end, delimiter in literals:
        language = 'cmake' if is_cmake(text, start, end, delimiter) else 'c'
        spans.append((start, end, language, delimiter is None))
    return spans


def mutants_of(path, text, generated_literals=False, template=False):
    """Every mutant of one file: its code's (C++ sources and headers), the
    text its string literals generate (when the config names the file), or
    the whole file as generated C (a header template)."""
    if template:
        out = generated_mutants(path, text, [(0, len(text), 'c', False)])
    else:
        out = code_mutants(path, text)
        if generated_literals:
            out += generated_mutants(path, text, literal_spans(text))
    unique = {m.id: m for m in out}
    return sorted(unique.values(), key=lambda x: (x.start, x.op, x.replacement))
