#!/usr/bin/python3
"""Rigid contact points of a wheel profile on a rail profile (default: S1002 on
60E1 inclined 1:40 at y_w = 0, 3, 6 mm), their contact angle, rolling radius and
gap curvatures; optionally a figure (--png).

Command-line entry point; the code is scripts/wheelrail_post/profiles.py (run --help).
"""
import sys

from wheelrail_post.profiles import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
