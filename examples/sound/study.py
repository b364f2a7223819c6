#!/usr/bin/python3
"""Paper 003's sound study: examples/sound/study.py run | collect | figures
(| migrate); the work is done by acoustic_tools.sound_study.

    examples/sound/study.py run --seeds 1 2 3 4 --chain    # the samples and the 1D chain into out/
    examples/sound/study.py collect                        # out/results.json, out/tables.md
    examples/sound/study.py figures                        # figures/*.png

study.py COMMAND --help lists each command's options."""
import os

from acoustic_tools.sound_study import main

if __name__ == "__main__":
    main(os.path.dirname(os.path.abspath(__file__)))
