#!/usr/bin/python3
"""Velocity-dependent friction: convergence and comparison with exact theory.

Command-line entry point; the code is scripts/wheelrail_post/friction_study.py (run --help).
"""
from wheelrail_post.friction_study import main

if __name__ == "__main__":
    main()
