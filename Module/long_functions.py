#!/usr/bin/env python3
"""Lists the C++ functions longer than N lines, longest first (issue 15: none over ~150 lines in
production code). Usage: Module/long_functions.py N FILE... ; for example
    Module/long_functions.py 150 $(git ls-files '*.cxx' '*.h')

Crude on purpose, and good enough for this code base: comments and string literals are blanked,
braces are counted, and a '{' whose preceding text has a ')' and is not a control statement,
class, namespace or initializer opens a function; lambdas and blocks inside a function count as
part of it. A function's length runs from the line of its '{' to the line of its '}'."""
import re, sys
def strip(src):
    src = re.sub(r'//[^\n]*', '', src)
    src = re.sub(r'/\*.*?\*/', lambda m: '\n'*m.group(0).count('\n'), src, flags=re.S)
    src = re.sub(r'R"(\w*)\((.*?)\)\1"', lambda m: '""'+'\n'*m.group(0).count('\n'), src, flags=re.S)
    src = re.sub(r'"(\\.|[^"\\\n])*"', '""', src)
    src = re.sub(r"'(\\.|[^'\\\n])*'", "''", src)
    return src
def funcs(path):
    s = strip(open(path, errors='replace').read())
    out = []; stack = []; line = 1; last = 0
    for i, c in enumerate(s):
        if c == '\n': line += 1
        elif c == '{':
            head = s[last:i]
            h = ' '.join(head.split())
            kind = 'block'
            if re.search(r'\b(namespace|class|struct|enum|union)\b[^()]*$', h) or h.endswith('='):
                kind = 'scope'
            elif ')' in h and not re.search(r'\b(if|for|while|switch|catch|do)\s*\(', h.split(';')[-1]) and not any(k == 'func' or k == 'lambda' for k, *_ in stack):
                kind = 'func'
            name = h.split(';')[-1].strip()[-120:]
            stack.append((kind, line, name)); last = i + 1
        elif c == '}':
            if stack:
                kind, start, name = stack.pop()
                if kind == 'func': out.append((line - start + 1, start, name))
            last = i + 1
        elif c == ';':
            pass
    return out
N = int(sys.argv[1]); files = sys.argv[2:]
res = []
for f in files:
    for n, start, name in funcs(f): res.append((n, f, start, name))
res.sort(reverse=True)
for n, f, start, name in res:
    if n > N:
        m = re.findall(r'([~A-Za-z_:0-9]+)\s*\(', name)
        print("%5d %s:%d %s" % (n, f, start, m[0] if m else name[:60]))
