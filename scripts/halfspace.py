#!/usr/bin/python3
"""Half-space reference of the wheel-rail contact patch (Kalker's exact theory).

Command-line entry point; the code is scripts/wheelrail_post/halfspace_cli.py (run --help).
"""
import sys

from wheelrail_post.halfspace_cli import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
