"""Collect the runs of run_production.sh (out/p<p>_H<H>_s<seed>/) and of
in.chain (out/chain/) into paper 003's tables and figures:
  out/results.json, out/tables.md, figures/*.png
Usage: /usr/bin/python3 examples/sound/collect.py [OUT_DIR [FIGURE_DIR]]
(3D packings: collect.py out3d figures/3d)"""
import os
import sys

from acoustic_tools.sound_collect import collect

here = os.path.dirname(os.path.abspath(__file__))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "out")
    figures = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "figures")
    collect(out, figures)


if __name__ == "__main__":
    main()
