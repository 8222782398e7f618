#!/usr/bin/python3
"""Plots and a report page from a wheelrail run's output directory.

Command-line entry point; the code is scripts/wheelrail_post/plots.py (run --help).
"""
from wheelrail_post.plots import main

if __name__ == "__main__":
    main()
