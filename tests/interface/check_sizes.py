#!/usr/bin/env python3
"""The sources' file and function sizes (the driver's C++ and the core's Fortran).

check_sizes.py DIR: no .cpp/.hpp/.h/.f90 file in DIR is over MAX_FILE_LINES lines and no
function body over MAX_FUNCTION_LINES lines (C++: from the line of its opening brace to the
line of its closing one; Fortran: from `subroutine`/`function` to its `end`, a contained
procedure counted on its own and inside its host), except those named in EXCEPTIONS with
their reason. Prints each
one over (file:line, the function, its length) and exits 1; an exception that no longer
applies (its function is gone or short now) is reported too, so that the list stays true.
check_sizes.py --self-test: runs the scan on a small file with one long function, one short
one, a long class and a long brace initialiser, and fails unless exactly the long function
is found.
check_sizes.py --list DRIVER_DIR: prints every function with its length, longest first.

The scan counts braces after removing comments, string and character literals: a body is a
`{` whose text before it (back to the last `;`, `{` or `}`) ends with `)` and optional
qualifiers and is not a namespace, class, struct, enum, union, initialiser or control
statement; lambdas and local classes count towards the function around them.
"""
import pathlib
import re
import sys
import tempfile

MAX_FILE_LINES = 800
MAX_FUNCTION_LINES = 150

# "relative/path.cpp:function": the reason it stays longer.
EXCEPTIONS = {
}

TOKENS = re.compile(r'//[^\n]*|/\*.*?\*/|R"([^(\s]*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|'
                    r"'(?:\\.|[^'\\\n])*'", re.S)
NOT_A_BODY = re.compile(r'\b(namespace|class|struct|enum|union|if|for|while|switch|catch|do|'
                        r'else|try)\b|=\s*$|\breturn\b')
QUALIFIERS = re.compile(r'\)\s*(const|noexcept|override|final|mutable|&|&&|\s)*'
                        r'(->\s*[\w:<>,\s*&]+)?\s*$')
NAME = re.compile(r'([~\w:]+(?:operator\s*\S+)?)\s*\(')


def strip(text):
    """Comments and literals as spaces, the newlines kept (line numbers stay)."""
    return TOKENS.sub(lambda m: re.sub(r'[^\n]', ' ', m.group(0)), text)


def functions(text):
    """(name, first line, line count) of each outermost function body in text."""
    code = strip(text)
    found = []
    stack = []  # for each open brace: True where it opens an outermost function body
    start = 0   # where the text before the next brace begins
    in_body = 0
    for i, ch in enumerate(code):
        if ch == ';':
            start = i + 1
        elif ch == '{':
            head = code[start:i]
            body = (in_body == 0 and QUALIFIERS.search(head) is not None and
                    NOT_A_BODY.search(head.split('(')[0] if '(' in head else head) is None and
                    not head.rstrip().endswith('=') and '(' in head)
            if body:
                # the head's name: the last identifier before the first '(' at depth 0
                names = NAME.findall(head)
                stack.append((True, names[0] if names else '?', code.count('\n', 0, i) + 1))
                in_body += 1
            else:
                stack.append((False, '', 0))
                if in_body:
                    in_body += 1
            start = i + 1
        elif ch == '}':
            if stack:
                is_fn, name, line = stack.pop()
                if is_fn:
                    end = code.count('\n', 0, i) + 1
                    found.append((name, line, end - line + 1))
                    in_body = 0
                elif in_body:
                    in_body -= 1
            start = i + 1
    return found


F_START = re.compile(r'^\s*(?:(?:pure|elemental|impure|recursive|module|non_recursive)\s+|'
                     r'(?:integer|real|logical|complex|character|type)\s*(?:\([^)]*\))?\s+)*'
                     r'(subroutine|function)\s+(\w+)', re.I)
F_END = re.compile(r'^\s*end\s+(subroutine|function)\b', re.I)


def fortran_procedures(text):
    """(name, first line, line count) of each subroutine and function in Fortran text."""
    found, stack = [], []
    for number, raw in enumerate(text.split('\n'), start=1):
        line = raw.split('!', 1)[0]
        if F_END.match(line):
            if stack:
                name, first = stack.pop()
                found.append((name, first, number - first + 1))
        elif (m := F_START.match(line)) is not None:
            stack.append((m.group(2), number))
    return found


def scan(driver):
    """([(relative path, line, what, length, limit)], every function) of the tree."""
    over, every = [], []
    for path in sorted(driver.rglob('*')):
        if path.suffix not in ('.cpp', '.hpp', '.h', '.f90') or not path.is_file():
            continue
        rel = path.relative_to(driver).as_posix()
        text = path.read_text()
        lines = text.count('\n')
        if lines > MAX_FILE_LINES:
            over.append((rel, 1, '(the file)', lines, MAX_FILE_LINES))
        procs = fortran_procedures(text) if path.suffix == '.f90' else functions(text)
        for name, line, length in procs:
            every.append((rel, line, name, length))
            if length > MAX_FUNCTION_LINES:
                over.append((rel, line, name, length, MAX_FUNCTION_LINES))
    return over, every


def check(driver):
    over, _ = scan(driver)
    problems = []
    used = set()
    for rel, line, name, length, limit in over:
        key = f'{rel}:{name}'
        if key in EXCEPTIONS:
            used.add(key)
            continue
        problems.append(f'{driver / rel}:{line}: {name} is {length} lines (at most {limit}); '
                        f'split it, or name it in EXCEPTIONS of {pathlib.Path(__file__).name} '
                        f'with the reason')
    for key in sorted(set(EXCEPTIONS) - used):
        problems.append(f'{key} is listed in EXCEPTIONS but is no longer over its limit: '
                        f'remove it from the list')
    return problems


def self_test():
    long_fn = 'int long_one(int a) {\n' + '    a += 1;\n' * 160 + '    return a;\n}\n'
    short_fn = 'double Short::value() const noexcept {\n    if (x) { return 1; }\n    return 0;\n}\n'
    long_class = 'struct Big {\n' + '    int m;\n' * 200 + '};\n'
    long_init = 'const int table[] = {\n' + '    1,\n' * 200 + '};\n'
    text = ('// a comment with a brace {\nnamespace n {\n' + long_class + long_init + short_fn +
            'const char* s = "}{";\n' + long_fn + '}  // namespace n\n')
    long_sub = ('  pure subroutine long_sub(a)  ! a comment: end subroutine\n' +
                '    a = a + 1\n' * 160 + '  end subroutine long_sub\n')
    short_fn = ('  real(rp) function short_f(x) result(y)\n    y = x\n  end function short_f\n')
    fortran = 'module m\ncontains\n' + short_fn + long_sub + 'end module m\n'
    with tempfile.TemporaryDirectory() as tmp:
        d = pathlib.Path(tmp)
        (d / 'a.cpp').write_text(text)
        (d / 'b.f90').write_text(fortran)
        over, every = scan(d)
        names = {name: length for _, _, name, length in every}
        ok = ([o[2] for o in over] == ['long_one', 'long_sub'] and names.get('long_one') == 163 and
              names.get('Short::value') == 4 and names.get('long_sub') == 162 and
              names.get('short_f') == 3 and len(every) == 4)
        if not ok:
            print(f'self-test failed: over {over}, functions {every}')
            return 1
    print('self-test passed: the long C++ function and Fortran subroutine are found, the class, '
          'initialiser and short functions are not')
    return 0


def main(argv):
    if argv[1:] == ['--self-test']:
        return self_test()
    if len(argv) == 3 and argv[1] == '--list':
        _, every = scan(pathlib.Path(argv[2]))
        for rel, line, name, length in sorted(every, key=lambda e: -e[3]):
            print(f'{length:5d}  {rel}:{line}  {name}')
        return 0
    if len(argv) != 2:
        print(__doc__)
        return 2
    driver = pathlib.Path(argv[1])
    problems = check(driver)
    for p in problems:
        print(p)
    if problems:
        return 1
    _, every = scan(driver)
    print(f'{len(every)} functions in {driver}: none over {MAX_FUNCTION_LINES} lines, '
          f'no file over {MAX_FILE_LINES} lines (exceptions: {len(EXCEPTIONS)})')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
