"""The avalanche study of examples/avalanche (paper 000) as jobs, and its
command line (examples/avalanche/study.py; acoustic_tools.study's layout).

A job is one LAMMPS run in a directory of its own, named by job_name (the
name is for people: nothing reads it back), with its settings in job.json,
written before LAMMPS starts, and what the deck measured in result.json,
written by the deck at its end (the run adds LAMMPS's total wall time to it):

  deposit  in.deposit: a layer of H/d on its base (free ends, `layer` d
           long on a base 100 d longer, or periodic), with one seed
  ramp     in.avalanche: the tilt ramp of a packing at one frequency, from
           its deposit (or, with switch_on, from a tilt at rest without
           ultrasound to that angle: quiet.json beside result.json)
  tcon     in.avalanche: one angle above theta_m, from the last static
           state of a ramp (paper 000's Fig. 8); tuniform: a longer hold of
           the uniform criterion

A ramp runs as pieces, each a LAMMPS process that pauses after the angle
that ends `piece` simulated seconds after its start; the next piece goes on
from the last whole angle (in.avalanche's TAG.resume), and a piece that was
killed loses what it wrote after that angle (cut_after); pieces.json keeps
when each piece began and ended, so that the wall time of a ramp counts a
killed piece up to its last whole angle (killed_pieces_time).  A finished
job is skipped, so the production is resumed by repeating the command.

  Settings, job_name, deposit_settings, ramp_settings, tcon_settings
                        the settings of each kind of job and its name
  Runner                runs the jobs (mpirun, pieces, the deposit first)
  PRODUCTION            the production sets, as lists of jobs: those of issue 42
                        at the calibrated coupling KAPPA, and those behind
                        RESULTS.md run before the calibration (KAPPA_BEFORE)
  record                job.json and result.json of the finished jobs into record/
  main                  the command line: run, job, demo, collect, figures, record, calibrate
"""
import json
import os
import shutil
import subprocess
import sys
import time

from . import study
from .lammps_log import wall_time

MARGIN = 50               # d of bare base on each side of a free-ends layer
# The coupling of the paper-000 study: the kappa_scale at which the band of
# the 14.4 d free-ends layer (paper 000's Fig. 3) ends at 75 kHz (99.9 % of
# its modes below), `study.py calibrate RESTART OUT.json --band 75e3` on that
# layer's deposit (examples/avalanche/README.md, "The coupling").
KAPPA = 0.17
# The coupling of the sets run before that calibration (RESULTS.md: a
# sensitivity study now).  Job names carry _k<kappa> for any other coupling,
# so that no job of the calibrated study takes the name of one of these.
KAPPA_BEFORE = 0.3
SEEDS = (4871, 1, 2, 3)   # the packings of the periodic set


def _g(x):
    return f"{float(x):g}"


def _number(x):
    """A number as one writes it in a deck: 1e7, 4e8, 0.05 (Python's g without
    the exponent's sign and zeros)."""
    text = f"{float(x):g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        text = f"{mantissa}e{int(exponent)}"
    return text


def _hz(freq):
    """A frequency as the decks' logs write it: 0, 70e3."""
    return "0" if float(freq) == 0 else f"{_g(float(freq) / 1e3)}e3"


def _text(value, spec):
    return "none" if value is None else format(value, spec)


def packing_settings(H, seed, free=1, layer=None, Edem=None, rest=None):
    """The settings that name a packing (acoustic_tools.avalanche_collect.packing_key)."""
    layer = layer if layer is not None else (400 if free else 80)
    return {"H": float(H), "seed": int(seed), "free": int(free), "layer": float(layer),
            "Edem": None if Edem is None else float(Edem), "rest": None if rest is None else float(rest)}


def packing_name(s):
    name = (f"free{_g(s['layer'])}" if s["free"] else f"periodic{_g(s['layer'])}")
    name += f"_E{_number(s['Edem'])}" if s.get("Edem") is not None else ""
    name += f"_e{_number(s['rest'])}" if s.get("rest") is not None else ""
    return f"{name}_H{_g(s['H'])}_s{s['seed']}"


def job_name(s):
    """The directory name of a job (readable; never parsed)."""
    name = packing_name(s) + "_" + ("deposit" if s["kind"] == "deposit" else s["tag"])
    if s["kind"] != "deposit" and float(s.get("kappa", KAPPA_BEFORE)) != KAPPA_BEFORE:
        name += f"_k{_g(s['kappa'])}"
    if s.get("switch_on") is not None:
        name += f"_on{_g(s['switch_on'])}"
    if s["kind"] != "deposit" and s.get("window") is not None:
        name += f"_w{_g(s['window'])}"
    return name


def geometry_variables(s):
    """-var values of the geometry: base length L, covered span and the
    observation window, centred on the layer: `window` d long (s["window"],
    paper 000's 0.4 m is 571 d) or by default the middle half of a
    free-ends layer; a periodic layer is observed whole."""
    if s["free"]:
        L = s["layer"] + 2 * MARGIN
        window = s.get("window") or s["layer"] / 2
        if not 0 < window <= s["layer"]:
            raise ValueError(f"window {window:g} d must lie within the layer ({s['layer']:g} d)")
        lo = (L - window) / (2 * L)
        return {"L": _g(L), "span": f"{s['layer'] / L:.6f}", "obslo": f"{lo:.6f}", "obshi": f"{1 - lo:.6f}"}
    return {"L": _g(s["layer"]), "span": "1", "obslo": "0", "obshi": "1"}


def deposit_settings(packing):
    s = dict(packing, kind="deposit")
    return s


def ramp_settings(packing, freq, kappa=KAPPA, source="bottom", theta0=None, tfollow=1.2, tsettle=0.5,
                  switch_on=None, piece="auto", dumpevery=50, dumplocal=1, window=None, thetamax=30.0):
    """A tilt ramp of a packing at freq Hz; theta0 by default 10 deg, 4 deg
    for H > 10 d at 70 kHz (at KAPPA_BEFORE a thick layer creeps and flows
    low); window: the observation window in d (geometry_variables)."""
    freq = float(freq)
    if theta0 is None:
        theta0 = 4.0 if packing["H"] > 10 and freq > 0 else 10.0
    s = dict(packing, kind="ramp", tag=f"f{_g(freq / 1e3)}", freq=freq, kappa=float(kappa), source=source,
             theta0=float(theta0), tfollow=float(tfollow), tsettle=float(tsettle), thetamax=float(thetamax),
             switch_on=None if switch_on is None else float(switch_on), piece=piece,
             dumpevery=dumpevery, dumplocal=dumplocal)
    if window is not None:
        s["window"] = float(window)
    s["deposit"] = job_name(deposit_settings(packing))
    return s


def snapshot_settings(packing, freq, U0, times, theta=None):
    """Paper 000's snapshots (Figs. 10, 12, 13): the packing tilted at rest
    without ultrasound to theta - 0.5 deg, then at theta with the drive at
    freq Hz and U0 (in d) switched on, held 0.1 s (nothing followed), a
    frame of the grains (with the drive's displacements, dumpq) and of the
    contacts every ms; times: the ms after the tilt to theta that the record
    keeps (avalanche_snapshots)."""
    theta = SNAPSHOT_THETA if theta is None else float(theta)
    s = ramp_settings(packing, freq, theta0=theta, thetamax=theta, tfollow=0, switch_on=theta - 0.5, piece=0,
                      dumpevery=1, dumplocal=1)
    s["quiet_theta0"] = 10.0     # the tilt at rest as the ramps make it (a quick pre-ramp to 14 deg flows)
    s["tuniform"] = SNAPSHOT_UNIFORM    # a flow is followed the whole 0.1 s, not ended when it becomes uniform
    mantissa, exponent = f"{float(U0):.0e}".split("e")
    s.update(kind="snapshot", tag=f"snap_f{_g(float(freq) / 1e3)}_u{mantissa}e{int(exponent)}", U0=float(U0), dumpq=1,
             snapshots=[int(t) for t in times])
    return s


def tcon_settings(ramp, theta, tuniform=None, dumpevery=0):
    """One angle theta above the theta_m of a ramp (its settings), from its
    last static state, followed like any angle of the ramp; dumpevery: ms
    between dump frames (0: none)."""
    tag = f"tcon_{ramp['tag']}_{theta:.1f}" + (f"_u{_g(tuniform)}" if tuniform is not None else "")
    s = {k: ramp[k] for k in ("H", "seed", "free", "layer", "Edem", "rest", "freq", "kappa", "source", "tfollow",
                              "deposit", "window") if k in ramp}
    # setup 0: no set-up of its own before the angle, so that a run at the
    # ramp's next angle repeats it bit for bit (in.avalanche; runs recorded
    # before 7 December 2026 made two and have no "setup" in their job.json)
    s.update(kind="tcon", tag=tag, ramp_tag=ramp["tag"], ramp=job_name(ramp), theta=float(f"{theta:.1f}"),
             tuniform=None if tuniform is None else float(tuniform), switch_on=None, dumpevery=int(dumpevery),
             setup=0)
    return s


def read_resume(path):
    """The resume line of in.avalanche: (theta, time, step, restart, next theta, carry file)."""
    words = open(path).read().split()
    return float(words[0]), float(words[1]), int(words[2]), words[3], words[4], words[5]


PIECES = "pieces.json"    # a ramp's pieces: when each began and ended (Runner.ramp)


def _read_pieces(directory):
    path = os.path.join(directory, PIECES)
    return json.load(open(path)) if os.path.exists(path) else []


def _write_pieces(directory, pieces):
    path = os.path.join(directory, PIECES)
    with open(path + ".part", "w") as f:
        json.dump(pieces, f, indent=1)
        f.write("\n")
    os.replace(path + ".part", path)


def piece_begins(directory, tag):
    """Note that a piece of the ramp in directory begins (pieces.json).  A
    piece before it that never ended was killed: it kept what it wrote up to
    its last whole angle, when it last wrote TAG.resume, so its "kept" wall
    time is from its start to then (0 if it wrote no angle)."""
    pieces = _read_pieces(directory)
    if pieces and pieces[-1].get("end") is None:
        resume = os.path.join(directory, f"{tag}.resume")
        written = os.path.getmtime(resume) if os.path.exists(resume) else 0.0
        pieces[-1]["kept"] = max(0.0, written - pieces[-1]["start"])
    pieces.append({"start": time.time()})
    _write_pieces(directory, pieces)


def piece_ends(directory):
    """Note that the last piece begun in directory ended (its LAMMPS process
    finished and wrote its "Total wall time")."""
    pieces = _read_pieces(directory)
    pieces[-1]["end"] = time.time()
    _write_pieces(directory, pieces)


def killed_pieces_time(directory):
    """The wall time (s) that the killed pieces of the ramp in directory
    spent on what the ramp kept (piece_begins); 0 if none was killed."""
    return sum(p.get("kept", 0.0) for p in _read_pieces(directory))


def cut_after(directory, tag, t, theta, step):
    """Drop what a killed piece wrote after the last whole angle (theta,
    ended at time t and step): the series lines after it (the one of that
    angle's last step stays) and the dump frames after that step."""
    series = os.path.join(directory, f"{tag}.series")
    if os.path.exists(series):
        keep = []
        for line in open(series):
            if line.startswith("#"):
                keep.append(line)
                continue
            words = line.split()
            when, angle = float(words[0]), float(words[1])
            if when < t - 5e-5 or (when < t + 5e-5 and angle == theta):
                keep.append(line)
        with open(series, "w") as f:
            f.writelines(keep)
    for name in (f"{tag}.dump", f"{tag}.contacts"):
        path = os.path.join(directory, name)
        if not os.path.exists(path):
            continue
        with open(path) as f:
            lines = f.readlines()
        keep, on, k = [], True, 0
        while k < len(lines):
            if lines[k].startswith("ITEM: TIMESTEP"):
                on = int(lines[k + 1]) <= step
                if on:
                    keep += lines[k:k + 2]
                k += 2
                continue
            if on:
                keep.append(lines[k])
            k += 1
        with open(path, "w") as f:
            f.writelines(keep)


class Runner:
    """Runs jobs under out with the lmp of build on np MPI ranks, the decks
    of the directory decks (examples/avalanche); say() prints what it does."""

    def __init__(self, build, out, decks, np=2, say=print, max_pieces=None, progress=None, recorded=None):
        self.lmp = os.path.join(os.path.abspath(build), "lammps", "lmp")
        # the record of earlier sessions (examples/avalanche/record): a ramp
        # or t_con run with a result there is done, a deposit never is (its
        # restart file is not recorded)
        self.recorded = os.path.abspath(recorded) if recorded else None
        self.decks = os.path.abspath(decks)
        if not os.access(self.lmp, os.X_OK):
            sys.exit(f"avalanche: no LAMMPS executable at {self.lmp} (build first: ./run.sh build)")
        self.out, self.np, self.say, self.max_pieces, self.progress = os.path.abspath(out), np, say, max_pieces, progress
        self.mpi = study.mpirun(np)
        self.env = dict(os.environ)
        if os.geteuid() == 0:
            self.env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

    def lammps(self, directory, deck, variables, log, contact=None):
        """One LAMMPS process in directory; returns its wall time (s)."""
        args = [*self.mpi, self.lmp, "-nocite", "-echo", "none", "-screen", "none", "-in", os.path.join(self.decks, deck),
                "-var", "dir", self.decks]
        for name, value in list((contact or {}).items()) + list(variables.items()):
            args += ["-var", name, str(value)]
        args += ["-log", log]
        start = time.monotonic()
        process = subprocess.Popen(args, cwd=directory, env=self.env, stdout=subprocess.DEVNULL)
        if self.progress:
            self.progress(os.path.join(directory, log), process)
        process.wait()
        return time.monotonic() - start

    def directory(self, s):
        return os.path.join(self.out, job_name(s))

    def finished(self, s):
        return study.read_result(self.directory(s)) is not None

    def recorded_result(self, s):
        """The result.json of job s in the record, or None (not recorded, or
        no record given)."""
        if self.recorded is None:
            return None
        return study.read_result(os.path.join(self.recorded, job_name(s)))

    @staticmethod
    def contact(s):
        law = {}
        if s.get("Edem") is not None:
            law["Edem"] = _number(s["Edem"])
        if s.get("rest") is not None:
            law["rest"] = _number(s["rest"])
        return law

    def finish(self, directory, logs):
        """Add LAMMPS's total wall time of the job's logs to its result.json,
        and that of its killed pieces up to their last whole angle (they
        write no total: killed_pieces_time)."""
        result = study.read_result(directory)
        result["wall_time"] = sum(wall_time(os.path.join(directory, log)) for log in logs
                                  if os.path.exists(os.path.join(directory, log)))
        killed = killed_pieces_time(directory)
        if killed:
            result["wall_time"] = round(result["wall_time"] + killed)
        path = os.path.join(directory, study.RESULT)
        with open(path + ".part", "w") as f:
            json.dump(result, f, indent=1)
            f.write("\n")
        os.replace(path + ".part", path)
        return result

    def deposit(self, s):
        d = self.directory(s)
        if self.finished(s):
            return d
        study.write_job(d, s)
        geometry = geometry_variables(s)
        self.lammps(d, "in.deposit", {"H": _g(s["H"]), "L": geometry["L"], "free": s["free"], "span": geometry["span"],
                                      "seed": s["seed"], "out": "deposit.restart"}, "log.deposit", self.contact(s))
        r = study.read_result(d)
        if r is None:
            sys.exit(f"avalanche: the deposit {d} failed (log.deposit)")
        self.finish(d, ["log.deposit"])
        self.say(f"{job_name(s)}: {r['grains']} grains on {r['base']}, H = {r['H_measured']} d")
        return d

    def ramp(self, s, again=False):
        """A ramp, piece after piece; returns its result (None if it paused).
        A ramp in the record is skipped unless again (its outputs are
        needed: the t_con runs start from its last static state)."""
        d = self.directory(s)
        name, tag = job_name(s), s["tag"]
        if self.finished(s):
            self.say(f"{name}: done before, skipped")
            return study.read_result(d)
        recorded = None if again else self.recorded_result(s)
        if recorded is not None:
            self.say(f"{name}: recorded before, skipped")
            return recorded
        deposit = self.deposit(deposit_settings({k: s[k] for k in ("H", "seed", "free", "layer", "Edem", "rest")}))
        study.write_job(d, s)
        geometry = geometry_variables(s)
        piece = s["piece"]
        if piece == "auto":
            r = study.read_result(deposit)
            piece = f"{20000 / (r['grains'] + r['base']):.1f}"
        common = {"tag": tag, "freq": _hz(s["freq"]), "kappa": _g(s["kappa"]), "source": s["source"],
                  "tfollow": _g(s["tfollow"]), "tsettle": _g(s["tsettle"]), "thetamax": _g(s["thetamax"]),
                  "obslo": geometry["obslo"], "obshi": geometry["obshi"], "dumpevery": s["dumpevery"],
                  "dumplocal": s["dumplocal"], "tpiece": piece}
        if s.get("U0") is not None:
            common["U0"] = _number(s["U0"])
        if s.get("dumpq"):
            common["dumpq"] = 1
        if s.get("tuniform") is not None:
            common["tuniform"] = _g(s["tuniform"])
        restart = os.path.relpath(os.path.join(deposit, "deposit.restart"), d)
        pieces = 0
        while study.read_result(d) is None:
            if self.max_pieces is not None and pieces >= self.max_pieces:
                theta = read_resume(os.path.join(d, f"{tag}.resume"))[0]
                self.say(f"{name}: paused after {pieces} piece(s), at {theta:.2f} deg; repeat the command to go on")
                return None
            resume = os.path.join(d, f"{tag}.resume")
            piece_begins(d, tag)
            if os.path.exists(os.path.join(d, f"log.{tag}")) and os.path.exists(resume):
                theta, t, step, last, following, carry = read_resume(resume)
                cut_after(d, tag, t, theta, step)
                self.lammps(d, "in.avalanche", dict(common, restart=last, pre=0, theta0=following, append=1,
                                                    carry=carry), f"log.{tag}.resume", self.contact(s))
            else:
                start = {"restart": restart, "theta0": _g(s["theta0"])}
                if s.get("switch_on") is not None and s["freq"] > 0:
                    start = self.quiet(s, d, restart, geometry)
                self.lammps(d, "in.avalanche", dict(common, **start), f"log.{tag}", self.contact(s))
            piece_ends(d)
            pieces += 1
            if study.read_result(d) is None and not os.path.exists(resume):
                sys.exit(f"avalanche: {name} stopped without a result or a resume file (log.{tag})")
        result = self.finish(d, [f"log.{tag}"])
        self.say(f"{name}: theta_m = {result['theta_m']} deg  t_con = {result['t_con']} s  wall {result['wall_time']:.0f} s")
        return result

    def rerun(self, ramp, recorded):
        """Run a recorded ramp again for its last static state (the t_con
        runs start from it; the record keeps no restart files).  The same
        input on the same number of ranks gives the same ramp: its theta_m
        must be the recorded one."""
        self.say(f"{job_name(ramp)}: recorded, but its last static state is not in {self.out}: the ramp runs again")
        again = self.ramp(ramp, again=True)
        if again is None:
            sys.exit(f"avalanche: {job_name(ramp)} paused while it ran again for its t_con runs (--max-pieces)")
        if again.get("theta_m") != recorded.get("theta_m"):
            sys.exit(f"avalanche: {job_name(ramp)} ran again to theta_m = {again.get('theta_m')} deg, recorded "
                     f"{recorded.get('theta_m')} deg: not the same ramp (another build, deck or number of ranks?)")
        return again

    def quiet(self, s, d, restart, geometry):
        """The tilt at rest without ultrasound to switch_on (quiet.json); the
        ramp goes on from its state 0.5 deg higher with ultrasound.  By
        default a quick pre-ramp to switch_on - 0.5 deg, in the job's
        directory; with quiet_theta0 the ramp's protocol from that angle
        (0.5 deg steps, each held) to switch_on, run once for every job of
        the packing that starts there (a directory of its own, shared)."""
        on, start = s["switch_on"], s.get("quiet_theta0")
        where = d if start is None else os.path.join(self.out, f"{packing_name(s)}_quiet{_g(start)}-{_g(on)}")
        os.makedirs(where, exist_ok=True)
        done = os.path.join(where, "quiet.json")
        if start is None or not (os.path.exists(done) and os.path.exists(os.path.join(where, "quiet.static.restart"))):
            self.lammps(where, "in.avalanche",
                        {"tag": "quiet", "freq": 0, "kappa": _g(s["kappa"]), "source": s["source"],
                         "tsettle": _g(s["tsettle"]), "obslo": geometry["obslo"], "obshi": geometry["obshi"],
                         "dumpevery": 0, "restart": os.path.relpath(os.path.join(d, restart), where),
                         "theta0": _g(on if start is None else start), "thetamax": _g(on),
                         "resultfile": "quiet.json"}, "log.quiet", self.contact(s))
        with open(done) as f:
            quiet = json.load(f)
        if where != d:
            shutil.copyfile(done, os.path.join(d, "quiet.json"))
        if not any(a["theta"] == on and a["state"] in ("stable", "stopped") for a in quiet["angles"]):
            sys.exit(f"avalanche: {job_name(s)}: the layer is not at rest at {on:g} deg without ultrasound "
                     f"({done}); switch_on must lie below theta_m at 0 Hz")
        return {"restart": os.path.relpath(os.path.join(where, "quiet.static.restart"), d), "pre": 0,
                "theta0": f"{on + 0.5:.2f}"}

    def tcon(self, ramp, steps=(1, 2, 3), angles=(), tuniform=None, dumpevery=0):
        """The t_con runs of a finished ramp at theta_m + steps and at the
        angles above theta_m; dumpevery: ms between dump frames (0: none)."""
        r = study.read_result(self.directory(ramp)) or self.recorded_result(ramp)
        if r is None or r.get("theta_m") is None:
            self.say(f"{job_name(ramp)}: no theta_m yet (run the ramp first), t_con runs skipped")
            return []
        tm = r["theta_m"]
        thetas = [float(f"{tm + step:.1f}") for step in steps] + [a for a in angles if a > tm + 1e-6]
        static = os.path.join(self.directory(ramp), f"{ramp['tag']}.static.restart")
        pending = [theta for theta in thetas if not self.finished(tcon_settings(ramp, theta, tuniform, dumpevery))
                   and self.recorded_result(tcon_settings(ramp, theta, tuniform, dumpevery)) is None]
        if pending and not os.path.exists(static):
            self.rerun(ramp, r)
        results = []
        for theta in thetas:
            s = tcon_settings(ramp, theta, tuniform, dumpevery)
            d = self.directory(s)
            recorded = None if self.finished(s) else self.recorded_result(s)
            if recorded is not None:
                self.say(f"{job_name(s)}: recorded before, skipped")
                results.append(recorded)
                continue
            if not self.finished(s):
                study.write_job(d, s)
                restart = os.path.relpath(os.path.join(self.directory(ramp), f"{ramp['tag']}.static.restart"), d)
                variables = {"restart": restart, "pre": 0, "setup": s["setup"], "tag": s["tag"], "freq": _hz(s["freq"]),
                             "kappa": _g(s["kappa"]), "source": s["source"], "theta0": f"{theta:.1f}",
                             "thetamax": f"{theta:.1f}", "tfollow": _g(s["tfollow"]),
                             "obslo": geometry_variables(s)["obslo"], "obshi": geometry_variables(s)["obshi"],
                             "dumpevery": s["dumpevery"]}
                if tuniform is not None:
                    variables["tuniform"] = _g(tuniform)
                self.lammps(d, "in.avalanche", variables, f"log.{s['tag']}", self.contact(s))
                if study.read_result(d) is None:
                    sys.exit(f"avalanche: {job_name(s)} failed (log.{s['tag']})")
                res = self.finish(d, [f"log.{s['tag']}"])
                self.say(f"{job_name(s)}: theta_m = {res['theta_m']} deg  t_con = {res['t_con']} s")
            results.append(study.read_result(d))
        return results


# The production sets: each a list of (what, arguments) in the order they
# run; "ramp" takes ramp_settings' arguments, "tcon" a ramp's and
# Runner.tcon's.  First the sets of issue 42, at the calibrated coupling
# KAPPA (examples/avalanche/README.md, "Production sets"), then those run
# before the calibration at KAPPA_BEFORE (RESULTS.md).
THICKNESSES = (3, 6, 8.7, 11.4, 14.4)   # H/d of paper 000's Fig. 7
PACKINGS = (1, 2, 3, 4)                 # the deposit seeds of the free-ends packings
SENSITIVITY = (0.14, 0.21)              # the calibration's +-5 kHz reading of the band top
SENSITIVITY_H = 14.4                    # ... at the layer of the calibration
PAPER_LAYER, PAPER_WINDOW = 2000, 571   # d: paper 000's layers (Table 1's N) and its 0.4 m window
TABLE1 = ((3, 8000), (14.4, 32000))     # (H/d, grains) of paper 000's Table 1 rows measured
TABLE1_THETA = 10.0                     # deg: the angle of the Table 1 runs, below every theta_m
GRAINS_PER_AREA = 0.79 * 4 / 3.141592653589793 / (1 + 0.2 ** 2 / 3)   # in.deposit's grains per d^2 (poly 0.2)
# paper 000's snapshots: H = 14.4 d at 15 deg, the packing whose theta_m
# without ultrasound (18 deg, record/free400_H14.4_s4_f0) lies as far above
# 15 deg as paper 000's (17 deg) or more, so that it rests there before the
# drive; (frequency, U0/d, ms after the tilt kept): Fig. 10 (70 kHz, 51 and
# 52 ms), Fig. 12 (30 kHz, 72 ms), Fig. 13 (70 kHz, U0/d = 1e-3 ... 1e-6,
# 18 ms)
SNAPSHOT_H, SNAPSHOT_SEED, SNAPSHOT_THETA = 14.4, 4, 15.0
SNAPSHOT_UNIFORM = 0.1    # s: the uniform criterion must hold the whole 0.1 s of the angle (in.avalanche: at most twin + tfollow)
# paper 000's Figs. 6, 9, 14: the motion over 1.2 s at theta_m (the fields
# set) and at the angles below it (the ramps' own frames), kept in the record
# as fields.json (avalanche_fields) for the calibrated jobs at these H/d
FIELDS_H, FIELDS_HOLD = (6, 14.4), 1.2
SNAPSHOTS = ((70e3, 1e-5, (18, 51, 52)), (30e3, 1e-5, (72,)), (70e3, 1e-3, (18,)), (70e3, 1e-4, (18,)),
             (70e3, 1e-6, (18,)))


def _periodic(H, seed, layer):
    return packing_settings(H, seed, free=0, layer=layer)


def table1_layer(H, grains):
    """The layer length (d, whole) whose deposit holds about `grains` grains
    at H/d (in.deposit fills H x layer at GRAINS_PER_AREA; the lattice rounds up
    to whole rows)."""
    return float(round(grains / (H * GRAINS_PER_AREA)))


def table1_settings(H, grains, freq):
    """One Table 1 run: the pre-ramp to TABLE1_THETA - 0.5 deg, a hold of at
    most 10 ms, then that angle for exactly 0.1 s (tfollow 0), no dumps, one
    process: the same simulated 0.31 s at 0 and 70 kHz, so that the wall
    times give paper 000's (t70 - t0)/t70."""
    return ramp_settings(packing_settings(H, 1, layer=table1_layer(H, grains)), freq, theta0=TABLE1_THETA,
                         thetamax=TABLE1_THETA, tfollow=0, tsettle=0.01, piece=0, dumpevery=0, dumplocal=0)


def production(name):
    """The jobs of one production set: [("ramp", settings) or ("tcon", (ramp settings, options))]."""
    jobs = []
    free = packing_settings
    if name == "thickness":
        # issue 42: the five thicknesses, four free-ends packings each, at the
        # calibrated coupling, ultrasound on from the start (its pre-ramp too)
        for f in (0, 70e3):
            for H in (6, 14.4, 3, 8.7, 11.4):
                jobs += [("ramp", ramp_settings(free(H, s), f, theta0=10)) for s in PACKINGS]
    elif name == "tcon_cal":
        # t_con at 0 and 70 kHz at 6 d (19 deg), 11.4 and 14.4 d, 1, 2, 3 deg
        # above each packing's theta_m at both frequencies
        for H in (6, 11.4, 14.4):
            for s in PACKINGS:
                jobs += [("tcon", (ramp_settings(free(H, s), f, theta0=10),
                                   {"steps": (1, 2, 3), "angles": (19.0,) if H == 6 else ()})) for f in (0, 70e3)]
    elif name == "sensitivity":
        # the 70 kHz shift at 14.4 d with the band top read 5 kHz lower or
        # higher (kappa_scale 0.14, 0.21); the 0 Hz ramps are the thickness set's.
        # Packing by packing, so that a set stopped part way has both
        # couplings on the packings it ran
        for s in PACKINGS:
            jobs += [("ramp", ramp_settings(free(SENSITIVITY_H, s), 70e3, kappa=k, theta0=10)) for k in SENSITIVITY]
    elif name == "paper_length":
        # one packing at 6 d and one at 14.4 d, 2000 d long, observed over
        # paper 000's 571 d, both frequencies, in pieces (Runner.ramp)
        for H in (6, 14.4):
            jobs += [("ramp", ramp_settings(free(H, 1, layer=PAPER_LAYER), f, theta0=10, window=PAPER_WINDOW))
                     for f in (0, 70e3)]
    elif name == "table1":
        jobs += [("ramp", table1_settings(H, n, f)) for H, n in TABLE1 for f in (0, 70e3)]
    elif name == "fields":
        # Figs. 6, 9 and 14: packing 1 at 6 and 14.4 d held 1.2 s at its
        # theta_m at both frequencies (from the ramp's last static state, the
        # uniform criterion held 1.2 s), with dump frames (fields.json)
        for H in FIELDS_H:
            jobs += [("tcon", (ramp_settings(free(H, 1), f, theta0=10),
                               {"steps": (0,), "tuniform": FIELDS_HOLD, "dumpevery": 50})) for f in (0, 70e3)]
    elif name == "snapshots":
        # Figs. 10, 12, 13: one packing at 15 deg, the drive switched on at rest
        jobs += [("ramp", snapshot_settings(free(SNAPSHOT_H, SNAPSHOT_SEED), f, U0, times))
                 for f, U0, times in SNAPSHOTS]
    elif name in ("periodic", "tcon", "free", "more", "kappa", "kappa_free", "switch_on"):
        jobs = _before(name)
    else:
        raise ValueError(f"unknown production set {name}")
    return jobs


def _before(name):
    """The sets run before the calibration, at KAPPA_BEFORE unless they say
    otherwise (RESULTS.md; kept so that its numbers can be rebuilt)."""
    def ramp(packing, freq, **options):
        return ramp_settings(packing, freq, **dict({"kappa": KAPPA_BEFORE}, **options))

    jobs = []
    if name == "periodic":
        for s in SEEDS:
            jobs += [("ramp", ramp(_periodic(6, s, 80), f)) for f in (0, 70e3)]
            jobs += [("ramp", ramp(_periodic(14.4, s, 40), 0)),
                     ("ramp", ramp(_periodic(14.4, s, 40), 70e3, theta0=6))]
            jobs += [("ramp", ramp(_periodic(3, s, 80), f)) for f in (0, 70e3)]
    elif name == "tcon":
        for s in SEEDS:
            jobs += [("tcon", (ramp(_periodic(6, s, 80), f), {"angles": (19.0,)})) for f in (0, 70e3)]
        for s in (1, 2, 3, 4):
            jobs += [("tcon", (ramp(packing_settings(6, s), f), {"steps": (1,), "angles": (19.0,)}))
                     for f in (0, 70e3)]
        for s in SEEDS:
            jobs += [("tcon", (ramp(_periodic(14.4, s, 40), f, theta0=6 if f else None), {}))
                     for f in (0, 70e3)]
        for H in (11.4, 14.4):
            for s in (1, 2, 3, 4):
                jobs += [("tcon", (ramp(packing_settings(H, s), f), {})) for f in (0, 70e3)]
    elif name == "free":
        for f in (0, 70e3):
            for H in (3, 6, 14.4, 8.7, 11.4):
                jobs += [("ramp", ramp(packing_settings(H, s), f)) for s in (1, 2, 3, 4)]
    elif name == "more":
        for H in (8.7, 11.4):
            for s in SEEDS:
                jobs += [("ramp", ramp(_periodic(H, s, 40), 0)),
                         ("ramp", ramp(_periodic(H, s, 40), 70e3, theta0=6))]
    elif name == "kappa":
        for s in (1, 2):
            jobs += [("ramp", ramp(_periodic(6, s, 80), 70e3, kappa=k)) for k in (0.1, 0.2, 1)]
    elif name == "kappa_free":
        jobs += [("ramp", ramp(packing_settings(8.7, s), 70e3, kappa=k)) for s in (1, 2) for k in (0.1, 0.2)]
        jobs += [("ramp", ramp(packing_settings(8.7, s), 70e3, kappa=0.1)) for s in (3, 4)]
    elif name == "switch_on":
        jobs += [("ramp", ramp(packing_settings(14.4, s), 70e3, switch_on=9.5)) for s in (1, 2, 3, 4)]
        jobs += [("ramp", ramp(packing_settings(14.4, s), 70e3, kappa=0.17, switch_on=10.5)) for s in (1, 3)]
        jobs += [("ramp", ramp(packing_settings(6, s), 70e3, kappa=0.17, switch_on=13)) for s in (1, 2, 3, 4)]
        jobs += [("ramp", ramp(packing_settings(14.4, s), 70e3, kappa=0.17, switch_on=10.5)) for s in (2, 4)]
    return jobs


# issue 42's sets at KAPPA first, then those of RESULTS.md at KAPPA_BEFORE
PRODUCTION = ("thickness", "tcon_cal", "sensitivity", "paper_length", "table1", "snapshots", "fields",
              "periodic", "tcon", "free", "more", "kappa", "kappa_free", "switch_on")


def record(out, dest):
    """Copy job.json, result.json (and quiet.json) of every finished job in
    out into dest/<job>/ (study.record_jobs), and a snapshot job's frames at
    its times cut to the layer's middle (avalanche_snapshots); returns the
    number of jobs written."""
    from .avalanche_fields import write_fields
    from .avalanche_snapshots import write_snapshots
    written = study.record_jobs(out, dest, files=(study.JOB, study.RESULT, "quiet.json"))
    for directory, settings, result in study.finished_jobs(out):
        target = os.path.join(dest, os.path.basename(directory))
        if settings.get("kind") == "snapshot":
            write_snapshots(directory, settings, target)
        elif keeps_fields(settings):
            geometry = geometry_variables(settings)
            write_fields(directory, settings, result, target, (float(geometry["obslo"]), float(geometry["obshi"])))
    return written


def keeps_fields(settings):
    """Whether the record keeps the motion of a job (fields.json): a ramp or
    t_con run at the calibrated coupling at the thicknesses FIELDS_H, free
    ends, ultrasound on from the start, with dump frames."""
    return (settings.get("kind") in ("ramp", "tcon") and float(settings.get("kappa", KAPPA_BEFORE)) == KAPPA
            and any(abs(float(settings.get("H", 0)) - H) < 1e-9 for H in FIELDS_H) and settings.get("free") == 1
            and settings.get("switch_on") is None)


# ---------------------------------------------------------------- command line

def _build(here):
    return os.path.normpath(os.path.join(here, "..", "..", "build"))


def _production(here):
    return os.path.join(here, "out", "production")


def _runner_options(parser, here, out=None):
    out = out or _production(here)
    parser.add_argument("--build", default=_build(here), help="the build directory of ./run.sh (default: build/)")
    parser.add_argument("--out", default=out, help=f"the job directories (default: {os.path.relpath(out)})")
    parser.add_argument("--np", type=int, default=2, help="MPI ranks (default 2)")
    parser.add_argument("--max-pieces", type=int, help="processes per ramp in one call (default: until it ends)")


def job_height(what, job):
    """H/d of a production job ("ramp", settings) or ("tcon", (ramp settings, options))."""
    return (job if what == "ramp" else job[0])["H"]


def selected(jobs, heights=None):
    """The jobs of a production set at the given thicknesses (all if None)."""
    if not heights:
        return list(jobs)
    return [(what, job) for what, job in jobs if any(abs(job_height(what, job) - h) < 1e-9 for h in heights)]


def _run(args):
    recorded = None if args.record == "none" else args.record
    runner = Runner(args.build, args.out, args.decks, args.np, max_pieces=args.max_pieces, recorded=recorded)
    unknown = [name for name in args.sets if name not in PRODUCTION]
    if unknown:
        sys.exit(f"run: unknown set {unknown[0]} ({', '.join(PRODUCTION)})")
    for name in args.sets or ["thickness"]:
        for what, job in selected(production(name), args.heights):
            if what == "ramp":
                runner.ramp(job)
            else:
                ramp, options = job
                runner.tcon(ramp, **options)
    return 0


def _run_arguments(p, here):
    p.add_argument("sets", nargs="*", metavar="SET",
                   help="at the calibrated coupling: thickness (default), tcon_cal, sensitivity, paper_length, "
                        "table1, snapshots, fields; before the calibration: periodic, tcon, free, more, kappa, kappa_free, switch_on "
                        "(examples/avalanche/README.md)")
    _runner_options(p, here)
    p.add_argument("--heights", type=float, nargs="+", metavar="H",
                   help="only the jobs of these thicknesses (H/d), e.g. one thickness per session")
    p.add_argument("--record", default=os.path.join(here, "record"),
                   help="jobs with a result there are done (default examples/avalanche/record; 'none': run them "
                        "all); a recorded ramp runs again when its t_con runs need its last static state")


def _job_arguments(p, here):
    p.add_argument("H", type=float, help="layer thickness / d")
    p.add_argument("seed", type=int)
    p.add_argument("freq", type=float, help="drive frequency (Hz; 0: no ultrasound)")
    _runner_options(p, here)
    p.add_argument("--periodic", action="store_true", help="a periodic layer (default: free ends)")
    p.add_argument("--layer", type=float, help="layer length / d (default 400 with free ends, 80 periodic)")
    p.add_argument("--edem", type=float, help="Young's modulus of the grains (Pa; default in.material's)")
    p.add_argument("--rest", type=float, help="restitution (default in.material's)")
    p.add_argument("--kappa", type=float, default=KAPPA, help=f"kappa_scale (default {KAPPA}, the calibrated one)")
    p.add_argument("--window", type=float, help="observation window / d, centred (default: half the layer; "
                                                "paper 000's 0.4 m is 571)")
    p.add_argument("--source", choices=("bottom", "base"), default="bottom")
    p.add_argument("--theta0", type=float, help="first angle (default 10, 4 for H > 10 d at 70 kHz)")
    p.add_argument("--tfollow", type=float, default=1.2)
    p.add_argument("--tsettle", type=float, default=0.5)
    p.add_argument("--switch-on", type=float, help="tilt at rest without ultrasound to this angle first")
    p.add_argument("--piece", default="auto", help="simulated s per process (auto: 20000 / atoms; 0: one process)")
    p.add_argument("--tcon", action="store_true", help="the t_con runs of the finished ramp instead of the ramp")
    p.add_argument("--tcon-steps", type=float, nargs="*", default=[1, 2, 3], help="deg above theta_m (default 1 2 3)")
    p.add_argument("--tcon-angles", type=float, nargs="*", default=[], help="angles above theta_m")
    p.add_argument("--tuniform", type=float, help="s the sigma criteria must hold in the t_con runs")


def _job(args):
    packing = packing_settings(args.H, args.seed, free=0 if args.periodic else 1, layer=args.layer, Edem=args.edem,
                               rest=args.rest)
    ramp = ramp_settings(packing, args.freq, kappa=args.kappa, source=args.source, theta0=args.theta0,
                         tfollow=args.tfollow, tsettle=args.tsettle, switch_on=args.switch_on, piece=args.piece,
                         window=args.window)
    runner = Runner(args.build, args.out, args.decks, args.np, max_pieces=args.max_pieces)
    if args.tcon:
        runner.tcon(ramp, args.tcon_steps, args.tcon_angles, args.tuniform)
    else:
        runner.ramp(ramp)
    return 0


def _demo_arguments(p, here):
    p.add_argument("--build", default=_build(here))
    p.add_argument("--out", default=os.path.join(here, "out", "demo"))
    p.add_argument("--np", type=int, default=2)
    p.add_argument("--H", type=float, default=6)
    p.add_argument("--L", type=float, default=80)
    p.add_argument("--theta0", type=float, default=10)
    p.add_argument("--source", choices=("bottom", "base"), default="bottom")
    p.add_argument("--tfollow", type=float, default=0.3, help="s (0.3: the demo stays at about 2 minutes; "
                                                              "paper 000's is 1.2)")
    p.add_argument("--tsettle", type=float, default=0.2)
    p.add_argument("--seed", type=int, default=4871)


def _demo(args):
    """The main job: a periodic layer, the ramp at 0 and at 70 kHz, progress
    lines as they come, theta_m at the end."""
    start = time.monotonic()

    def stamp(line):
        print(f"[{time.monotonic() - start:4.0f}s] {line}", flush=True)

    def progress(log, process):
        offset = 0
        while True:
            done = process.poll() is not None
            if os.path.exists(log):
                with open(log) as f:
                    f.seek(offset)
                    text = f.read()
                    cut = text.rfind("\n") + 1
                    offset += len(text[:cut].encode())
                for line in text[:cut].splitlines():
                    if line.startswith(("angle", "avalanche", "deposit:")):
                        stamp(line)
            if done:
                return
            time.sleep(0.5)

    out = os.path.abspath(args.out)
    print(f"avalanche demo: H = {args.H:g} d, L = {args.L:g} d, periodic, source {args.source}, kappa_scale {KAPPA:g} "
          f"(the calibrated coupling), {args.np} MPI ranks, outputs in {out}", flush=True)
    runner = Runner(args.build, out, args.decks, args.np, say=lambda line: None, progress=progress)
    packing = packing_settings(args.H, args.seed, free=0, layer=args.L)
    results = []
    for freq in (0, 70e3):
        s = ramp_settings(packing, freq, source=args.source, theta0=args.theta0, tfollow=args.tfollow,
                          tsettle=args.tsettle, piece=0, dumpevery=20)
        d = runner.directory(s)
        if os.path.exists(d):
            shutil.rmtree(d)          # the demo runs anew
        if freq == 0 and os.path.exists(runner.directory(deposit_settings(packing))):
            shutil.rmtree(runner.directory(deposit_settings(packing)))
        results.append((s, runner.ramp(s)))
    print()
    for s, r in results:
        print(f"result (H = {args.H:g} d): {s['tag']}: freq {_hz(s['freq'])} Hz  theta_m = "
              f"{_text(r['theta_m'], '.2f')} deg  t_con = {_text(r['t_con'], '.3f')} s")
    a0, a70 = (_text(r["theta_m"], ".2f") for _, r in results)
    print(f"theta_m without ultrasound: {a0} deg; with 70 kHz: {a70} deg (paper 000: about 2 deg lower with 70 kHz)")
    print(f"wall time {time.monotonic() - start:.0f} s; job directories (logs, series, dumps) in {out}")
    return 0


def _collect_arguments(p, here):
    p.add_argument("--jobs", default=_production(here), help="the job directories (default: the production's; "
                                               "examples/avalanche/record for the record)")
    p.add_argument("--tables", default=os.path.join(here, "out", "tables"),
                   help="where tables.md, summary.json and the figures' tables go (default out/tables)")


def _collect(args):
    from .avalanche_collect import collect
    sys.stdout.write(collect(args.jobs, args.tables))
    return 0


def _figures_arguments(p, here):
    p.add_argument("--jobs", default=_production(here))
    p.add_argument("--figures", default=os.path.join(here, "figures"),
                   help="where the PNGs go (default examples/avalanche/figures; give another one for the record)")


def _figures(args):
    from .avalanche_collect import figures
    figures(args.jobs, args.figures)
    return 0


def _record_arguments(p, here):
    p.add_argument("--jobs", default=_production(here))
    p.add_argument("--record", default=os.path.join(here, "record"))


def _record(args):
    if not os.path.isdir(args.jobs):
        sys.exit(f"record: no production outputs in {args.jobs} (run the production first)")
    print(f"record: {record(args.jobs, args.record)} jobs from {args.jobs} written to {args.record}")
    return 0


def _calibrate_arguments(p, here):
    from .avalanche_calibration import SCANS, SOURCES
    p.add_argument("restart")
    p.add_argument("output")
    p.add_argument("--freq", type=float, default=70e3)
    p.add_argument("--quick", action="store_true", help="two values per scan (tests)")
    p.add_argument("--scan", choices=sorted(SCANS), help="this parameter only")
    p.add_argument("--values", type=float, nargs="+", help="its values (with --scan)")
    p.add_argument("--sources", choices=SOURCES, nargs="+", default=list(SOURCES))
    p.add_argument("--no-spectrum", action="store_true",
                   help="no eigenmodes and pulse (dense: too costly for thousands of grains)")
    p.add_argument("--band", type=float, metavar="F",
                   help="instead of the scan: the kappa_scale at which 99.9 %% of the modes lie below F Hz "
                        "(kernel polynomial density of states; paper 000: 75e3 on the 14.4 d layer)")


def _calibrate(args):
    from .avalanche_calibration import SCANS, band_calibration, calibration_scan
    if args.band:
        result = band_calibration(os.path.abspath(args.restart), os.path.join(args.decks, "in.material"), args.band,
                                  check=KAPPA)
        result["restart"] = os.path.relpath(os.path.abspath(args.restart), args.decks)   # no machine's path
        with open(args.output, "w") as handle:
            json.dump(result, handle, indent=1)
        ref, at, check = result["reference"], result["at_kappa"], result["at_check"]
        print(f"calibrate: 99.9 % of the modes below {ref['top'] / 1e3:.1f} kHz at kappa_scale {ref['kappa']:g}, "
              f"below {args.band / 1e3:g} kHz at kappa_scale {result['kappa']:.3f} (computed again: "
              f"{at['top'] / 1e3:.1f} kHz); at the study's {KAPPA:g}: {check['top'] / 1e3:.1f} kHz, "
              f"{100 * check['below_75kHz']:.2f} % of the modes below 75 kHz, {100 * check['in_5_45kHz']:.0f} % "
              f"in 5-45 kHz")
        return 0
    if args.values and not args.scan:
        sys.exit("calibrate: --values needs --scan")
    scans = {k: (v[::len(v) - 1] if args.quick else v) for k, v in SCANS.items() if args.scan in (None, k)}
    if args.values:
        scans[args.scan] = args.values
    results = calibration_scan(os.path.abspath(args.restart), os.path.join(args.decks, "in.material"), args.freq, scans,
                               args.sources, spectrum=not args.no_spectrum)
    with open(args.output, "w") as handle:
        json.dump(results, handle, indent=1)
    return 0


COMMANDS = {
    "run": (_run, "the production jobs, set by set (issue 42's at the calibrated coupling, RESULTS.md's before it); "
                  "resumable: repeat until all are there",
            _run_arguments),
    "job": (_job, "one ramp of one packing at one frequency (or, with --tcon, its t_con runs)", _job_arguments),
    "demo": (_demo, "the main job (./run.sh demo): H = 6 d, 80 d, periodic, 0 and 70 kHz", _demo_arguments),
    "collect": (_collect, "the tables: tables.md (also on stdout), summary.json, the figures' tables",
                _collect_arguments),
    "figures": (_figures, "the PNG figures of the jobs", _figures_arguments),
    "record": (_record, "job.json and result.json of the finished jobs into record/ (committed)", _record_arguments),
    "calibrate": (_calibrate, "the calibration scan of a frozen layer through LAMMPS's Python module (JSON; "
                              "python3 -m acoustic_tools.avalanche_figures calibration draws it)",
                  _calibrate_arguments),
}


def main(here, argv=None):
    """examples/avalanche/study.py (here: examples/avalanche, the decks and
    the defaults of the directories)"""
    def with_decks(add_arguments):
        def add(parser):
            add_arguments(parser, here)
            parser.set_defaults(decks=here)
        return add

    commands = {name: (function, text, with_decks(add)) for name, (function, text, add) in COMMANDS.items()}
    return study.main("The avalanche study of examples/avalanche (paper 000): run -> collect -> figures.",
                      commands, argv)
