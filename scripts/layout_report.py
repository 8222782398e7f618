#!/usr/bin/python3
"""The code layout: every C++ file with its line count and largest function.

Command-line entry point; the code is scripts/wheelrail_post/layout_report.py (run --help).
"""
import sys

from wheelrail_post.layout_report import main

if __name__ == "__main__":
    sys.exit(main())
