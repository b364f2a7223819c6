"""The command line of examples/cavity (paper 004): examples/cavity/study.py.

  run       the cavities of the sets given (SETS), one job per directory
            OUT/<set>/<name>/, N at a time, each skipped when its
            result.json is there; each job's settings go to its job.json
            before LAMMPS starts, in.cavity writes result.json at its end.
            A cavity runs as pieces (in.cavity's restart points, one per
            chunk of shear): each LAMMPS process stops after --piece-hours of
            wall time (or --max-pieces processes per call), the next goes on
            from the last whole chunk (TAG.resume), and a piece that was
            killed loses only what it wrote after that chunk (cut_after).
            The pieced run is the uninterrupted one, bit for bit.
  collect   OUT/summary.json and OUT/tables.md (acoustic_tools.cavity_collect)
  figures   the PNG figures (acoustic_tools.cavity_figures)
  plan      the runs of the sets given, their length and their estimated cost
            (--progress: how much of each is done in OUT and the hours left)
  record    job.json, result.json and the numbers of each finished run
            (row.json, cavity_collect.record) into RECORD/<set>/<name>/,
            without the recordings: collect --out RECORD makes every table
            from it, so that finished runs outlive the machine

The sets of issue 43 (paper 004 at H/d = 30, L/H = 5; PAPER_SETS) beside
those of the H/d = 10 study behind RESULTS.md's first tables (H10_SETS).
"""
import math
import os
import shutil
import subprocess
import sys
import time

from . import cavity_collect, study

# ---------------------------------------------------------------------------
# the H/d = 10 study (RESULTS.md's first tables): name: (Hd, NP, NU, strain,
# tskip, freq), strain and tskip in H/U
H10_SETS = {
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
# the variables of in.cavity that every job.json sets, and those it may set
VARIABLES = ("Hd", "NP", "NU", "strain", "tskip", "freq", "nrec")
OPTIONAL = ("LH", "seed", "walls", "stress", "tchunk", "uslid")

# ---------------------------------------------------------------------------
# paper 004's cavity (issue 43)
D, G, RHO_P, PHI, N0, REST, DISP = 1e-3, 9.81, 2500.0, 0.6, 1.5e4, 0.5, 0.15
PAPER_HD = 30
PAPER_SHEAR_S = 10.0          # paper 004 §II: 10 s of shear, recorded after the first second
PAPER_SKIP_S = 1.0
# where 10 s is out of reach: the paper's shortest record in d/U (9 s at its
# N_U = 1: 9 s x U/d = 891 d/U), after a transient of REDUCED_SKIP_HU H/U
# (1 s at N_U = 1 is 3.3 H/U at H/d = 30; the stationarity check of
# cavity_collect tells whether the record is steady)
PAPER_RECORD_DU = 9.0 * 1.0 * math.sqrt(G * D) / D
REDUCED_SKIP_HU = 5.0
# a run takes the paper's 10 s when its shear is at most this many steps
# (about 5-6 h on one free core at the measured speed, RESULTS.md "Cost")
FULL_STEPS_MAX = 2.5e7
# steps per chunk of shear (one restart point per chunk; the velocity field
# one block per chunk): about CHUNK_STEPS, within 0.05 .. 4 H/U
CHUNK_STEPS = 1.5e5
# I_M of the scan, and the N_U of its two (N_U, N_P) pairs at each
PAPER_IM = (1e-3, 3e-3, 1e-2, 3e-2, 1e-1, 3e-1, 6e-1)
PAIRS_NU = {1e-3: (1, 10), 3e-3: (1, 10), 1e-2: (1, 10), 3e-2: (1, 10), 1e-1: (10, 30), 3e-1: (10, 30),
            6e-1: (10, 30)}
KEY_IM = (1e-3, 1e-2, 1e-1, 3e-1)     # three packings (seeds 1, 2, 3) of the first pair
SEEDS = (1, 2, 3)
# ultrasound: a frequency scan at fixed N_P = 1 (the network's spectrum is
# set by the pressure, so every I_M has the band at the same place: 99.9 %
# of the modes below 87 kHz at H/d = 30, N_P = 1), three I_M through N_U
# (6.1e-3, 6.1e-2, 0.30), three packings each, the lid's grains in the
# network, the runs without ultrasound as long as those with
US_NP = 1.0
US_NU = (1, 10, 50)
US_FREQ = (0.0, 35e3, 70e3, 140e3)


def im_label(im):
    """1e-3 -> 'im1e-3', 0.3 -> 'im3e-1'"""
    mantissa, exponent = f"{im:.0e}".split("e")
    return f"im{mantissa}e{int(exponent)}"


def np_for(im, NU, Hd=PAPER_HD):
    """Eq. 3 solved for N_P: N_P = (N_U (d/H)^(3/2) / I_M)^2, to 4 digits"""
    return float(f"{(NU * (1.0 / Hd) ** 1.5 / im) ** 2:.4g}")


def time_step(NP, Hd=PAPER_HD):
    """in.cavity's time step (s): a tenth of the shortest contact time"""
    P = NP * PHI * RHO_P * G * Hd * D
    kn = N0 * P * D
    mmin = RHO_P * math.pi / 6 * (D * (1 - DISP)) ** 3
    tc = math.pi / math.sqrt(2 * kn / mmin * (1 - 1 / (1 + (math.pi / math.log(REST)) ** 2)))
    return tc / 10


def hu_seconds(NU, Hd=PAPER_HD):
    """H/U in seconds"""
    return Hd * D / (NU * math.sqrt(G * D))


def paper_length(NP, NU, Hd=PAPER_HD, full_steps_max=FULL_STEPS_MAX):
    """(strain, tskip) in H/U: the paper's 10 s recorded after 1 s when that
    is at most full_steps_max steps, else the paper's shortest record in d/U
    (PAPER_RECORD_DU) after REDUCED_SKIP_HU H/U"""
    hu = hu_seconds(NU, Hd)
    if PAPER_SHEAR_S / time_step(NP, Hd) <= full_steps_max:
        return round(PAPER_SHEAR_S / hu, 2), round(PAPER_SKIP_S / hu, 2)
    return round(REDUCED_SKIP_HU + PAPER_RECORD_DU / Hd, 2), REDUCED_SKIP_HU


def chunk_length(NP, NU, Hd=PAPER_HD):
    """tchunk (H/U) of about CHUNK_STEPS steps, within 0.05 .. 4 H/U"""
    steps_per_hu = hu_seconds(NU, Hd) / time_step(NP, Hd)
    return float(f"{min(4.0, max(0.05, CHUNK_STEPS / steps_per_hu)):.2g}")


def paper_run(im, NU, seed=1, Hd=PAPER_HD, LH=5, walls="smooth", freq=0.0, NP=None, stress=1, uslid=0):
    """The settings (without set and name) of one run of issue 43"""
    NP = np_for(im, NU, Hd) if NP is None else NP
    strain, tskip = us_length(NP, NU, Hd) if uslid else paper_length(NP, NU, Hd)
    return {"Hd": Hd, "LH": LH, "NP": NP, "NU": NU, "strain": strain, "tskip": tskip, "freq": freq,
            "seed": seed, "walls": walls, "stress": stress, "tchunk": chunk_length(NP, NU, Hd), "uslid": uslid}


def us_length(NP, NU, Hd=PAPER_HD):
    """the runs of the ultrasound set, with and without the drive: the
    paper's shortest record in d/U after REDUCED_SKIP_HU H/U (the drive's
    cost on top of the shear's)"""
    return round(REDUCED_SKIP_HU + PAPER_RECORD_DU / Hd, 2), REDUCED_SKIP_HU


def _paper_sets():
    scan, seeds, sens, us = {}, {}, {}, {}
    for im in PAPER_IM:
        for NU in PAIRS_NU[im]:
            scan[f"{im_label(im)}_nu{NU}"] = paper_run(im, NU)
        if im in KEY_IM:
            for seed in SEEDS[1:]:
                seeds[f"{im_label(im)}_nu{PAIRS_NU[im][0]}_s{seed}"] = paper_run(im, PAIRS_NU[im][0], seed=seed,
                                                                                 stress=0)
    # App. B's Coulomb threshold on the side walls against the scan's
    # frictionless ones, at 1e-2 and 0.3; L/H = 7 at 0.1
    for im in (1e-2, 3e-1):
        sens[f"{im_label(im)}_nu{PAIRS_NU[im][0]}_coulomb"] = paper_run(im, PAIRS_NU[im][0], walls="coulomb", stress=0)
    sens[f"{im_label(1e-1)}_nu10_LH7"] = paper_run(1e-1, 10, LH=7, stress=0)
    for NU in US_NU:
        im = NU / math.sqrt(US_NP) * (1.0 / PAPER_HD) ** 1.5
        for freq in US_FREQ:
            for seed in SEEDS:
                us[f"np1_nu{NU}_f{freq / 1e3:g}_s{seed}"] = paper_run(im, NU, seed=seed, freq=freq, NP=US_NP,
                                                                       stress=0, uslid=1)
    return {"h30": scan, "h30seeds": seeds, "h30sens": sens, "h30us": us}


PAPER_SETS = _paper_sets()
SETS = dict(H10_SETS, **PAPER_SETS)


def records_per_period(NU):
    """nrec of paper 004's 10 kHz recording: 10 kHz x d/U = 101 / NU records
    per d/U (d = 1 mm, U = NU sqrt(g d)), to 6 digits"""
    return float(f"{1e4 * 1e-3 / (NU * math.sqrt(9.81e-3)):.6g}")


def job_settings(set_name, name, Hd, NP, NU, strain, tskip, freq, tag="cavity", **extra):
    """The job.json of one cavity (extra: the OPTIONAL variables of in.cavity)"""
    unknown = set(extra) - set(OPTIONAL)
    if unknown:
        raise ValueError(f"unknown settings {sorted(unknown)}")
    settings = {"kind": "cavity", "deck": "in.cavity", "set": set_name, "name": name, "tag": tag, "Hd": Hd,
                "NP": NP, "NU": NU, "strain": strain, "tskip": tskip, "freq": freq, "nrec": records_per_period(NU)}
    settings.update(extra)
    return settings


def set_jobs(set_name):
    """{name: job settings} of a set"""
    jobs = {}
    for name, values in SETS[set_name].items():
        if isinstance(values, dict):
            v = dict(values)
            jobs[name] = job_settings(set_name, name, v.pop("Hd"), v.pop("NP"), v.pop("NU"), v.pop("strain"),
                                      v.pop("tskip"), v.pop("freq"), **v)
        else:
            jobs[name] = job_settings(set_name, name, *values)
    return jobs


def _text(value):
    """a setting as the text of a -var (6 significant digits, no ".0")"""
    return str(value) if isinstance(value, (int, str)) else f"{value:g}"


def command(lmp, here, directory, settings, ranks=1, log="log.lammps", extra=None):
    """mpirun of in.cavity for one job (outputs TAG.* and result.json in
    directory); extra: more -var (the piece's: tpiece, restart, ...)"""
    mpi = study.mpirun(ranks)
    arguments = [lmp, "-nocite", "-echo", "none", "-screen", "none", "-in", os.path.join(here, "in.cavity"),
                 "-var", "dir", here, "-var", "tag", settings["tag"], "-var", "result", "result.json"]
    for name in VARIABLES + tuple(n for n in OPTIONAL if n in settings):
        arguments += ["-var", name, _text(settings[name])]
    for name, value in (extra or {}).items():
        arguments += ["-var", name, _text(value)]
    return mpi + arguments + ["-log", os.path.join(directory, log)]


# ---------------------------------------------------------------------------
# pieces

def read_resume(directory, tag):
    """in.cavity's TAG.resume: (step, restart file, carry file, nskip), or
    None when there is none"""
    path = os.path.join(directory, f"{tag}.resume")
    if not os.path.exists(path):
        return None
    words = open(path).read().split()
    return int(words[0]), words[1], words[2], int(words[3])


def _step_of(line):
    try:
        return int(line.split()[0])
    except (ValueError, IndexError):
        return None


def tidy_series(path, upto=None, after=None):
    """A fix ave/time file of pieces as the uninterrupted run writes it: the
    header lines of the top only, records with after < step <= upto (None:
    no bound) in increasing order (a resumed piece writes the record of its
    first step again: dropped)"""
    if not os.path.exists(path):
        return
    keep, last, data = [], None, False
    for line in open(path):
        if line.startswith("#"):
            if not data and line not in keep:
                keep.append(line)
            continue
        step = _step_of(line)
        if step is None:
            continue
        data = True
        if (upto is not None and step > upto) or (after is not None and step <= after) \
                or (last is not None and step <= last):
            continue
        keep.append(line)
        last = step
    with open(path + ".part", "w") as f:
        f.writelines(keep)
    os.replace(path + ".part", path)


def tidy_chunks(path, upto=None):
    """A fix ave/chunk file of pieces: the header lines of the top only, the
    blocks with step <= upto in increasing order"""
    if not os.path.exists(path):
        return
    lines = open(path).readlines()
    keep, last, k, data = [], None, 0, False
    while k < len(lines):
        line = lines[k]
        if line.startswith("#"):
            if not data and line not in keep:
                keep.append(line)
            k += 1
            continue
        words = line.split()
        data = True
        step, rows = int(words[0]), int(words[1])
        block = lines[k:k + 1 + rows]
        k += 1 + rows
        if len(block) < 1 + rows or (upto is not None and step > upto) or (last is not None and step <= last):
            continue
        keep += block
        last = step
    with open(path + ".part", "w") as f:
        f.writelines(keep)
    os.replace(path + ".part", path)


def tidy_dump(path, upto=None):
    """A dump of pieces: the snapshots with step <= upto, each once, whole"""
    if not os.path.exists(path):
        return
    lines = open(path).readlines()
    keep, last, k = [], None, 0
    starts = [i for i, line in enumerate(lines) if line.startswith("ITEM: TIMESTEP")] + [len(lines)]
    for a, b in zip(starts[:-1], starts[1:]):
        frame = lines[a:b]
        step = _step_of(frame[1]) if len(frame) > 1 else None
        if step is None or len(frame) < 4:
            continue
        try:
            count = int(frame[3])
        except ValueError:
            continue
        if len(frame) < 9 + count:              # cut by a kill
            continue
        if (upto is not None and step > upto) or (last is not None and step <= last):
            continue
        keep += frame[:9 + count]
        last = step
    with open(path + ".part", "w") as f:
        f.writelines(keep)
    os.replace(path + ".part", path)


def cut_after(directory, tag, step=None, nskip=None):
    """The outputs of a cavity's pieces as one run: what a killed piece
    wrote after step (the last restart point) dropped, the headers and the
    record a resumed piece writes again at its first step dropped (records
    of fix ave/time start after nskip)"""
    for name in (f"{tag}.wall.txt", f"{tag}.us.txt"):
        tidy_series(os.path.join(directory, name), upto=step, after=nskip)
    for name in (f"{tag}.flow", f"{tag}.stress"):
        tidy_chunks(os.path.join(directory, name), upto=step)
    tidy_dump(os.path.join(directory, f"{tag}.contacts"), upto=step)


def run_job(lmp, here, directory, settings, ranks=1, piece_seconds=0, max_pieces=None, say=None, deadline=None):
    """Write job.json and run one cavity in directory, piece after piece
    (each LAMMPS process stops at the first restart point after
    piece_seconds of wall time; 0: one process), at most max_pieces
    processes in this call and none started after the time deadline (s
    since the epoch; a piece then stops at the first restart point after
    it); the line to print"""
    study.write_job(directory, settings)
    environment = dict(os.environ)
    if os.geteuid() == 0:
        environment.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    label = f"{settings['set']}/{settings['name']}"
    tag = settings["tag"]
    start, pieces = time.time(), 0
    while study.read_result(directory) is None:
        if max_pieces is not None and pieces >= max_pieces:
            resume = read_resume(directory, tag)
            where = f"step {resume[0]}" if resume else "the start"
            return f"{label}: paused after {pieces} piece(s) at {where}; repeat the command to go on"
        resume = read_resume(directory, tag)
        budget = piece_seconds
        if deadline is not None:
            left = deadline - time.time()
            if left <= 0:
                where = f"step {resume[0]}" if resume else "the start"
                return f"{label}: paused at {where} (the call's --hours are over); repeat the command to go on"
            budget = max(60.0, left) if not budget else max(60.0, min(budget, left))
        extra = {"tpiece": budget}
        if resume is not None and os.path.exists(os.path.join(directory, "log.lammps")):
            step, restart, carry, nskip = resume
            cut_after(directory, tag, step, nskip)
            extra.update(restart=restart, carry=carry, append=1)
            log = f"log.piece{step}"
        else:
            for name in os.listdir(directory) if os.path.isdir(directory) else []:
                if name.startswith(f"{tag}.") or name.startswith("log."):
                    os.remove(os.path.join(directory, name))
            log = "log.lammps"
        subprocess.run(command(lmp, here, directory, settings, ranks, log, extra), cwd=directory, env=environment,
                       stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        pieces += 1
        after = read_resume(directory, tag)
        if study.read_result(directory) is None and (after is None or after == resume):
            return f"{label}: FAILED, see {os.path.join(directory, log)}"
        if say is not None and study.read_result(directory) is None:
            say(f"{label}: piece {pieces} ended at step {after[0]}")
    resume = read_resume(directory, tag)
    cut_after(directory, tag, None, None if resume is None else resume[3])
    with open(os.path.join(directory, "log.lammps")) as handle:
        line = next((line for line in handle if line.startswith(f"cavity {tag}:")), "")
    return f"{label}: {line.split(': ', 1)[-1].strip()}  wall {time.time() - start:.0f} s, {pieces} piece(s)"


# ---------------------------------------------------------------------------
# cost

def grains(Hd, LH=5):
    """in.cavity's number of grains"""
    return round(0.80 * LH * Hd * Hd / (math.pi / 4 * (1 + DISP ** 2 / 3)))


def steps(settings):
    """(preparation, shear) steps of one job: the deposit and the compression
    (in.cavity's runs before the shear), the shear"""
    Hd, NP, NU = settings["Hd"], settings["NP"], settings["NU"]
    dt = time_step(NP, Hd)
    dtdep = time_step(1.0, Hd) if NP > 1 else dt       # the deposit's stiffness: N_P = 1 when N_P > 1
    H = Hd * D
    ytop = 4 * H + 4 * D
    deposit = (math.sqrt(2 * ytop / G) + 0.05 + 0.1) / dtdep
    P = NP * PHI * RHO_P * G * H
    compress = 40 * D * math.sqrt(PHI * RHO_P / P) / dt
    return deposit + compress, settings["strain"] * hu_seconds(NU, Hd) / dt


def solve_interval(settings):
    """in.cavity's steps between two vibration solves (nus)"""
    dt = time_step(settings["NP"], settings["Hd"])
    period = D / (settings["NU"] * math.sqrt(G * D))
    return max(1, round(0.1 * period / dt))


def cost_hours(settings, atom_steps_per_s, solve_steps=None):
    """estimated hours of one job on one rank at atom_steps_per_s (grains x
    steps per second); with ultrasound each solve costs solve_steps steps
    (default US_SOLVE_STEPS, measured at H/d = 30)"""
    solve_steps = US_SOLVE_STEPS if solve_steps is None else solve_steps
    prep, shear = steps(settings)
    atoms = grains(settings["Hd"], settings.get("LH", 5)) + 2 * round(settings.get("LH", 5) * settings["Hd"])
    factor = 1.0 + solve_steps / solve_interval(settings) if settings.get("freq", 0) > 0 else 1.0
    return (prep + shear * factor) * atoms / atom_steps_per_s / 3600.0


def done_fraction(directory, settings):
    """How much of the run in directory is done, as a fraction of its steps
    (deposit and compression, then the shear): 1 when it has its result,
    the last whole chunk of the shear (TAG.resume) when it is paused, 0
    before its first chunk"""
    if study.read_result(directory) is not None:
        return 1.0
    resume = read_resume(directory, settings["tag"])
    if resume is None:
        return 0.0
    prep, shear = steps(settings)
    return min(1.0, (prep + resume[0]) / (prep + shear))


def plan(sets, atom_steps_per_s, solve_steps=None, out=None):
    """The lines of a table of the runs of sets: name, I_M, length, steps,
    hours; with out (the runs' directory) also how much of each is done and
    the hours left"""
    lines = ["| run | H/d | L/H | N_U | N_P | I_M | walls | f (kHz) | shear (H/U) | recorded (d/U; s) "
             "| steps | chunk (H/U) | hours |" + (" done | hours left |" if out else ""),
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|" + ("---|---|" if out else "")]
    total, left = {}, {}
    for set_name in sets:
        for name, s in set_jobs(set_name).items():
            hours = cost_hours(s, atom_steps_per_s, solve_steps)
            total[set_name] = total.get(set_name, 0.0) + hours
            done = done_fraction(os.path.join(out, set_name, name), s) if out else 0.0
            left[set_name] = left.get(set_name, 0.0) + (1.0 - done) * hours
            im = s["NU"] / math.sqrt(s["NP"]) * (1.0 / s["Hd"]) ** 1.5
            rec_s = (s["strain"] - s["tskip"]) * hu_seconds(s["NU"], s["Hd"])
            rec_du = (s["strain"] - s["tskip"]) * s["Hd"]
            prep, shear = steps(s)
            lines.append(f"| {set_name}/{name} | {s['Hd']} | {s.get('LH', 5)} | {s['NU']} | {s['NP']:g} | {im:.3g} "
                         f"| {s.get('walls', 'smooth')} | {s['freq'] / 1e3:g} | {s['strain']:g} | {rec_du:.0f}; {rec_s:.3g} "
                         f"| {prep + shear:.3g} | {s.get('tchunk', 1):g} | {hours:.1f} |"
                         + (f" {100 * done:.0f} % | {(1 - done) * hours:.1f} |" if out else ""))
    lines.append("")
    for set_name, hours in total.items():
        lines.append(f"{set_name}: {len(SETS[set_name])} runs, {hours:.0f} h"
                     + (f", {left[set_name]:.1f} h left" if out else ""))
    lines.append(f"all: {sum(total.values()):.0f} h on one rank" + (f", {sum(left.values()):.1f} h left" if out else ""))
    return lines


# ---------------------------------------------------------------------------
# the command line

def select_runs(set_names, only=None):
    """[(set, name, settings)] of the runs of SET_NAMES that ONLY's texts select (all without
    ONLY): a text that is the name or set/name of one of these runs selects it alone
    (im1e-2_nu1, not im1e-2_nu10); any other text, the runs whose set/name contains it."""
    runs = [(set_name, name, settings) for set_name in set_names
            for name, settings in set_jobs(set_name).items()]
    if not only:
        return runs
    names = {text for set_name, name, _ in runs for text in (name, f"{set_name}/{name}")}
    return [(set_name, name, settings) for set_name, name, settings in runs
            if any(text in (name, f"{set_name}/{name}") if text in names else text in f"{set_name}/{name}"
                   for text in only)]


def run(args):
    """study.py run"""
    lmp = shutil.which(args.lmp) or args.lmp
    if not os.access(lmp, os.X_OK):
        sys.exit(f"no LAMMPS at {lmp} (./run.sh build first, or --lmp)")
    lmp, here, out = os.path.abspath(lmp), os.path.abspath(args.here), os.path.abspath(args.out)
    deadline = None if not args.hours else time.time() + 3600.0 * args.hours
    jobs = []
    for set_name, name, settings in select_runs(args.sets, args.only):
        directory = os.path.join(out, set_name, name)
        if study.read_result(directory) is None:
            jobs.append((lmp, here, directory, settings, args.ranks, args.piece_hours * 3600.0,
                         args.max_pieces, print, deadline))
    study.run_jobs(run_job, jobs, args.jobs)


def collect(args):
    """study.py collect"""
    cavity_collect.collect(args.out)


def figures(args):
    """study.py figures"""
    cavity_collect.draw(args.out, args.figures)


def record_command(args):
    """study.py record"""
    print(f"record: {cavity_collect.record(args.out, args.record)} runs of {args.out} written to {args.record}")


def plan_command(args):
    """study.py plan"""
    print("\n".join(plan(args.sets, args.rate, args.solve_steps, args.out if args.progress else None)))


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
                            help=f"{', '.join(sorted(SETS))} (see RESULTS.md for the cost of each)")
        parser.add_argument("--only", nargs="+", metavar="TEXT",
                            help="only these runs: a run's name or set/name selects it alone, "
                                 "any other text the runs whose set/name contains it")
        parser.add_argument("--lmp", default=os.path.join(here, "..", "..", "build", "lammps", "lmp"),
                            help="LAMMPS (default: build/lammps/lmp)")
        parser.add_argument("--jobs", type=int, default=1, help="cavities at a time (default 1)")
        parser.add_argument("--ranks", type=int, default=1, help="MPI ranks of each cavity (default 1)")
        parser.add_argument("--piece-hours", type=float, default=2.0,
                            help="wall hours per LAMMPS process, ended at the next restart point (default 2; 0: none)")
        parser.add_argument("--max-pieces", type=int,
                            help="processes per cavity in this call (default: until it ends)")
        parser.add_argument("--hours", type=float, default=0,
                            help="wall hours of this call: no piece starts after them, and a running piece stops "
                                 "at its first restart point after them (default 0: no limit)")
        parser.set_defaults(here=here)

    def record_arguments(parser):
        common(parser)
        parser.add_argument("--record", default=os.path.join(here, "record"),
                            help="where the runs go (default: examples/cavity/record, committed)")

    def plan_arguments(parser):
        common(parser)
        parser.add_argument("sets", nargs="+", choices=sorted(SETS), metavar="SET")
        parser.add_argument("--progress", action="store_true",
                            help="also how much of each run is done in --out and the hours left")
        parser.add_argument("--rate", type=float, default=RATE,
                            help=f"grain-steps per second of one rank (default {RATE:.3g}, measured: RESULTS.md)")
        parser.add_argument("--solve-steps", type=float, default=US_SOLVE_STEPS,
                            help=f"cost of one vibration solve in steps of the shear (default {US_SOLVE_STEPS:g})")

    return study.main("Paper 004's lid-driven cavity: run the cavities, collect the tables, draw the figures.", {
        "run": (run, "run the cavities of the sets not yet finished (resumable, in pieces)", run_arguments),
        "collect": (collect, "summary.json and tables.md into OUT, the tables on stdout", common),
        "figures": (figures, "the PNG figures", lambda parser: common(parser, figures_too=True)),
        "plan": (plan_command, "the runs of the sets, their length and estimated cost", plan_arguments),
        "record": (record_command, "job.json, result.json and each finished run's numbers (row.json) into the "
                                   "record, without the recordings; collect --out RECORD makes the tables from it",
                   record_arguments),
    }, argv)


# measured speed of in.cavity at H/d = 30 on one rank (RESULTS.md, "Cost"):
# grain-steps per second of the shear (4 852 atoms, 1 000-1 200 steps/s
# each for two single-rank runs side by side on the 2-core machine), and the
# cost of one vibration solve of fix acoustic/mindlin (4 550 grains, 70 kHz)
# in steps of the shear
RATE = 5.3e6
US_SOLVE_STEPS = 38.0
