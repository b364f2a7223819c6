#!/usr/bin/python3
"""Keep the result lines of the production runs in the repository.

    /usr/bin/python3 examples/avalanche/record.py [OUT_DIR] [RECORD_DIR]

The production outputs (OUT_DIR, default examples/avalanche/out, git-ignored)
take hours of the 2 cores and gigabytes of dumps, and vanish with the machine.
This copies, for every finished job of run_ensemble.sh, the lines of its logs
that collect.py reads (the deposit line, the `avalanche` lines with theta_m and
t_con, one `angle` line per tested angle, the LAMMPS "Total wall time" lines)
into RECORD_DIR (default examples/avalanche/record, committed), under the same
paths, together with each geometry's jobs.txt.  A job recorded earlier and not
present in OUT_DIR is kept, so the record grows across machines; a job present
in both is written again from OUT_DIR.  Unfinished deposits and ramps (no
deposit or theta_m line yet) are left out.  `collect.py RECORD_DIR` then rebuilds the tables and the figures
that need no dumps (Fig. 7 and Fig. 8).
"""
import os
import sys

from acoustic_tools.avalanche_record import record

here = os.path.dirname(os.path.abspath(__file__))


def main(out=os.path.join(here, "out"), dest=os.path.join(here, "record")):
    if not os.path.isdir(out):
        sys.exit(f"record: no production outputs in {out} (run run_production.sh first)")
    print(f"record: {record(out, dest)} logs from {out} written to {dest}")


if __name__ == "__main__":
    main(*sys.argv[1:])
