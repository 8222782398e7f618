#!/usr/bin/python3
"""Mesh and time-step convergence of a rolling case against exact theory.

Command-line entry point; the code is scripts/wheelrail_post/convergence_study.py (run --help).
"""
from wheelrail_post.convergence_study import main

if __name__ == "__main__":
    main()
