"""Keep the result lines of examples/avalanche's production runs
(examples/avalanche/record.py is the command line): the lines of each
finished job's logs that avalanche_collect reads, copied under the same
paths into a record directory that is committed, with each geometry's
jobs.txt.

  result_lines  the lines of a log that avalanche_collect reads
  finished      whether a log's job finished
  record_jobs   append the new job lines of a jobs.txt
  record        copy every finished job of the outputs into the record
"""
import glob
import os

# the lines kept, and the directories of the outputs that hold packings (H<H>/s<seed>/)
KEPT = ("deposit:", "avalanche ", "angle ", "Total wall time:")
GEOMETRIES = ("ensemble", "ensemble_L*", "ensemble_E*", "ensemble_e*", "ensemble_periodic", "kappa/k*", "kappa_free/k*",
              "switch_on/at*")


def result_lines(log):
    """The lines of a LAMMPS log that avalanche_collect reads."""
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
