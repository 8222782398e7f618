#!/usr/bin/python3
"""Print doc/parameters.md, the parameter reference (Markdown), from `wheelrail --help`.

Usage: build/wheelrail --help | doc/parameter_table.py > doc/parameters.md
tests/input/parameters_doc_01.sh checks that doc/parameters.md is this output.
"""
import re
import sys

path, comment, rows = [], [], []
for line in sys.stdin.read().split('\n'):
    s = line.strip()
    if s.startswith('subsection '):
        path.append(s[len('subsection '):])
        comment = []
    elif s == 'end':
        path.pop()
        comment = []
    elif s.startswith('#'):
        if path:
            comment.append(s[1:].strip())
    elif s.startswith('set '):
        m = re.match(r'set (.*?)\s*= ?(.*)$', s)
        rows.append(('/'.join(path), m.group(1), m.group(2), ' '.join(comment)))
        comment = []
    elif not s:
        comment = []

print("""# Parameter reference

Every entry, with unit, default and allowed range (also printed by `build/wheelrail --help`;
this table is made by `build/wheelrail --help | doc/parameter_table.py > doc/parameters.md`).
Values outside the range, misspelt entries, unknown subsections, malformed numbers and missing
include files stop the run with a message naming the entry and a non-zero exit status.
""")
current = None
for section, name, value, text in rows:
    if section != current:
        print(f"\n**{section}**\n\n| parameter | default | meaning (unit, range) |\n|---|---|---|")
        current = section
    print(f"| {name} | `{value}` | {text.replace('|', '/')} |")
