#!/usr/bin/python3
"""Run a traction sweep of wheelrail cases and plot it (paper Figs. 14, 15).

Command-line entry point; the code is scripts/wheelrail_post/sweep.py (run --help).
"""
from wheelrail_post.sweep import main

if __name__ == "__main__":
    main()
