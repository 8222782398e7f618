#!/usr/bin/python3
"""Lateral creep force and spin moment of profile cases against the half-space reference.

Command-line entry point; the code is scripts/wheelrail_post/creep_study.py (run --help).
"""
from wheelrail_post.creep_study import main

if __name__ == "__main__":
    main()
