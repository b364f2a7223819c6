#!/usr/bin/python3
"""Paper 004's lid-driven cavity: examples/cavity/study.py run | collect |
figures; the work is done by acoustic_tools.cavity_study.

    examples/cavity/study.py plan h30                 # the runs of a set and their cost
    examples/cavity/study.py plan h30 --progress      # ... how much of each is done in out/, the hours left
    examples/cavity/study.py run h30 --hours 10       # the cavities into out/<set>/<name>/, in pieces
    examples/cavity/study.py collect                  # out/summary.json, out/tables.md
    examples/cavity/study.py figures                  # figures/*.png

study.py COMMAND --help lists each command's options."""
import os

from acoustic_tools.cavity_study import main

if __name__ == "__main__":
    main(os.path.dirname(os.path.abspath(__file__)))
