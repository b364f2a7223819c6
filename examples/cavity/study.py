#!/usr/bin/python3
"""Paper 004's lid-driven cavity: examples/cavity/study.py run | collect |
figures; the work is done by acoustic_tools.cavity_study.

    examples/cavity/study.py run scan us paper size   # the cavities into out/<set>/<name>/
    examples/cavity/study.py collect                  # out/summary.json, out/tables.md
    examples/cavity/study.py figures                  # figures/*.png

study.py COMMAND --help lists each command's options."""
import os

from acoustic_tools.cavity_study import main

if __name__ == "__main__":
    main(os.path.dirname(os.path.abspath(__file__)))
