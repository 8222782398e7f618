#!/usr/bin/python3
"""The standard profiles (S1002 wheel, 60E1 rail) and the paper's idealised pair
as point files in mesh/profiles/, from their geometric definitions; --check
verifies the definitions' characteristic dimensions and the files.

Command-line entry point; the code is scripts/wheelrail_post/standard_profiles.py (run --help).
"""
import sys

from wheelrail_post.standard_profiles import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
