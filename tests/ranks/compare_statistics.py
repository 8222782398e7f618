#!/usr/bin/env python3
"""Compare the statistics of one case run on 1 and on N MPI ranks.

usage: compare_statistics.py ONE_RANK/statistics N_RANKS/statistics

What holds between rank counts: the static start's CG and its AMG
preconditioner depend on the partition, so the two runs start from states
that differ within the static solve's tolerances. The discrete problem is
symmetric in y, and the static solve lands on one of two equilibria that are
mirror images of each other (a lateral force of about 1e-7 F_N, of either
sign), whichever the round-off picks; the explicit run then follows that
state or its mirror image. So every column agrees to RELATIVE of the
column's largest magnitude, except that the lateral columns (F_lateral,
trailing slip rate y) may all carry the opposite sign: they agree to
RELATIVE of their largest magnitude after multiplying the second run's by
the same sign s = +1 or -1 on every row. The energy balance is round-off of
the total energy: balance [J] to RELATIVE of the largest energy, balance
error [-] to RELATIVE.
The integer columns (step, contact nodes, slip nodes) must be equal.
Prints, per column, the largest difference in the unit of its criterion, and
exits with 1 if any column fails.
"""
import re
import sys

RELATIVE = 1e-6

LATERAL_FORCE = "F_lateral [N]"
LATERAL_SLIP = "trailing slip rate y [m/s]"
INTEGERS = ("step", "contact nodes", "slip nodes")
ENERGIES = ("kinetic [J]", "internal [J]", "hourglass [J]", "damping dissipation [J]",
            "contact energy [J]", "friction dissipation [J]")


def read(path):
    names, rows = [], []
    with open(path) as f:
        for line in f:
            m = re.match(r"#\s*(\d+):\s*(.*\S)\s*$", line)
            if m:
                names.append(m.group(2))
            elif line.strip() and not line.startswith("#"):
                rows.append([float(x) for x in line.split()])
    if not rows or any(len(r) != len(names) for r in rows):
        sys.exit("%s: no rows, or rows that do not match the %d columns" % (path, len(names)))
    return names, rows


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    names, a = read(sys.argv[1])
    names_b, b = read(sys.argv[2])
    if names != names_b:
        sys.exit("the files have different columns")
    if len(a) != len(b):
        sys.exit("the files have %d and %d rows" % (len(a), len(b)))
    col = {n: i for i, n in enumerate(names)}

    def column(name, rows):
        return [r[col[name]] for r in rows]

    def largest(name):
        return max(max(abs(x) for x in column(name, a)), max(abs(x) for x in column(name, b)))

    energy_scale = max(largest(n) for n in ENERGIES if n in col)
    # the mirror image or not: the sign of the second run's lateral force
    # where the first run's is largest
    fa, fb = column(LATERAL_FORCE, a), column(LATERAL_FORCE, b)
    k = max(range(len(fa)), key=lambda i: abs(fa[i]))
    sign = -1 if fa[k] * fb[k] < 0 else 1
    print("lateral columns: the second run %s" %
          ("is the mirror image of the first (y -> -y)" if sign < 0 else "has the same sign"))
    failed = False
    print("%d rows, %d columns; relative tolerance %g" % (len(a), len(names), RELATIVE))
    for name in names:
        x, y = column(name, a), column(name, b)
        if name in INTEGERS:
            worst = max(abs(p - q) for p, q in zip(x, y))
            ok = worst == 0
            what = "largest difference %d" % worst
        elif name in (LATERAL_FORCE, LATERAL_SLIP):
            worst = max(abs(p - sign * q) for p, q in zip(x, y)) / max(largest(name), 1e-300)
            ok = worst <= RELATIVE
            what = "largest relative difference %.1e (second run x %+d)" % (worst, sign)
        else:
            scale = energy_scale if name == "balance [J]" else \
                1. if name == "balance error [-]" else max(largest(name), 1e-300)
            worst = max(abs(p - q) for p, q in zip(x, y)) / scale
            ok = worst <= RELATIVE
            what = "largest relative difference %.1e" % worst
        failed |= not ok
        print("  %-28s %s%s" % (name, what, "" if ok else "  FAILED"))
    print("FAILED" if failed else "all columns within their tolerances")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
