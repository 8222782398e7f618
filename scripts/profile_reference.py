#!/usr/bin/python3
"""The half-space reference of a profile run (Geometry/Profiles) and its FE
contact patch against it: area, length, width, p_max, F_x / F_N, slip area.

Command-line entry point; the code is scripts/wheelrail_post/profile_reference.py
and profile_compare.py (run --help).
"""
import sys

from wheelrail_post.profile_compare import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
