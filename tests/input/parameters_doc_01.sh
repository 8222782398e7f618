#!/usr/bin/env bash
# doc/parameters.md is what `wheelrail --help | doc/parameter_table.py` prints:
# a parameter declared, renamed or given another default, range or text
# without the reference regenerated fails here (the diff is printed).
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
"$exe" --help | /usr/bin/python3 "$src/doc/parameter_table.py" > parameters.md
if ! diff -u "$src/doc/parameters.md" parameters.md; then
  echo "FAILED: doc/parameters.md is out of date: build/wheelrail --help | doc/parameter_table.py > doc/parameters.md"
  exit 1
fi
echo "doc/parameters.md: $(grep -c '^| ' parameters.md) table rows, the same as --help gives"
