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
import glob
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
KEPT = ("deposit:", "avalanche ", "angle ", "Total wall time:")
GEOMETRIES = ("ensemble", "ensemble_L*", "ensemble_E*", "ensemble_e*", "ensemble_periodic", "kappa/k*", "kappa_free/k*",
              "switch_on/at*")


def result_lines(log):
    """The lines of a LAMMPS log that collect.py reads."""
    with open(log) as f:
        return [line for line in f if line.startswith(KEPT)]


def finished(lines, name):
    """A deposit log with its deposit line, or a ramp / t_con log with its
    theta_m line."""
    if name == "log.deposit":
        return any(line.startswith("deposit:") for line in lines)
    return any("theta_m = " in line for line in lines)


def record_jobs(src, dst):
    """Append the job lines of src/jobs.txt that dst/jobs.txt lacks."""
    old = []
    if os.path.exists(dst):
        with open(dst) as f:
            old = f.readlines()
    with open(src) as f:
        new = [line for line in f if line not in old]
    if new:
        with open(dst, "a") as f:
            f.writelines(new)
    return len(new)


def record(out, dest):
    """Copy the result lines of every finished job in out into dest; returns
    the number of logs written."""
    written = 0
    for pattern in GEOMETRIES:
        for top in sorted(glob.glob(os.path.join(out, pattern))):
            rel = os.path.relpath(top, out)
            for log in sorted(glob.glob(os.path.join(top, "H*", "s*", "log.*"))):
                if log.endswith(".resume"):     # the first lines of a piece; the piece appends to log.TAG
                    continue
                lines = result_lines(log)
                if not finished(lines, os.path.basename(log)):
                    continue
                target = os.path.join(dest, os.path.relpath(log, out))
                os.makedirs(os.path.dirname(target), exist_ok=True)
                with open(target, "w") as f:
                    f.writelines(lines)
                written += 1
            jobs = os.path.join(top, "jobs.txt")
            if os.path.exists(jobs):
                os.makedirs(os.path.join(dest, rel), exist_ok=True)
                record_jobs(jobs, os.path.join(dest, rel, "jobs.txt"))
    return written


def main(out=os.path.join(here, "out"), dest=os.path.join(here, "record")):
    if not os.path.isdir(out):
        sys.exit(f"record: no production outputs in {out} (run run_production.sh first)")
    print(f"record: {record(out, dest)} logs from {out} written to {dest}")


if __name__ == "__main__":
    main(*sys.argv[1:])
