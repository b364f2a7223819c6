#!/usr/bin/python3
"""The avalanche study (paper 000): one entry point from the decks to the figures.

    examples/avalanche/study.py run [SET ...]     # the production jobs (resumable)
    examples/avalanche/study.py collect           # tables.md, summary.json
    examples/avalanche/study.py figures           # the PNGs

and job (one ramp), demo (./run.sh demo), record, calibrate; `study.py
COMMAND --help`.  The work is done by acoustic_tools.avalanche_study.
"""
import os
import sys

from acoustic_tools.avalanche_study import main

if __name__ == "__main__":
    sys.exit(main(os.path.dirname(os.path.abspath(__file__))))
