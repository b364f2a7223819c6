#!/usr/bin/python3
"""Collect the cavity runs of run_scan.sh into the tables and figures of RESULTS.md.

    /usr/bin/python3 examples/cavity/collect.py [OUT_DIR] [FIG_DIR]

OUT_DIR (default examples/cavity/out) holds <set>/<tag>/ run directories
(scan, paper, size, us), each with cavity.params, cavity.wall.txt,
cavity.contacts, cavity.flow and log.lammps.  For every run: I_M, mean force
F/(PLd), vortex centre ell/L, solid fraction Phi* (3D-equivalent), the
autocorrelation times of the wall force (Eq. 6) and the truncated log-normal
fits (Eq. 7) at three scales.  Prints markdown tables, writes
OUT_DIR/summary.json and the PNG figures of paper 004 Figs. 3, 9, 10, 12, 13,
14 and Phi*(I_M) (acoustic_tools.cavity_collect).
"""
import os
import sys

from acoustic_tools.cavity_collect import collect

here = os.path.dirname(os.path.abspath(__file__))


def main(top=os.path.join(here, "out"), figdir=os.path.join(here, "figures")):
    collect(top, figdir)


if __name__ == "__main__":
    main(*sys.argv[1:])
