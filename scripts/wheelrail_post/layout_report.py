"""The code layout as a table: every C++ file under source/, include/ and
tests/ with its line count and its largest function (name and lines).

    scripts/layout_report.py [--markdown] [--limit N]

Functions are found in the layout .clang-format gives them: a definition's
opening brace on a line of its own at the indentation of the function's name
(control statements indent their braces further). Files over --limit lines
(default 600) are marked.
"""
import argparse
import os
import re

from . import SCRIPTS_DIR

TOP = os.path.dirname(SCRIPTS_DIR)
NOT_FUNCTIONS = re.compile(r"^(class|struct|union|enum|namespace|extern|template\s*<[^>]*>\s*(class|struct))\b")
NAME = re.compile(r"([A-Za-z_][A-Za-z_0-9]*(::[A-Za-z_~][A-Za-z_0-9]*)*(<[^()]*>)?)\s*\(")


def indent(line):
    return len(line) - len(line.lstrip(" "))


def functions(lines):
    """(name, first line, number of lines) of each function definition."""
    found = []
    for i, line in enumerate(lines):
        if line.strip() != "{":
            continue
        level = indent(line)
        # walk back over the signature to its first line at this indentation
        j = i - 1
        while j >= 0 and (not lines[j].strip() or indent(lines[j]) > level):
            j -= 1
        if j < 0 or indent(lines[j]) != level:
            continue
        head = lines[j].strip()
        if NOT_FUNCTIONS.match(head) or head.startswith(("//", "/*", "*", "#", "}")):
            continue
        # the return type may stand on the line before the name
        signature = " ".join(l.strip() for l in lines[j:i])
        match = NAME.search(signature)
        if not match or match.group(1) in ("if", "for", "while", "switch", "catch"):
            continue
        depth, k = 0, i
        while k < len(lines):
            depth += lines[k].count("{") - lines[k].count("}")
            if depth == 0:
                break
            k += 1
        first = j - 1 if j > 0 and indent(lines[j - 1]) == level and lines[j - 1].strip() \
            and not lines[j - 1].strip().endswith((";", "}", "*/")) else j
        found.append((match.group(1), first + 1, k - first + 1))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--markdown", action="store_true", help="a Markdown table")
    parser.add_argument("--limit", type=int, default=600, help="mark files longer than this")
    args = parser.parse_args()
    rows = []
    for folder in ("include", "source", "tests"):
        for root, _, files in sorted(os.walk(os.path.join(TOP, folder))):
            for f in sorted(files):
                if not f.endswith((".cc", ".h")):
                    continue
                path = os.path.join(root, f)
                with open(path, encoding="utf-8") as stream:
                    lines = stream.read().split("\n")
                n = len(lines) - 1
                fs = functions(lines)
                largest = max(fs, key=lambda x: x[2]) if fs else ("-", 0, 0)
                rows.append((os.path.relpath(path, TOP), n, largest[0], largest[2]))
    total = sum(r[1] for r in rows)
    if args.markdown:
        print("| file | lines | largest function (lines) |")
        print("|---|---:|---|")
        for path, n, name, length in rows:
            mark = " **over %d**" % args.limit if n > args.limit else ""
            print("| `%s` | %d%s | `%s` (%d) |" % (path, n, mark, name, length))
        print("| total (%d files) | %d | |" % (len(rows), total))
    else:
        width = max(len(r[0]) for r in rows)
        for path, n, name, length in rows:
            mark = "  > %d" % args.limit if n > args.limit else ""
            print("%-*s %6d  %s (%d)%s" % (width, path, n, name, length, mark))
        print("%-*s %6d  (%d files)" % (width, "total", total, len(rows)))
    return 0

