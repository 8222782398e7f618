#!/usr/bin/python3
"""Creep-force table of a wheelrail case: F_x / F_N against the longitudinal creepage.

Command-line entry point; the code is scripts/wheelrail_post/creep_curve.py (run --help).
"""
from wheelrail_post.creep_curve import main

if __name__ == "__main__":
    main()
