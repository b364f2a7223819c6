"""The command line of examples/cavity (paper 004): examples/cavity/study.py.

  run       the cavities of the sets given (scan, paper, size, us; SETS),
            one job per directory OUT/<set>/<name>/, N at a time, each
            skipped when its result.json is there (a job stopped half-way
            runs again); each job's settings go to its job.json before
            LAMMPS starts, in.cavity writes result.json at its end
  collect   OUT/summary.json and OUT/tables.md (acoustic_tools.cavity_collect)
  figures   the PNG figures (acoustic_tools.cavity_figures)
"""
import math
import os
import shutil
import subprocess
import sys
import time

from . import cavity_collect, study

# name: (Hd, NP, NU, strain, tskip, freq) of each run: I_M = NU / sqrt(NP)
# (d/H)^(3/2); the strain (sheared length over H, recording after tskip)
# shrinks with I_M so that the cost, proportional to strain / I_M, stays bounded
SETS = {
    # H/d = 10, L/H = 5: I_M from 1e-3 to 0.6 through N_P and N_U
    "scan": {"im1e-3": (10, 1000, 1, 7, 1, 0), "im3e-3": (10, 100, 1, 12, 2, 0),
             "im1e-2": (10, 10, 1, 22, 2, 0), "im3e-2": (10, 100, 10, 42, 2, 0),
             "im1e-1": (10, 10, 10, 62, 2, 0), "im3e-1": (10, 1, 10, 102, 2, 0),
             "im6e-1": (10, 0.25, 10, 102, 2, 0)},
    # H/d = 30, 10 s of shear at I_M = 0.3 (330 H/U), recorded after 1 s
    "paper": {"im3e-1_H30": (30, 0.04, 10, 330, 33, 0)},
    # H/d = 20 at I_M = 0.1 and 0.01 beside the scan's H/d = 10
    "size": {"im1e-1_H20": (20, 1.25, 10, 42, 2, 0), "im1e-2_H20": (20, 1.25, 1, 12, 2, 0)},
    # H/d = 10 at I_M = 0.01, 0.1, 0.3 without and with 70 kHz from the bottom
    "us": {"im1e-2_f0": (10, 10, 1, 22, 2, 0), "im1e-2_f70": (10, 10, 1, 22, 2, 70e3),
           "im1e-1_f0": (10, 10, 10, 42, 2, 0), "im1e-1_f70": (10, 10, 10, 42, 2, 70e3),
           "im3e-1_f0": (10, 1, 10, 62, 2, 0), "im3e-1_f70": (10, 1, 10, 62, 2, 70e3)},
}
# the variables of in.cavity that a job.json sets
VARIABLES = ("Hd", "NP", "NU", "strain", "tskip", "freq", "nrec")


def records_per_period(NU):
    """nrec of paper 004's 10 kHz recording: 10 kHz x d/U = 101 / NU records
    per d/U (d = 1 mm, U = NU sqrt(g d)), to 6 digits"""
    return float(f"{1e4 * 1e-3 / (NU * math.sqrt(9.81e-3)):.6g}")


def job_settings(set_name, name, Hd, NP, NU, strain, tskip, freq, tag="cavity"):
    """The job.json of one cavity"""
    return {"kind": "cavity", "deck": "in.cavity", "set": set_name, "name": name, "tag": tag, "Hd": Hd, "NP": NP,
            "NU": NU, "strain": strain, "tskip": tskip, "freq": freq, "nrec": records_per_period(NU)}


def _text(value):
    """a setting as the text of a -var (6 significant digits, no ".0")"""
    return str(value) if isinstance(value, int) else f"{value:g}"


def command(lmp, here, directory, settings, ranks=1):
    """mpirun of in.cavity for one job (outputs TAG.* and result.json in directory)"""
    mpi = ["mpirun", "-np", str(ranks)]
    version = subprocess.run(["mpirun", "--version"], capture_output=True, text=True)
    if "Open MPI" in version.stdout + version.stderr:
        mpi.append("--oversubscribe")
    arguments = [lmp, "-nocite", "-echo", "none", "-screen", "none", "-in", os.path.join(here, "in.cavity"),
                 "-var", "dir", here, "-var", "tag", settings["tag"], "-var", "result", "result.json"]
    for name in VARIABLES:
        arguments += ["-var", name, _text(settings[name])]
    return mpi + arguments + ["-log", os.path.join(directory, "log.lammps")]


def run_job(lmp, here, directory, settings, ranks=1):
    """Write job.json and run one cavity in directory; the line to print"""
    study.write_job(directory, settings)
    environment = dict(os.environ)
    if os.geteuid() == 0:
        environment.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    subprocess.run(command(lmp, here, directory, settings, ranks), cwd=directory, env=environment,
                   stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    label = f"{settings['set']}/{settings['name']}"
    if study.read_result(directory) is None:
        return f"{label}: FAILED, see {os.path.join(directory, 'log.lammps')}"
    with open(os.path.join(directory, "log.lammps")) as handle:
        line = next((line for line in handle if line.startswith(f"cavity {settings['tag']}:")), "")
    return f"{label}: {line.split(': ', 1)[-1].strip()}  wall {time.time() - start:.0f} s"


def run(args):
    """study.py run"""
    lmp = shutil.which(args.lmp) or args.lmp
    if not os.access(lmp, os.X_OK):
        sys.exit(f"no LAMMPS at {lmp} (./run.sh build first, or --lmp)")
    lmp, here, out = os.path.abspath(lmp), os.path.abspath(args.here), os.path.abspath(args.out)
    jobs = []
    for set_name in args.sets:
        for name, values in SETS[set_name].items():
            directory = os.path.join(out, set_name, name)
            if study.read_result(directory) is None:
                jobs.append((lmp, here, directory, job_settings(set_name, name, *values), args.ranks))
    study.run_jobs(run_job, jobs, args.jobs)


def collect(args):
    """study.py collect"""
    cavity_collect.collect(args.out)


def figures(args):
    """study.py figures"""
    cavity_collect.draw(args.out, args.figures)


def main(here, argv=None):
    """examples/cavity/study.py (here: examples/cavity)"""
    def common(parser, figures_too=False):
        parser.add_argument("--out", default=os.path.join(here, "out"),
                            help="the runs' directory (default: examples/cavity/out)")
        if figures_too:
            parser.add_argument("--figures", default=os.path.join(here, "figures"),
                                help="where the PNGs go (default: examples/cavity/figures)")

    def run_arguments(parser):
        common(parser)
        parser.add_argument("sets", nargs="+", choices=sorted(SETS), metavar="SET",
                            help="scan, paper, size, us (see RESULTS.md for the cost of each)")
        parser.add_argument("--lmp", default=os.path.join(here, "..", "..", "build", "lammps", "lmp"),
                            help="LAMMPS (default: build/lammps/lmp)")
        parser.add_argument("--jobs", type=int, default=1, help="cavities at a time (default 1)")
        parser.add_argument("--ranks", type=int, default=1, help="MPI ranks of each cavity (default 1)")
        parser.set_defaults(here=here)

    return study.main("Paper 004's lid-driven cavity: run the cavities, collect the tables, draw the figures.", {
        "run": (run, "run the cavities of the sets not yet finished (resumable)", run_arguments),
        "collect": (collect, "summary.json and tables.md into OUT, the tables on stdout", common),
        "figures": (figures, "the PNG figures", lambda parser: common(parser, figures_too=True)),
    }, argv)
