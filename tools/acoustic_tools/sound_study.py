"""The command line of examples/sound (paper 003): examples/sound/study.py.

  run       the samples (in.sound: packing, pulse, moduli), one job per
            directory OUT/p<p>_H<H>_s<seed>[_m<mass>][_v<speed>][_mu<mu>]/, N at a
            time, each skipped when its result.json is there (a job stopped
            half-way runs again); --mu 0: frictionless packings (in.packing's
            mu; in.measure then uses the frictionless network); with --chain, the 1D chain (in.chain) into
            OUT/chain/, with --chain-poly W..., polydisperse chains into
            OUT/chain_poly<W>/; with --lattice P... and --lattice-series
            P..., perfect triangular lattices (in.lattice) into
            OUT/lattice_p<P>_M<M>/.  Each job's settings go to its job.json before
            LAMMPS starts; the deck writes result.json at its end, to which
            run adds the job's wall_seconds.
  collect   OUT/results.json and OUT/tables.md (acoustic_tools.sound_collect)
  figures   the PNG figures (acoustic_tools.sound_figures)
  figures-run  in.figures on one finished sample (default: the first at
            p = 1e-4, H = 25) into OUT/figures_<sample>/: the snapshot of
            Fig. 3, the modes of Fig. 10 (chosen from the network's modes:
            sound_modes.selected_modes) and the damped signals of Fig. 11
  migrate   one-off: job.json and result.json for the sample directories
            written before the decks wrote result.json (summary.txt,
            moduli.txt, checks.txt and the log; examples/sound/record/ too)

The directory's name is only a name: collect reads the settings from
job.json.  Directory names keep the texts of the pressure and the piston
given on the command line (p1e-4, _m0.1, _v0), as the former run_production.sh named
them.
"""
import os
import re
import shutil
import subprocess
import sys
import time

from . import sound_collect, study
from .lammps_output import read_key_values

PRESSURES = ("1e-4", "1e-5", "1e-6", "1e-7")
HEIGHTS = (25, 8)
SEEDS = (1, 2, 3, 4)
CHAIN_SIZES = (8, 16, 32, 64, 128, 256, 512, 1024, 2048)
CHAIN_POLY_SIZES = (8, 16, 32, 64, 128, 256, 512)
LATTICE_ROWS = (9, 29)                    # walls 7.9 and 25.2 apart: the packings' H = 8 and 25
LATTICE_SERIES_ROWS = (8, 16, 32, 64, 128, 256)
LATTICE_SERIES_WIDTH = 4                  # the pulse is uniform along x: 4 balls per row suffice
DEFAULT_MASS, DEFAULT_SPEED = "1", "0.001"
DEFAULT_MU = "0.5"                        # in.packing's friction coefficient (paper 003's)
DEFAULT_MODULI_STRAIN = "0.05"            # in.moduli's strain, a fraction of the overlap (3 p)^(2/3) over h
# the variables of in.sound that a sample's job.json sets (mu: only when it
# is not the default, so that the command of a frictional sample stays as it was)
SAMPLE_VARIABLES = ("p", "W", "D", "H", "seed", "piston_mass", "piston_speed")


def _number(text):
    """a number given as text (the command line, a directory's name): an int
    when it is one, else a float"""
    value = float(text)
    return int(value) if value.is_integer() and re.fullmatch(r"[+-]?[0-9]+", str(text).strip()) else value


def sample_name(p, H, seed, piston_mass=DEFAULT_MASS, piston_speed=DEFAULT_SPEED, mu=DEFAULT_MU,
                moduli_strain=DEFAULT_MODULI_STRAIN):
    """The directory name of a sample (texts as given on the command line):
    p<p>_H<H>_s<seed>, with _m<mass> and _v<speed> for another piston than
    the default, _mu<mu> for another friction coefficient (p1e-4_H25_s1_mu0)
    and _e<strain> for another strain of the moduli (p1e-7_H25_s1_e0.5)"""
    name = f"p{p}_H{H}_s{seed}"
    if str(piston_mass) != DEFAULT_MASS:
        name += f"_m{piston_mass}"
    if str(piston_speed) != DEFAULT_SPEED:
        name += f"_v{piston_speed}"
    if float(mu) != float(DEFAULT_MU):
        name += f"_mu{mu}"
    if float(moduli_strain) != float(DEFAULT_MODULI_STRAIN):
        name += f"_e{moduli_strain}"
    return name


def sample_settings(p, H, seed, width=24, depth=0, piston_mass=DEFAULT_MASS, piston_speed=DEFAULT_SPEED,
                    extra=(), mu=DEFAULT_MU, moduli_strain=DEFAULT_MODULI_STRAIN):
    """The job.json of a sample: kind "sample", the pressure (p), the target
    height (H), the seed, the width (W), the depth (D, 0: 2D), the piston's
    mass (in units of the grains') and dashpot speed, the friction
    coefficient mu of the preparation (0: a frictionless packing, measured
    on its frictionless network), the strain of the moduli (in.moduli's
    moduli_strain, a fraction of the overlap; only when it is not the
    default) and any other variable of in.sound given as (name, text) pairs
    in extra ("variables")"""
    settings = {"kind": "sample", "deck": "in.sound", "p": float(p), "H": int(H), "seed": int(seed),
                "W": _number(width), "D": _number(depth), "piston_mass": _number(piston_mass),
                "piston_speed": _number(piston_speed), "mu": _number(mu)}
    if float(moduli_strain) != float(DEFAULT_MODULI_STRAIN):
        settings["moduli_strain"] = _number(moduli_strain)
    if extra:
        settings["variables"] = {name: value for name, value in extra}
    return settings


def write_sample_job(directory, p, H, seed, width, depth, piston_mass, piston_speed):
    """job.json of a sample run by the former examples/sound/run_production.sh (texts of
    its command line)"""
    study.write_job(directory, sample_settings(p, H, seed, width, depth, piston_mass, piston_speed))


def add_wall_seconds(directory, seconds):
    """Add the job's wall time (s) to its result.json"""
    study.add_to_result(directory, {"wall_seconds": int(seconds)})


def _deck_text(settings, name, texts):
    """the -var text of one of a sample's settings: the command line's text
    when there is one (the log then reads as the former run_production.sh's), else
    the number"""
    return texts.get(name, f"{settings[name]:g}" if isinstance(settings[name], float) else str(settings[name]))


def sample_command(lmp, here, directory, settings, texts):
    """The LAMMPS command of one sample"""
    command = [lmp, "-in", os.path.join(here, "in.sound"), "-var", "here", here]
    for name in SAMPLE_VARIABLES:
        command += ["-var", name, _deck_text(settings, name, texts)]
    if "mu" in settings and float(settings["mu"]) != float(DEFAULT_MU):
        command += ["-var", "mu", _deck_text(settings, "mu", texts)]
    if "moduli_strain" in settings:
        command += ["-var", "moduli_strain", _deck_text(settings, "moduli_strain", texts)]
    for name, value in settings.get("variables", {}).items():
        command += ["-var", name] + str(value).split()
    return command + ["-var", "dir", directory, "-log", os.path.join(directory, "log.lammps"),
                      "-screen", "none", "-nocite"]


def chain_settings(sizes, poly=0.0, realizations=1, seed=1, walls="identical", p=1e-4):
    """The job.json of a chain job (in.chain): the sizes N, the walls
    (identical: Appendix C's springs; rigid), the polydispersity w
    (diameters uniform in [1 - w, 1 + w]; 0: identical balls), the chains of
    each N (realizations) and their seed"""
    settings = {"kind": "chain", "deck": "in.chain", "p": float(p), "N": [int(n) for n in sizes], "walls": walls,
                "poly": float(poly)}
    if poly:
        settings.update({"realizations": int(realizations), "seed": int(seed)})
    return settings


def chain_name(settings):
    """OUT's directory of a chain job: chain, chain_poly<w>, with _rigid for rigid walls"""
    name = "chain" + (f"_poly{settings['poly']:g}" if settings["poly"] else "")
    return name + ("_rigid" if settings["walls"] != "identical" else "")


def chain_command(lmp, here, directory, settings):
    """The LAMMPS command of a chain job"""
    command = [lmp, "-in", os.path.join(here, "in.chain"), "-var", "p", f"{settings['p']:g}",
               "-var", "N"] + [str(n) for n in settings["N"]] + ["-var", "walls", settings.get("walls", "identical")]
    if settings.get("poly"):
        command += ["-var", "poly", f"{settings['poly']:g}", "-var", "realizations", str(settings["realizations"]),
                    "-var", "seed", str(settings["seed"])]
    return command + ["-var", "dir", directory, "-log", os.path.join(directory, "log.lammps"), "-screen", "none",
                      "-nocite"]


def lattice_settings(p, rows, width):
    """The job.json of a triangular lattice (in.lattice): the pressure, the
    numbers of rows (one lattice each) and the balls per row M"""
    return {"kind": "lattice", "deck": "in.lattice", "p": float(p), "rows": [int(n) for n in rows], "M": int(width)}


def lattice_name(settings, text):
    """OUT's directory of a lattice job: lattice_p<p>_M<M> (p as given)"""
    return f"lattice_p{text}_M{settings['M']}"


def lattice_command(lmp, here, directory, settings, text):
    """The LAMMPS command of a lattice job"""
    return [lmp, "-in", os.path.join(here, "in.lattice"), "-var", "p", text, "-var", "M", str(settings["M"]),
            "-var", "rows"] + [str(n) for n in settings["rows"]] + [
        "-var", "dir", directory, "-log", os.path.join(directory, "log.lammps"), "-screen", "none", "-nocite"]


def _run_job(label, directory, settings, command):
    """Write job.json, run LAMMPS, add wall_seconds to result.json; the
    line to print"""
    study.write_job(directory, settings)
    start = time.time()
    done = subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True)
    seconds = time.time() - start
    if done.returncode != 0 or study.read_result(directory) is None:
        return f"{label}: FAILED, see {os.path.join(directory, 'log.lammps')}"
    add_wall_seconds(directory, seconds)
    summary = ""
    with open(os.path.join(directory, "log.lammps")) as handle:
        for line in handle:
            if line.startswith("moduli: sigma1/sigma2"):
                summary = line.strip() + " "
    return f"{label}: {summary}({seconds:.0f} s)"


def default_lmp(here):
    """LAMMPS of this repository's build (./run.sh build)"""
    return os.path.join(here, "..", "..", "build", "lammps", "lmp")


def run(args):
    """study.py run: the samples (and the chain) not yet finished, args.jobs at a time"""
    here = os.path.abspath(args.here)
    lmp = shutil.which(args.lmp) or args.lmp
    if not os.access(lmp, os.X_OK):
        sys.exit(f"no LAMMPS at {lmp} (./run.sh build first, or --lmp)")
    lmp = os.path.abspath(lmp)
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    jobs = []
    for p in [] if args.no_samples else args.pressures:
        for H in args.heights:
            for seed in args.seeds:
                directory = os.path.join(out, sample_name(p, H, seed, args.piston_mass, args.piston_speed, args.mu,
                                                          args.moduli_strain))
                if study.read_result(directory) is not None:
                    continue
                settings = sample_settings(p, H, seed, args.width, args.depth, args.piston_mass,
                                           args.piston_speed, args.var or (), args.mu, args.moduli_strain)
                texts = {"p": p, "W": args.width, "D": args.depth, "piston_mass": args.piston_mass,
                         "piston_speed": args.piston_speed, "mu": args.mu, "moduli_strain": args.moduli_strain}
                friction = "" if float(args.mu) == float(DEFAULT_MU) else f" mu={args.mu}"
                jobs.append((f"p={p} H={H} seed={seed}{friction}", directory, settings,
                             sample_command(lmp, here, directory, settings, texts)))
    chains = [chain_settings(args.chain_sizes)] if args.chain else []
    chains += [chain_settings(args.chain_poly_sizes, w, args.chain_realizations) for w in args.chain_poly or ()]
    for settings in chains:
        directory = os.path.join(out, chain_name(settings))
        if study.read_result(directory) is None:
            jobs.append((chain_name(settings), directory, settings, chain_command(lmp, here, directory, settings)))
    lattices = [(p, lattice_settings(p, LATTICE_ROWS, args.width)) for p in args.lattice or ()]
    lattices += [(p, lattice_settings(p, args.lattice_series_rows, LATTICE_SERIES_WIDTH))
                 for p in args.lattice_series or ()]
    for text, settings in lattices:
        directory = os.path.join(out, lattice_name(settings, text))
        if study.read_result(directory) is None:
            jobs.append((os.path.basename(directory), directory, settings,
                         lattice_command(lmp, here, directory, settings, text)))
    study.run_jobs(_run_job, jobs, args.jobs)


def collect(args):
    """study.py collect"""
    sound_collect.collect(args.out)


SUMMARY_PREFIXES = ("packing", "checks", "pulse", "moduli")


def log_summary(directory):
    """the lines of a sample's log.lammps that in.sound prints as its summary
    (the lines that begin with packing, checks, pulse or moduli), for
    record/<sample>/log_summary.txt"""
    path = os.path.join(directory, "log.lammps")
    if not os.path.exists(path):
        return ""
    with open(path, errors="replace") as f:
        return "".join(line for line in f if line.startswith(SUMMARY_PREFIXES))


def is_sample(name):
    """a packing sample's directory (p<p>_H<H>_s<seed>...), not a chain or lattice"""
    return re.match(r"p[0-9.e+-]+_H[0-9]+_s[0-9]+", name) is not None


def record(args):
    """study.py record: the finished samples of OUT into RECORD (job.json,
    result.json, log_summary.txt), then the tables of OUT (collect: they
    need the samples' signals, which the record does not keep) into
    RECORD/tables.md, or RECORD/<args.tables> when OUT holds only part of
    the study (the full study's tables.md then stays as it is)"""
    name = getattr(args, "tables", None) or "tables.md"
    if os.path.basename(name) != name or not name.endswith(".md"):
        raise SystemExit(f"study.py record: --tables {name}: give a file name ending in .md, no directory")
    written = study.record_jobs(args.out, args.record, summarise=log_summary, select=is_sample)
    print(f"record: {written} samples from {args.out} written to {args.record}")
    sound_collect.collect(args.out)
    shutil.copyfile(os.path.join(args.out, "tables.md"), os.path.join(args.record, name))
    print(f"record: the tables of {args.out} in {os.path.join(args.record, name)}")


def figures(args):
    """study.py figures"""
    sound_collect.draw(args.out, args.figures)


def figures_run(args):
    """study.py figures-run: in.figures on one finished sample"""
    here = os.path.abspath(args.here)
    lmp = os.path.abspath(shutil.which(args.lmp) or args.lmp)
    out = os.path.abspath(args.out)
    jobs = sound_collect.samples(out)
    if args.sample:
        chosen = [key for key, (directory, _) in jobs.items() if os.path.basename(directory) == args.sample]
    else:
        chosen = sorted(key for key in jobs if key[0] == 1e-4 and key[1] == 25)
    if not chosen:
        sys.exit(f"no finished sample {args.sample or 'at p = 1e-4, H = 25'} in {out}")
    sample_dir, result = jobs[chosen[0]]
    data = sound_collect.packing_modes(sample_dir, result)
    selected = data["selected"]
    modes = sorted(i + 1 for indices in selected.values() for i in indices)   # the deck's m: 1 = lowest
    speed = 0.26 * (float(result["p"]) / 1e-4) ** (1.0 / 6.0)    # paper 003's c_tof (its Fig. 3: t = 80 at L = 25)
    settings = {"kind": "figures", "deck": "in.figures", "sample": os.path.basename(sample_dir),
                "modes": modes, "damping": [float(z) for z in args.damping],
                "Tsnap": round(0.8 * float(result["h"]) / speed, 1),
                "Tpulse": round(3.0 * float(result["h"]) / speed, 1)}
    directory = os.path.join(out, "figures_" + settings["sample"])
    os.makedirs(directory, exist_ok=True)
    study.write_job(directory, settings)
    command = [lmp, "-in", os.path.join(here, "in.figures"),
               "-var", "restart", os.path.join(sample_dir, "packing.restart"), "-var", "h", repr(float(result["h"])),
               "-var", "dir", directory, "-var", "Tsnap", str(settings["Tsnap"]),
               "-var", "Tpulse", str(settings["Tpulse"]), "-var", "modes"] + [str(m) for m in modes] + [
               "-var", "damping"] + [f"{z:g}" for z in settings["damping"]] + [
               "-log", os.path.join(directory, "log.lammps"), "-screen", "none", "-nocite"]
    print(f"{settings['sample']}: modes {modes} ({selected}, indices from 0), damping {settings['damping']}, "
          f"snapshot at t = {settings['Tsnap']}; signal of the modes against pulse_A.dat: "
          f"{data['signal_deviation']:.2g} of its peak", flush=True)
    start = time.time()
    done = subprocess.run(command, stdin=subprocess.DEVNULL)
    if done.returncode != 0:
        sys.exit(f"in.figures FAILED, see {os.path.join(directory, 'log.lammps')}")
    study.write_result(directory, {"modes": modes, "selected": selected, "zero_modes": int(data["modes"]["zero"].sum()),
                                   "signal_deviation": data["signal_deviation"],
                                   "wall_seconds": int(time.time() - start)})
    print(f"{directory}: done ({time.time() - start:.0f} s)")


# ---- one-off: the samples written before the decks wrote result.json

LEGACY_NAME = re.compile(r"p([0-9.e+-]+)_H([0-9]+)_s([0-9]+)(?:_m([0-9.e+-]+))?(?:_v([0-9.e+-]+))?")
OLD_FILES = ("summary.txt", "moduli.txt", "checks.txt")


def _text_number(text):
    """a value of the old key-value files as the deck prints it in result.json"""
    try:
        return _number(text)
    except ValueError:
        return text


def _old_values(path):
    """the "key value" lines of an old file, numbers kept as printed"""
    values = {}
    with open(path) as handle:
        for line in handle:
            words = line.split()
            if len(words) == 2:
                values[words[0]] = _text_number(words[1])
    return values


def legacy_result(directory):
    """result.json of a sample directory of the old decks (summary.txt,
    moduli.txt, checks.txt, and log.lammps or, in record/, log_summary.txt
    for "packing: at rest"), in the order in.sound writes it now, or None
    when it had not finished (no moduli.txt)"""
    if not os.path.exists(os.path.join(directory, "moduli.txt")):
        return None
    summary = _old_values(os.path.join(directory, "summary.txt"))
    moduli = _old_values(os.path.join(directory, "moduli.txt"))
    result = {key: summary[key] for key in sound_collect.SUMMARY_KEYS if key in summary and key != "wall_seconds"}
    log = next(os.path.join(directory, name) for name in ("log.lammps", "log_summary.txt")
               if os.path.exists(os.path.join(directory, name)))
    with open(log) as handle:
        result["at_rest"] = any(line.startswith("packing: at rest") for line in handle)
    result.update(moduli)
    checks = os.path.join(directory, "checks.txt")
    if os.path.exists(checks):
        result["checks"] = _old_values(checks)
    if "wall_seconds" in summary:
        result["wall_seconds"] = summary["wall_seconds"]
    return result


def migrate_directory(directory, remove_old=False):
    """job.json (settings from the directory's name and summary.txt) and
    result.json (legacy_result) of one old sample directory; a directory of
    the new decks run by the former run_production.sh (result.json, no
    job.json, wall_seconds alone in summary.txt) gets its job.json and its
    wall_seconds.  remove_old: delete the old files afterwards (record/).
    What was done, or None when nothing was to do."""
    match = LEGACY_NAME.fullmatch(os.path.basename(directory))
    if not match or os.path.exists(os.path.join(directory, study.JOB)):
        return None
    result = study.read_result(directory)
    if result is None:
        result = legacy_result(directory)
        if result is None:
            return None
        study.write_result(directory, result)
        done = "job.json, result.json"
    else:
        summary = os.path.join(directory, "summary.txt")
        if "wall_seconds" not in result and os.path.exists(summary):
            add_wall_seconds(directory, read_key_values(summary)["wall_seconds"])
        done = "job.json"
    p, H, seed, mass, speed = match.groups()
    study.write_job(directory, sample_settings(p, H, seed, result["W"], result["D"], mass or DEFAULT_MASS,
                                               speed or DEFAULT_SPEED))
    if remove_old:
        for name in OLD_FILES:
            if os.path.exists(os.path.join(directory, name)):
                os.remove(os.path.join(directory, name))
    return done


def migrate(args):
    """study.py migrate"""
    for name in sorted(os.listdir(args.out)):
        done = migrate_directory(os.path.join(args.out, name), args.remove_old)
        if done:
            print(f"{name}: {done}")


def main(here, argv=None):
    """examples/sound/study.py (here: examples/sound)"""
    def common(parser, figures_too=False):
        parser.add_argument("--out", default=os.path.join(here, "out"),
                            help="the jobs' directory (default: examples/sound/out; 3D: out3d)")
        if figures_too:
            parser.add_argument("--figures", default=os.path.join(here, "figures"),
                                help="where the PNGs go (default: examples/sound/figures)")

    def run_arguments(parser):
        common(parser)
        parser.add_argument("--lmp", default=default_lmp(here), help="LAMMPS (default: build/lammps/lmp)")
        parser.add_argument("--jobs", type=int, default=2, help="samples at a time, one core each (default 2)")
        parser.add_argument("--pressures", nargs="+", default=list(PRESSURES),
                            help="target pressures p, as the directory names show them (default 1e-4 ... 1e-7)")
        parser.add_argument("--heights", nargs="+", type=int, default=list(HEIGHTS), help="target heights H (25 8)")
        parser.add_argument("--seeds", nargs="+", type=int, default=list(SEEDS), help="seeds (1 2 3 4)")
        parser.add_argument("--width", default="24", help="width W (periodic), d (24)")
        parser.add_argument("--depth", default="0", help="depth D of a 3D packing; 0: 2D (default)")
        parser.add_argument("--piston-mass", default=DEFAULT_MASS,
                            help="the piston's mass / the grains' (1; others go to ..._m<mass>)")
        parser.add_argument("--piston-speed", default=DEFAULT_SPEED,
                            help="terminal speed of the piston's dashpot, 0: free (0.001; others go to ..._v<speed>)")
        parser.add_argument("--mu", default=DEFAULT_MU,
                            help="friction coefficient of the contacts (0.5, the paper's; others go to ..._mu<mu>); "
                                 "0: frictionless packings, measured on the frictionless network (model normal)")
        parser.add_argument("--moduli-strain", default=DEFAULT_MODULI_STRAIN,
                            help="the strain of the moduli, a fraction of the overlap (3 p)^(2/3) over h (0.05; "
                                 "others go to ..._e<strain>): the same packings, C33 at a larger strain")
        parser.add_argument("--var", nargs=2, action="append", metavar=("NAME", "VALUE"),
                            help="another variable of in.sound (recorded in job.json), e.g. --var max_checks 8000")
        parser.add_argument("--no-samples", action="store_true",
                            help="no packings: only the chains (and lattices) asked for")
        parser.add_argument("--chain", action="store_true", help="also the 1D chain (in.chain) into OUT/chain")
        parser.add_argument("--chain-sizes", nargs="+", type=int, default=list(CHAIN_SIZES),
                            help="the chain's N (8 16 ... 2048)")
        parser.add_argument("--chain-poly", nargs="+", type=float, metavar="W",
                            help="also polydisperse chains, diameters uniform in [1 - W, 1 + W], into "
                                 "OUT/chain_poly<W> (Table III, Fig. 7), e.g. 0.05 0.1 0.2")
        parser.add_argument("--chain-poly-sizes", nargs="+", type=int, default=list(CHAIN_POLY_SIZES),
                            help="their N (8 16 ... 512)")
        parser.add_argument("--chain-realizations", type=int, default=100,
                            help="polydisperse chains of each N and W (100)")
        parser.add_argument("--lattice", nargs="+", metavar="P",
                            help="perfect triangular lattices at these pressures, 9 and 29 rows of --width balls, "
                                 "into OUT/lattice_p<P>_M<W> (Figs. 8, 12; c_tof beside Eqs. 18-19)")
        parser.add_argument("--lattice-series", nargs="+", metavar="P",
                            help="triangular lattices of 4 balls per row and --lattice-series-rows rows at these "
                                 "pressures, into OUT/lattice_p<P>_M4 (Figs. 7, 12; Table III)")
        parser.add_argument("--lattice-series-rows", nargs="+", type=int, default=list(LATTICE_SERIES_ROWS),
                            help="their rows (8 16 ... 256)")
        parser.set_defaults(here=here)

    def figures_run_arguments(parser):
        common(parser)
        parser.add_argument("--lmp", default=default_lmp(here), help="LAMMPS (default: build/lammps/lmp)")
        parser.add_argument("--sample", help="the sample's directory name (default: the first at p = 1e-4, H = 25)")
        parser.add_argument("--damping", nargs="+", default=["0.01", "0.03", "0.1", "0.3"],
                            help="fractions of the critical damping of Fig. 11 (0.01 0.03 0.1 0.3)")
        parser.set_defaults(here=here)

    def record_arguments(parser):
        common(parser)
        parser.add_argument("--record", default=os.path.join(here, "record"),
                            help="the record of the study in git (default: examples/sound/record)")
        parser.add_argument("--tables", default="tables.md",
                            help="the file of RECORD that takes OUT's tables (default tables.md); another "
                            "name when OUT holds only part of the study, e.g. tables_H25_seeds1-30.md")

    def migrate_arguments(parser):
        common(parser)
        parser.add_argument("--remove-old", action="store_true",
                            help="delete summary.txt, moduli.txt, checks.txt once converted (record/)")

    return study.main("Paper 003's sound study: run the samples, collect the tables, draw the figures.", {
        "run": (run, "run the samples not yet finished (resumable)", run_arguments),
        "collect": (collect, "results.json and tables.md into OUT, the tables on stdout", common),
        "record": (record, "the finished samples of OUT into the record (job.json, result.json, "
                   "log_summary.txt) and its tables.md", record_arguments),
        "figures": (figures, "the PNG figures", lambda parser: common(parser, figures_too=True)),
        "figures-run": (figures_run, "in.figures on one finished sample: Figs. 3, 10, 11 (about a minute)",
                        figures_run_arguments),
        "migrate": (migrate, "one-off: job.json and result.json for the samples of the old decks",
                    migrate_arguments),
    }, argv)
