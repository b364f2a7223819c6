#!/usr/bin/env python3
"""Largest difference of the friction factors (and of the tangential
amplitudes, relative to the largest) between two dumps of the local output
of fix acoustic/mindlin (columns: atom IDs i and j, U_t, mu*/mu), contact by
contact.  Usage: factors_diff.py REFERENCE OTHER"""
import sys

import numpy as np


def contacts(path):
    lines = open(path).read().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ENTRIES")) + 1
    end = next((k for k in range(start, len(lines)) if lines[k].startswith("ITEM:")), len(lines))
    rows = np.array([line.split() for line in lines[start:end]], dtype=float)
    return {(int(min(r[0], r[1])), int(max(r[0], r[1]))): (r[2], r[3]) for r in rows}


def main():
    reference, other = contacts(sys.argv[1]), contacts(sys.argv[2])
    common = sorted(set(reference) & set(other))
    ut = np.array([[reference[k][0], other[k][0]] for k in common])
    s = np.array([[reference[k][1], other[k][1]] for k in common])
    print(f"{len(common)} contacts in both ({len(reference)}, {len(other)}): "
          f"max |d(mu*/mu)| = {np.abs(s[:, 0] - s[:, 1]).max():.3g}, "
          f"max |dU_t| / max U_t = {np.abs(ut[:, 0] - ut[:, 1]).max() / ut[:, 0].max():.3g}")


if __name__ == "__main__":
    main()
