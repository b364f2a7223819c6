"""The jobs of examples/avalanche (acoustic_tools.avalanche_study runs them)
into the tables and figures of its RESULTS.md; `examples/avalanche/study.py
collect` and `figures` are the command lines.

The jobs are directories, one LAMMPS run each, with the job's settings in
job.json (written by the run command) and what the deck measured in
result.json (written by the deck); acoustic_tools.study reads them.  Nothing
is read from a directory's name.  The settings say what a job is:

  kind       "deposit" (in.deposit), "ramp" (a tilt ramp of in.avalanche) or
             "tcon" (one angle above theta_m from a ramp's last static state)
  H, seed    the packing; with free (1: free ends, 0: periodic), layer (its
             length in d) and the contact law Edem, rest (null: in.material's)
             it names the packing, and a job's deposit is the job named by
             its setting "deposit"
  tag, freq, kappa, switch_on, theta, tuniform, ...
             the ramp's or the run's variables

Reading:

  load, packing_key, geometry, geometries, ensembles, packing
                        the ensembles of ramps, geometry by geometry
  angles, flow_onset, last_mu_factor, first_angle, time_before_onset
                        what a ramp's angles say
  kappa_study, switch_on_study, paired_ramps, coupling_summary
                        the studies beside the packings of a set
  summarise, theta_slope, slope, tcon_one_degree_above, tcon_at_angle,
  tcon_runs_at_angle, tcon_against_hold, mean_with_censored, held_series
                        ensemble statistics
  print_tables, print_kappa, print_switch_on, print_couplings, ...
                        the markdown tables
  calibrated_study, sensitivity_study, table1_study, tcon_above, paper_thetam,
  print_calibrated, write_calibrated_tables
                        the study at the calibrated coupling KAPPA (issue 42's
                        sets: thickness, tcon_cal, sensitivity, paper_length,
                        table1), apart from the sets run before the
                        calibration at SET_KAPPA (a sensitivity study now)
  study_data, write_tables, draw_figures, collect, figures
                        all of it: tables and summary.json, and the figures
"""
import contextlib
import glob
import io
import json
import os
import sys

import numpy as np

from . import avalanche as av
from . import avalanche_figures as figs
from . import study
from .avalanche_study import KAPPA, KAPPA_BEFORE, SENSITIVITY, SENSITIVITY_H
from .lammps_output import read_dump
from .stats import mean_sd

# paper 000, §3.1-3.2 text: H = 3 d: 20 deg without, 14.5 deg with 70 kHz;
# H = 14.4 d: 17 deg without (Fig. 6), flows at 16 deg with 70 kHz (Fig. 9);
# the other values are only drawn in Fig. 7: "about 2 deg lower with 70 kHz";
# theta_m(H/d) falls by about 0.26 deg per d (issue 13's reading of Fig. 7)
PAPER = {3.0: (20.0, 14.5), 14.4: (17.0, np.nan)}
PAPER_SLOPE = -0.26
PAPER_TCON_H6_19DEG = (1.15, 0.30)

PAPER_TCON_ANGLE_H6 = 19.0
DEFAULT_TUNIFORM = 0.01   # s, in.avalanche's uniform hold (its thold)
FOLLOW = 1.3              # s, twin + tfollow: how long a t_con run follows its angle
DEFAULT_LAYER = 400       # d, paper 000's free-ends layer
# kappa_scale of the ensembles in the record so far: the sets run before the
# calibration (avalanche_study.KAPPA_BEFORE); KAPPA, the calibrated coupling
# of the study (avalanche_study.KAPPA), is drawn beside them
SET_KAPPA = KAPPA_BEFORE
# the kappa_scale studies: 70 kHz ramps at another kappa_scale, beside the
# same packings' ramps at SET_KAPPA; one study per boundary condition
# (free: 0 periodic, 1 free ends): (name of its table and figure, label)
KAPPA_STUDIES = {0: ("kappa", "periodic"), 1: ("kappa_free", "free ends")}


def load(top):
    """{name: job} of the finished jobs in top: each job a dict with its
    "name", "dir", "settings" (job.json) and "result" (result.json)."""
    return {os.path.basename(d): {"name": os.path.basename(d), "dir": d, "settings": s, "result": r}
            for d, s, r in study.finished_jobs(top)}


def _jobs(top_or_jobs):
    return load(top_or_jobs) if isinstance(top_or_jobs, (str, os.PathLike)) else top_or_jobs


def geometry(settings):
    """The geometry of a job's packing: (free, layer, Edem, rest); the length
    of a periodic layer is not part of it (the periodic set has 80 d and
    40 d layers)."""
    free = int(settings.get("free", 1))
    return (free, float(settings.get("layer", DEFAULT_LAYER)) if free else None,
            settings.get("Edem"), settings.get("rest"))


def packing_key(settings):
    """What names a packing: its geometry, H and seed."""
    return geometry(settings) + (float(settings["H"]), str(settings["seed"]))


def geometry_label(key):
    """"periodic" or "free ends, <layer> d", with the contact law when it is not in.material's."""
    free, layer, modulus, restitution = key
    label = f"free ends, {layer:g} d" if free else "periodic"
    label += f", E = {float(modulus):g} Pa" if modulus is not None else ""
    label += f", restitution {float(restitution):g}" if restitution is not None else ""
    return label


def _geometry_order(key):
    free, layer, modulus, restitution = key
    default = modulus is None and restitution is None
    first = 0 if (not free and default) else 1 if (free and layer == DEFAULT_LAYER and default) else 2
    return (first, free, layer or 0, float(modulus or 0), float(restitution or 0))


def geometries(top, kappa=SET_KAPPA):
    """(geometry, label) of the ensembles among the jobs at kappa_scale
    kappa: the periodic set, the free-ends set (400 d), then the others
    (another length, another contact law) by length, modulus and
    restitution."""
    keys = {geometry(j["settings"]) for j in _jobs(top).values() if _in_ensemble(j, kappa)}
    return [(key, geometry_label(key)) for key in sorted(keys, key=_geometry_order)]


def _in_ensemble(job, kappa=SET_KAPPA):
    """A ramp or t_con run of the ensembles at kappa_scale kappa (by default
    the set's), ultrasound on from the start (no switch-on), not a run of
    one angle (Table 1's, one_angle)."""
    s = job["settings"]
    return (s.get("kind") in ("ramp", "tcon") and float(s.get("kappa", SET_KAPPA)) == kappa
            and s.get("switch_on") is None and not one_angle(s))


def one_angle(settings):
    """A ramp that holds one angle and follows nothing after the window
    (theta0 = thetamax, tfollow 0: avalanche_study.table1_settings), a
    measurement of the cost, not of theta_m."""
    s = settings
    return (s.get("kind") == "ramp" and s.get("thetamax") is not None and s.get("theta0") is not None
            and float(s["theta0"]) == float(s["thetamax"]) and float(s.get("tfollow", 1.2)) == 0)


def result(job):
    """(theta_m, t_con) of a ramp or t_con job; nan when absent or none."""
    if job is None:
        return np.nan, np.nan
    r = job["result"]
    tm = r.get("theta_m")
    if tm is None:
        return np.nan, np.nan
    tc = r.get("t_con")
    return float(tm), float(tc) if tc is not None else np.nan


def deposit(jobs, job):
    """(grains, base grains, measured H/d, length/d) of the deposit of a ramp
    or t_con job; zeros and nan when its deposit has not finished."""
    d = jobs.get(job["settings"].get("deposit", ""))
    if d is None:
        return 0, 0, np.nan, np.nan
    r = d["result"]
    return int(r["grains"]), int(r["base"]), float(r["H_measured"]), float(r["length"])


def _wall(job):
    return float(job["result"].get("wall_time", np.nan)) if job else np.nan


def packing(jobs, ramps, tcons):
    """Everything about one packing: its ramps {tag: job} at the set's
    kappa_scale and its t_con runs (jobs)."""
    any_job = next(iter(ramps.values()))
    s = any_job["settings"]
    n, nb, hm, length = deposit(jobs, any_job)
    p = {"dirs": {tag: j["dir"] for tag, j in ramps.items()}, "seed": str(s["seed"]), "grains": n, "base": nb,
         "H_measured": hm, "length": length, "deposit": s.get("deposit"), "window": s.get("window")}
    for tag in ("f0", "f70"):
        job = ramps.get(tag)
        p[tag] = result(job)
        p[f"{tag}_wall"] = _wall(job)
        p[f"{tag}_rest"] = job["result"].get("settled", "") if job else ""
        p[f"{tag}_onset"] = flow_onset(job) if job and np.isfinite(p[tag][0]) else np.nan
        runs = sorted(((float(t["settings"]["theta"]), t["settings"].get("tuniform"), t) for t in tcons
                       if t["settings"].get("ramp_tag") == tag), key=lambda r: (r[0], r[1] is not None, r[1] or 0))
        p[f"tcon_{tag}"] = [(theta, result(t)[1]) for theta, hold, t in runs if hold is None]
        p[f"tcon_{tag}_held"] = sorted((float(hold), theta, result(t)[1], t["dir"], t["settings"]["tag"])
                                       for theta, hold, t in runs if hold is not None)
    p["other"] = sorted((float(j["settings"]["freq"]) / 1e3,) + result(j) + (flow_onset(j), last_mu_factor(j))
                        for tag, j in ramps.items() if tag not in ("f0", "f70") and np.isfinite(result(j)[0]))
    return p


def ensembles(top, kappa=SET_KAPPA):
    """{geometry label: {H: [packings]}} for the geometries present: the
    ramps at kappa_scale kappa (by default the set's) without switch-on,
    grouped by packing; a packing needs its deposit and theta_m at 0 or 70
    kHz."""
    jobs = _jobs(top)
    by_packing = {}
    for job in jobs.values():
        if not _in_ensemble(job, kappa):
            continue
        s = job["settings"]
        ramps, tcons = by_packing.setdefault(packing_key(s), ({}, []))
        if s["kind"] == "ramp":
            ramps[s["tag"]] = job
        else:
            tcons.append(job)
    out = {}
    for key, label in geometries(jobs, kappa):
        by_h = {}
        for pkey in sorted((k for k in by_packing if k[:4] == key), key=lambda k: (k[4], k[5])):
            ramps, tcons = by_packing[pkey]
            if not ramps or jobs.get(next(iter(ramps.values()))["settings"].get("deposit", "")) is None:
                continue
            p = packing(jobs, ramps, tcons)
            if np.isfinite(p["f0"][0]) or np.isfinite(p["f70"][0]):
                by_h.setdefault(pkey[4], []).append(p)
        if by_h:
            out[label] = by_h
    return out


def angles(job):
    """[(angle, state, time followed (s), mean mu*/mu at its end)] of the
    tested angles of a ramp or t_con job, in order."""
    return [(float(a["theta"]), a["state"], float(a["time"]), float(a["mu"])) for a in job["result"]["angles"]]


def flow_onset(job):
    """The first angle of a ramp that ended with a flow: partial (more than
    half of the observed grains still mobile after 0.1 + tfollow s, not
    uniform) or uniform; nan if none.  It is at or below theta_m."""
    for theta, state, _, _ in angles(job):
        if state in ("partial", "uniform"):
            return theta
    return np.nan


def last_mu_factor(job):
    """mean mu*/mu at the end of the last angle before theta_m (nan if none)."""
    values = [mu for _, state, _, mu in angles(job) if state != "uniform"]
    return values[-1] if values else np.nan


def first_angle(job):
    """The first tested angle of a ramp (nan if none)."""
    lines = angles(job)
    return lines[0][0] if lines else np.nan


def time_before_onset(job):
    """Simulated time (s) the layer was followed at the tested angles before
    the first spreading flow (nan without a flow); under 70 kHz it creeps
    all that time (the pre-ramp and its hold, at most tsettle, come on top)."""
    lines = angles(job)
    spreading = [i for i, (_, state, _, _) in enumerate(lines) if state in ("partial", "uniform")]
    return sum(t for _, _, t, _ in lines[:spreading[0]]) if spreading else np.nan


def _ramps_by_packing(jobs, kappa=SET_KAPPA):
    """{packing key: {tag: ramp job}} of the ensembles' ramps at kappa_scale kappa."""
    found = {}
    for job in jobs.values():
        if _in_ensemble(job, kappa) and job["settings"]["kind"] == "ramp":
            found.setdefault(packing_key(job["settings"]), {})[job["settings"]["tag"]] = job
    return found


def paired_ramps(jobs, ramps, kappa=SET_KAPPA):
    """(ramp, the same packing's ramps {tag: job} in its ensemble at
    kappa_scale kappa) for every ramp of a study.  A packing whose deposit
    differs from the ensemble's (grains, base, H, length) is not the same
    packing: it is left out, with a note on stderr."""
    reference = _ramps_by_packing(jobs, kappa)
    pairs = []
    for job in sorted(ramps, key=lambda j: j["name"]):
        ref = reference.get(packing_key(job["settings"]))
        ref_job = next(iter(ref.values()), None) if ref else None
        if ref_job is None or jobs.get(ref_job["settings"].get("deposit", "")) is None or \
                deposit(jobs, job) != deposit(jobs, ref_job):
            print(f"collect: {job['dir']} left out: its deposit is not that of its ensemble's packing "
                  f"({ref_job['dir'] if ref_job else 'none'})", file=sys.stderr)
            continue
        pairs.append((job, ref))
    return pairs


def _study_key(job):
    s = job["settings"]
    return (float(s["H"]), str(s["seed"]))


def kappa_study(top, free=0):
    """Rows (kappa, H, seed, theta_m 0 Hz, theta_m 70 kHz, shift, mean mu*/mu
    below theta_m, shift of the first spreading flow) of the 70 kHz ramps at
    a kappa_scale other than the set's (no switch-on) with free ends (free
    1) or periodic (free 0), each beside the same packing's ramps at the
    set's kappa_scale (paired_ramps).  The ramps of the calibrated study
    (kappa_scale KAPPA and the sensitivity set's, calibrated_study) are
    not part of it."""
    jobs = _jobs(top)
    study_ramps = [j for j in jobs.values() if j["settings"].get("kind") == "ramp"
                   and j["settings"].get("tag") == "f70" and j["settings"].get("switch_on") is None
                   and float(j["settings"].get("kappa", SET_KAPPA)) not in (SET_KAPPA, KAPPA) + tuple(SENSITIVITY)
                   and int(j["settings"].get("free", 1)) == free]
    rows = {}                 # (kappa, H, seed) -> row: the reference ramps appear once
    for job, ref in paired_ramps(jobs, study_ramps):
        H, seed = _study_key(job)
        t0 = result(ref.get("f0"))[0]
        onset0 = flow_onset(ref["f0"]) if "f0" in ref else np.nan
        for k, ramp in ((SET_KAPPA, ref.get("f70")), (float(job["settings"]["kappa"]), job)):
            if ramp is not None and np.isfinite(result(ramp)[0]):
                t70 = result(ramp)[0]
                rows[(k, H, seed)] = (k, H, seed, t0, t70, t0 - t70, last_mu_factor(ramp), onset0 - flow_onset(ramp))
    return [rows[key] for key in sorted(rows)]


def switch_on_study(top):
    """Rows (H, seed, kappa_scale, first tested angle, theta_m 0 Hz, theta_m
    70 kHz, first spreading flow at 70 kHz, time followed at the angles
    before it (s), mean mu*/mu before theta_m) of the 70 kHz ramps switched
    on at rest (setting switch_on) and of the same packings' ramps in their
    ensemble (ultrasound on from the pre-ramp), sorted by H, packing,
    kappa_scale and first angle: does the creep at the angles before the
    flow lower theta_m?"""
    jobs = _jobs(top)
    late = [j for j in jobs.values() if j["settings"].get("kind") == "ramp"
            and j["settings"].get("tag") == "f70" and j["settings"].get("switch_on") is not None]
    rows = {}
    for job, ref in paired_ramps(jobs, late):
        H, seed = _study_key(job)
        t0 = result(ref.get("f0"))[0]
        for ramp in (ref.get("f70"), job):
            if ramp is None:
                continue
            t70 = result(ramp)[0]
            if np.isfinite(t70):
                key = (H, seed, float(ramp["settings"]["kappa"]), first_angle(ramp))
                rows[key] = key + (t0, t70, flow_onset(ramp), time_before_onset(ramp), last_mu_factor(ramp))
    return [rows[key] for key in sorted(rows, key=lambda k: (k[0], int(k[1]), k[2], k[3]))]


def coupling_summary(rows):
    """theta_m at 70 kHz of the switch-on ramps at couplings other than the
    ensembles' (switch_on_study rows): {kappa_scale: [(H, (mean, s.d.,
    count) of theta_m, (mean, s.d., count) of the shift from the same
    packing's theta_m at 0 Hz)]}, by H."""
    groups = {}
    for H, _, kappa, _, t0, t70, *_ in rows:
        if kappa != SET_KAPPA:
            groups.setdefault(kappa, {}).setdefault(H, []).append((t70, t0 - t70))
    return {kappa: [(H, mean_sd([t for t, _ in v]), mean_sd([d for _, d in v])) for H, v in sorted(by_h.items())]
            for kappa, by_h in sorted(groups.items())}


def tcon_one_degree_above(packs, tag):
    """(mean, s.d., count) of t_con in the runs one degree above each
    packing's theta_m (paper 000 Fig. 8's first angle above theta_m); a run
    that never became uniform is not counted."""
    return mean_sd([t for p in packs for th, t in p[f"tcon_{tag}"] if th == p[tag][0] + 1.0])


def tcon_runs_at_angle(packs, tag, theta):
    """t_con of every run at the angle theta, packing by packing (nan for a
    run that never became uniform), the ramp's own t_con counted where its
    theta_m is theta (the ramp tilted it there from the angle before, at
    rest or not, as a t_con run does from the last static state: Fig. 8
    draws both)."""
    return [t for p in packs for th, t in [p[tag]] + p[f"tcon_{tag}"] if th == theta]


def tcon_at_angle(packs, tag, theta):
    """(mean, s.d., count) of t_con in the runs at the angle theta (paper 000
    gives t_con at 19 deg for H = 6 d; tcon_runs_at_angle); a run that never
    became uniform is not counted."""
    return mean_sd(tcon_runs_at_angle(packs, tag, theta))


def tcon_against_hold(packs, tag, theta):
    """t_con at the angle theta for each hold time of the uniform criterion
    (in.avalanche's tuniform; the t_con runs with the setting tuniform):
    [(hold, [t_con of each run, packing by packing])], the default hold
    first (tcon_runs_at_angle); nan for a run that was not uniform within
    0.1 + tfollow s."""
    rows = [(DEFAULT_TUNIFORM, tcon_runs_at_angle(packs, tag, theta))]
    held = [(h, t) for p in packs for h, th, t, *_ in p[f"tcon_{tag}_held"] if th == theta]
    for hold in sorted({h for h, _ in held}):
        rows.append((hold, [t for h, t in held if h == hold]))
    return rows


def mean_with_censored(times, hold, follow=FOLLOW):
    """Mean t_con with each run that was not uniform within `follow` s
    counted at follow - hold, the latest t_con it could have shown: a
    lower bound of the mean when some runs are censored."""
    return float(np.mean([t if np.isfinite(t) else follow - hold for t in times]))


def slope(points):
    """Least-squares slope of theta against the measured H/d over (target H,
    measured H, theta) points of all packings, with its standard error; nan
    unless there are two target thicknesses or more."""
    pts = np.array([p for p in points if np.all(np.isfinite(p))])
    if len(pts) < 4 or len(np.unique(pts[:, 0])) < 2:
        return np.nan, np.nan
    (a, b), cov = np.polyfit(pts[:, 1], pts[:, 2], 1, cov=True)
    return float(a), float(np.sqrt(cov[0, 0]))


def summarise(by_h):
    """(rows, slope at 0 kHz, slope at 70 kHz) of one geometry ({H:
    [packings]}): a row per H with the count of packings, the measured H/d,
    (mean, s.d., count) of theta_m, its shift, the first spreading flow and
    its shift, t_con, the mean wall times, the layer's size and the packings
    at rest before the ramp; the slopes of theta_m(H/d) (theta_slope)."""
    rows = []
    for H, packs in sorted(by_h.items()):
        t0 = [p["f0"][0] for p in packs]
        t70 = [p["f70"][0] for p in packs]
        shift = [a - b for a, b in zip(t0, t70) if np.isfinite(a) and np.isfinite(b)]
        o0 = [p["f0_onset"] for p in packs]
        o70 = [p["f70_onset"] for p in packs]
        oshift = [a - b for a, b in zip(o0, o70) if np.isfinite(a) and np.isfinite(b)]
        rows.append({"H": H, "n": len(packs),
                     "H_measured": mean_sd([p["H_measured"] for p in packs])[0],
                     "theta0": mean_sd(t0), "theta70": mean_sd(t70), "shift": mean_sd(shift),
                     "onset0": mean_sd(o0), "onset70": mean_sd(o70), "onset_shift": mean_sd(oshift),
                     "tcon0": mean_sd([p["f0"][1] for p in packs]), "tcon70": mean_sd([p["f70"][1] for p in packs]),
                     "wall0": mean_sd([p["f0_wall"] for p in packs])[0],
                     "wall70": mean_sd([p["f70_wall"] for p in packs])[0],
                     "grains": packs[0]["grains"], "base": packs[0]["base"], "length": packs[0]["length"],
                     "at_rest": sum(p["f0_rest"] == "at rest" for p in packs)})
    return rows, theta_slope(by_h, "f0"), theta_slope(by_h, "f70")


def theta_slope(by_h, tag, h_min=0.0):
    """slope of theta_m (ramp tag) against the measured H/d over the packings
    of the target thicknesses >= h_min, with its standard error"""
    return slope([(H, p["H_measured"], p[tag][0]) for H, packs in by_h.items() if H >= h_min for p in packs])


def fmt(ms, digits=2):
    """A (mean, s.d., count) as "mean ± s.d." (the mean alone without a
    s.d.), or a dash without a mean."""
    m, s, n = ms
    if not np.isfinite(m):
        return "—"
    return f"{m:.{digits}f} ± {s:.{digits}f}" if np.isfinite(s) else f"{m:.{digits}f}"


def standard_error(ms):
    """The standard error of the mean of a (mean, s.d., count), as fmt takes it."""
    m, s, n = ms
    return (s / np.sqrt(n) if n > 1 else np.nan, np.nan, 1)


def num(x, spec="g"):
    """x formatted by spec, or a dash when it was not measured (nan)."""
    return format(x, spec) if np.isfinite(x) else "—"


def slope_text(ms):
    """a fitted slope and its standard error in deg/d, or a dash without data."""
    return f"{ms[0]:+.3f} ± {ms[1]:.3f} °/d" if np.isfinite(ms[0]) else "—"


def print_slopes(by_h, s0, s70):
    """The slopes of theta_m(H/d) at 0 and 70 kHz over all packings (s0,
    s70: theta_slope's) and from H = 6 d up, beside paper 000's, on stdout."""
    print(f"\nslope of θ_m(H/d), all packings: 0 kHz {slope_text(s0)}, "
          f"70 kHz {slope_text(s70)} (paper 000 ≈ {PAPER_SLOPE}°/d)")
    t0, t70 = theta_slope(by_h, "f0", 6.0), theta_slope(by_h, "f70", 6.0)
    print(f"the same from H = 6 d up (paper 000's grey zone of Fig. 7 left out): 0 kHz {slope_text(t0)}, "
          f"70 kHz {slope_text(t70)}")


def print_tables(all_ens, summary):
    """The markdown tables and lists of each geometry on stdout: theta_m,
    its shift and t_con per H (summary: summarise of each geometry), the
    first spreading flows, the slopes, each packing, the other drive
    frequencies, the t_con runs and t_con against the hold time."""
    for label, by_h in all_ens.items():
        rows, s0, s70 = summary[label]
        print(f"\n### {label}\n")
        print("| H/d (measured) | packings | grains + base, length | θ_m 0 kHz | θ_m 70 kHz | shift (s.e.) "
              "| t_con at θ_m, 0 / 70 kHz (s) | paper 000 θ_m 0 / 70 kHz | wall time per ramp 0 / 70 kHz (s) |")
        print("|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            p = PAPER.get(r["H"])
            trend = 20.0 + PAPER_SLOPE * (r["H"] - 3.0)
            ptxt = (f"{p[0]:g} / {p[1]:g}" if p and np.isfinite(p[1]) else f"{p[0]:g} / ≈ {p[0] - 2:g}" if p
                    else f"≈ {trend:.1f} / ≈ {trend - 2:.1f} (Fig. 7)")
            print(f"| {r['H']:g} ({r['H_measured']:.2f}) | {r['n']} | {r['grains']} + {r['base']}, {r['length']:g} d "
                  f"| {fmt(r['theta0'])}° | {fmt(r['theta70'])}° | {fmt(r['shift'])}° ({fmt(standard_error(r['shift']))}°) "
                  f"| {fmt(r['tcon0'])} / {fmt(r['tcon70'])} | {ptxt} | {num(r['wall0'], '.0f')} / {num(r['wall70'], '.0f')} |")
        print("\nfirst angle with a flow that spreads (partial or uniform), mean ± s.d.:")
        for r in rows:
            print(f"- H = {r['H']:g} d: 0 kHz {fmt(r['onset0'])}°, 70 kHz {fmt(r['onset70'])}°, "
                  f"shift {fmt(r['onset_shift'])}° (s.e. {fmt(standard_error(r['onset_shift']))}°)")
        print_slopes(by_h, s0, s70)
        print("\nper packing (seed: θ_m 0 / 70 kHz, t_con 0 / 70 kHz, first spreading flow 0 / 70 kHz):")
        for H, packs in sorted(by_h.items()):
            print(f"- H = {H:g} d: " + "; ".join(
                f"s{p['seed']}: {num(p['f0'][0])} / {num(p['f70'][0])}°, {num(p['f0'][1], '.2f')} / "
                f"{num(p['f70'][1], '.2f')} s, {num(p['f0_onset'])} / {num(p['f70_onset'])}°" for p in packs))
        print_other_frequencies(by_h)
        tc = [(H, tag, th, t) for H, packs in sorted(by_h.items()) for p in packs
              for tag in ("f0", "f70") for th, t in p[f"tcon_{tag}"]]
        if tc:
            print("\nt_con above θ_m (one run per angle, from the last static state of the ramp; "
                  "—: no uniform flow within 1.3 s):")
            for H in sorted({h for h, *_ in tc}):
                for tag in ("f0", "f70"):
                    pts = sorted((th, t) for h, g, th, t in tc if h == H and g == tag)
                    if pts:
                        print(f"- H = {H:g} d, {tag[1:]} kHz: " + ", ".join(f"{th:g}° {num(t, '.2f')} s"
                                                                            for th, t in pts))
            print("\nt_con one degree above θ_m, mean ± s.d. (runs):")
            for H in sorted({h for h, *_ in tc}):
                m0, m70 = (tcon_one_degree_above(by_h[H], tag) for tag in ("f0", "f70"))
                print(f"- H = {H:g} d: 0 kHz {fmt(m0)} s ({m0[2]}), 70 kHz {fmt(m70)} s ({m70[2]})")
            if 6.0 in by_h:
                a = PAPER_TCON_ANGLE_H6
                m0, m70 = (tcon_at_angle(by_h[6.0], tag, a) for tag in ("f0", "f70"))
                print(f"\nt_con at {a:g}° and H = 6 d, mean ± s.d. (runs): 0 kHz {fmt(m0)} s ({m0[2]}), "
                      f"70 kHz {fmt(m70)} s ({m70[2]}); paper 000 {PAPER_TCON_H6_19DEG[0]:g} / "
                      f"{PAPER_TCON_H6_19DEG[1]:g} s")
        print_tcon_against_hold(by_h)


def print_tcon_against_hold(by_h):
    """t_con against the hold time of the uniform criterion, at the angles
    where runs with another hold (setting tuniform) are there."""
    cases = sorted({(H, tag, th) for H, packs in by_h.items() for p in packs
                    for tag in ("f0", "f70") for _, th, *_ in p[f"tcon_{tag}_held"]})
    if not cases:
        return
    print("\nt_con against the time the σ criteria must hold (tuniform): the runs packing by packing "
          "(—: not uniform within 1.3 s), their mean ± s.d., and the mean with those counted at 1.3 s − hold:")
    for H, tag, theta in cases:
        print(f"- H = {H:g} d, {tag[1:]} kHz, {theta:g}°:")
        for hold, times in tcon_against_hold(by_h[H], tag, theta):
            ms = mean_sd(times)
            bound = f", ≥ {mean_with_censored(times, hold):.2f} s" if ms[2] < len(times) else ""
            print(f"  - {hold:g} s: " + ", ".join(num(t, ".2f") for t in times) + f" s: {fmt(ms)} s{bound}")


def thetam_table(rows):
    """Fig. 7's table of summarise's rows: H/d, theta_m mean and s.d. at 0
    and 70 kHz, paper 000's values."""
    return [(r["H_measured"], r["theta0"][0], r["theta0"][1], r["theta70"][0], r["theta70"][1])
            + PAPER.get(r["H"], (np.nan, np.nan)) for r in rows]


def tcon_rows(all_ens, label, free):
    """Rows ("H<H>_<f>kHz[_free_ends]", theta, t_con, kind) of Fig. 8:
    theta_m (kind "thetam": the ramp's own flow) and the t_con runs (kind
    "run") of every packing at H = 6, 11.4 and 14.4 d, each geometry once
    (label: the first geometry; free: the free-ends one, may be the same)."""
    geometries = [(label, "_free_ends" if label.startswith("free") else "")]
    if free and free != label:
        geometries.append((free, "_free_ends"))
    rows = []
    for geometry, suffix in geometries:
        for H in (6.0, 11.4, 14.4):
            for p in all_ens.get(geometry, {}).get(H, []):
                for tag in ("f0", "f70"):
                    runs = [(p[tag][0], p[tag][1], "thetam")] + [(th, t, "run") for th, t in p[f"tcon_{tag}"]]
                    for th, t, kind in runs:
                        if np.isfinite(th) and np.isfinite(t):
                            rows.append((f"H{H:g}_{tag[1:]}kHz{suffix}", th, t, kind))
    return rows


def tcon_table_lines(all_ens, label, free):
    """The rows of tcon_rows as lines "H<H>_<f>kHz[_free_ends] theta t_con kind"."""
    return [f"{name} {th:g} {t:g} {kind}\n" for name, th, t, kind in tcon_rows(all_ens, label, free)]


def _table_text(rows):
    return "".join(" ".join(f"{v:g}" for v in row) + "\n" for row in rows)


# ------------------------------------------------ the study at the calibrated coupling
# issue 42's production sets at kappa_scale KAPPA (avalanche_study.production:
# thickness, tcon_cal, sensitivity, paper_length, table1), read like the
# others from job.json and result.json: the ensembles at KAPPA (ensembles(top,
# KAPPA)), the sensitivity set's 70 kHz ramps at the other readings of the
# band top, and the one-angle runs of Table 1.

# paper 000 Table 1: (t70 - t0)/t70 for N grains (its +49 % and +26 %)
PAPER_TABLE1 = {8000: 0.49, 32000: 0.26}
TCON_STEPS = (1.0, 2.0, 3.0)   # deg above each packing's theta_m (the tcon_cal set)
CALIBRATED_LABEL = f"kappa_scale {KAPPA:g} (the calibrated coupling)"
BEFORE_LABEL = f"kappa_scale {SET_KAPPA:g} (run before the calibration: sensitivity study)"


def paper_thetam(H):
    """paper 000's theta_m at 0 and 70 kHz and its shift at the target H/d,
    as texts that say where each comes from: stated in its text (3 d: 20
    and 14.5 deg; 14.4 d: 17 deg) or interpolated as Fig. 7 draws them (0
    kHz on the straight line through 20 deg at 3 d and 17 deg at 14.4 d,
    70 kHz 2 deg below the 0 kHz value, its "about 2 deg lower")."""
    t0, t70 = PAPER.get(float(H), (np.nan, np.nan))
    line = 20.0 + (17.0 - 20.0) * (float(H) - 3.0) / (14.4 - 3.0)
    zero = f"{t0:g} (stated)" if np.isfinite(t0) else f"≈ {line:.1f} (interpolated)"
    base = t0 if np.isfinite(t0) else line
    seventy = f"{t70:g} (stated)" if np.isfinite(t70) else f"≈ {base - 2:.1f} (interpolated)"
    shift = f"{t0 - t70:g} (stated)" if np.isfinite(t0) and np.isfinite(t70) else "≈ 2 (its text)"
    return zero, seventy, shift


def with_error(ms, digits=2):
    """"mean ± s.d. (s.e.)" of a (mean, s.d., count); the mean alone, or a dash."""
    se = standard_error(ms)
    return fmt(ms, digits) + (f" ({fmt(se, digits)})" if np.isfinite(se[0]) else "")


def tcon_above(packs, tag, step):
    """t_con of each packing's t_con run `step` deg above its own theta_m at
    the ramp tag (nan: not uniform within 0.1 + tfollow s); packings
    without such a run are not listed.  The angle is theta_m + step to
    0.1 deg, as avalanche_study.tcon_settings writes it."""
    return [t for p in packs if np.isfinite(p[tag][0])
            for th, t in p[f"tcon_{tag}"] if abs(th - float(f"{p[tag][0] + step:.1f}")) < 1e-6]


def times_text(times):
    """mean ± s.d. of t_con runs with their count, and how many were not
    uniform (nan) within the time followed; a dash without runs."""
    ms = mean_sd(times)
    if not times:
        return "—"
    missing = len(times) - ms[2]
    return f"{fmt(ms)} s ({ms[2]}" + (f"; {missing} not uniform within {FOLLOW:g} s" if missing else "") + ")"


def sensitivity_study(top):
    """Rows (kappa, H, seed, theta_m 0 Hz, theta_m 70 kHz, shift, mean
    mu*/mu before theta_m, shift of the first spreading flow) of the 70 kHz
    ramps of the SENSITIVITY_H d free-ends packings (400 d, in.material's
    contact law) at KAPPA and at the sensitivity set's couplings
    (SENSITIVITY), each beside the same packing's 0 Hz ramp at KAPPA
    (paired_ramps); none without a ramp at one of SENSITIVITY."""
    jobs = _jobs(top)
    kappas = set(SENSITIVITY) | {KAPPA}
    ramps = [j for j in jobs.values() if j["settings"].get("kind") == "ramp" and j["settings"].get("tag") == "f70"
             and j["settings"].get("switch_on") is None and not one_angle(j["settings"])
             and j["settings"].get("window") is None
             and float(j["settings"].get("kappa", SET_KAPPA)) in kappas
             and float(j["settings"]["H"]) == SENSITIVITY_H
             and geometry(j["settings"]) == (1, float(DEFAULT_LAYER), None, None)]
    if not any(float(j["settings"]["kappa"]) != KAPPA for j in ramps):
        return []
    rows = []
    for job, ref in paired_ramps(jobs, ramps, KAPPA):
        H, seed = _study_key(job)
        t0, t70 = result(ref.get("f0"))[0], result(job)[0]
        if not np.isfinite(t70):
            continue
        onset0 = flow_onset(ref["f0"]) if "f0" in ref else np.nan
        rows.append((float(job["settings"]["kappa"]), H, seed, t0, t70, t0 - t70, last_mu_factor(job),
                     onset0 - flow_onset(job)))
    return sorted(rows, key=lambda r: (r[0], r[1], int(r[2]) if r[2].isdigit() else 0, r[2]))


def band_tops(top):
    """{packing name: (kappa_scale, band top (Hz))} of the band calibrations
    kept in top/band/ (`study.py calibrate --band`: 99.9 % of the modes
    below the top at the reference coupling); {} when top is not a
    directory."""
    tops = {}
    if not isinstance(top, (str, os.PathLike)):
        return tops
    for path in sorted(glob.glob(os.path.join(str(top), "band", "*.json"))):
        with open(path) as handle:
            reference = json.load(handle).get("reference") or {}
        if "kappa" in reference and "top" in reference:
            tops[os.path.splitext(os.path.basename(path))[0]] = (float(reference["kappa"]), float(reference["top"]))
    return tops


def band_top_at(tops, H, seed, kappa):
    """The band top (Hz) of the DEFAULT_LAYER d free-ends packing (H, seed)
    at kappa_scale kappa, from its calibration (band_tops) scaled as
    kappa_scale^(1/3) (every eigenfrequency at fixed contact forces); nan
    without one."""
    found = tops.get(f"free{DEFAULT_LAYER:g}_H{H:g}_s{seed}")
    return found[1] * (kappa / found[0]) ** (1 / 3) if found else np.nan


def sensitivity_summary(rows):
    """{kappa: ((mean, s.d., count) of theta_m at 70 kHz, of the shift)} of
    sensitivity_study's rows."""
    return {k: (mean_sd([r[4] for r in rows if r[0] == k]), mean_sd([r[5] for r in rows if r[0] == k]))
            for k in sorted({r[0] for r in rows})}


def _paper_grains(grains):
    """The N of paper 000's Table 1 within 10 % of grains, or None."""
    near = [n for n in PAPER_TABLE1 if abs(grains - n) <= 0.1 * n]
    return near[0] if near else None


def table1_study(top):
    """Rows (H, grains, base grains, length, time at the angle 0 / 70 kHz,
    wall time 0 / 70 kHz, (t70 - t0)/t70, paper 000's N or None, its value
    or nan) of the one-angle runs at KAPPA (one_angle: Table 1's, the same
    simulated time at 0 and 70 kHz), a row per packing with both
    frequencies finished and their deposit, by grains."""
    jobs = _jobs(top)
    runs = {}
    for job in jobs.values():
        s = job["settings"]
        if one_angle(s) and float(s.get("kappa", SET_KAPPA)) == KAPPA and s.get("switch_on") is None:
            runs.setdefault(packing_key(s), {})[s.get("tag")] = job
    rows = []
    for key, ramps in runs.items():
        if "f0" not in ramps or "f70" not in ramps or jobs.get(ramps["f0"]["settings"].get("deposit", "")) is None:
            continue
        grains, base, _, length = deposit(jobs, ramps["f0"])
        held = [sum(t for _, _, t, _ in angles(ramps[tag])) for tag in ("f0", "f70")]
        w0, w70 = _wall(ramps["f0"]), _wall(ramps["f70"])
        n = _paper_grains(grains)
        rows.append((key[4], grains, base, length, held[0], held[1], w0, w70, (w70 - w0) / w70, n,
                     PAPER_TABLE1[n] if n else np.nan))
    return sorted(rows, key=lambda r: (r[1], r[0]))


def calibrated_study(top, tops=None):
    """The study at the calibrated coupling: a dict with its ensembles
    ("ensembles": {label: {H: [packings]}}, ensembles(top, KAPPA)), their
    summaries ("summary"), {label: geometry} ("geometries"), the label of the free-ends 400 d one ("label",
    None without it), the sensitivity set ("sensitivity": rows of
    sensitivity_study; "band_tops": the band top of each of its rows,
    from tops, band_tops(top) by default) and Table 1 ("table1": rows of
    table1_study); None when none of these is there."""
    jobs = _jobs(top)
    ens = ensembles(jobs, KAPPA)
    sens, t1 = sensitivity_study(jobs), table1_study(jobs)
    tops = band_tops(top) if tops is None else tops
    if not ens and not sens and not t1:
        return None
    main = geometry_label((1, float(DEFAULT_LAYER), None, None))
    return {"ensembles": ens, "summary": {label: summarise(by_h) for label, by_h in ens.items()},
            "geometries": {label: key for key, label in geometries(jobs, KAPPA)},
            "label": main if main in ens else None, "sensitivity": sens, "table1": t1,
            "band_tops": {(H, seed, k): band_top_at(tops, H, seed, k) for k, H, seed, *_ in sens},
            "percolation": percolation_rows(ens[main]) if main in ens else [],
            "snapshots": snapshot_rows(jobs), "fields": fields_rows(jobs)}


def print_calibrated_thetam(label, by_h, summary):
    """theta_m at 0 and 70 kHz per H of one geometry at KAPPA (mean ± s.d.
    and standard error over the packings), the shift paired by packing with
    its standard error, beside paper 000's values (stated or interpolated),
    then each packing, on stdout."""
    rows, s0, s70 = summary
    print(f"\n### θ_m at {CALIBRATED_LABEL}, {label}\n")
    print("| H/d (measured) | packings | grains + base, length | θ_m 0 kHz, mean ± s.d. (s.e.) "
          "| θ_m 70 kHz, mean ± s.d. (s.e.) | shift paired by packing, mean ± s.d. (s.e.) | pairs "
          "| paper 000 θ_m 0 kHz | paper 000 θ_m 70 kHz | paper 000 shift |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        p0, p70, pshift = paper_thetam(r["H"])
        print(f"| {r['H']:g} ({r['H_measured']:.2f}) | {r['n']} | {r['grains']} + {r['base']}, {r['length']:g} d "
              f"| {with_error(r['theta0'])}° | {with_error(r['theta70'])}° | {with_error(r['shift'])}° "
              f"| {r['shift'][2]} | {p0}° | {p70}° | {pshift}° |")
    print("\n(s.e.: the standard error of the mean, s.d./√n; the shift is θ_m(0 kHz) − θ_m(70 kHz) of each "
          "packing with both ramps; paper 000 states 20° / 14.5° at 3 d and 17° at 14.4 d, the other values "
          "are interpolated as in Fig. 7)")
    print("\nfirst angle with a flow that spreads (partial or uniform; θ_m is the first uniform flow, paper 000's "
          "criterion), mean ± s.d. (s.e.):")
    for r in rows:
        print(f"- H = {r['H']:g} d: 0 kHz {with_error(r['onset0'])}°, 70 kHz {with_error(r['onset70'])}°, "
              f"shift paired by packing {with_error(r['onset_shift'])}° ({r['onset_shift'][2]} pairs)")
    print_slopes(by_h, s0, s70)
    print("\nper packing (seed: θ_m 0 / 70 kHz, shift, t_con at θ_m 0 / 70 kHz):")
    for H, packs in sorted(by_h.items()):
        print(f"- H = {H:g} d: " + "; ".join(
            f"s{p['seed']}: {num(p['f0'][0])} / {num(p['f70'][0])}°, {num(p['f0'][0] - p['f70'][0])}°, "
            f"{num(p['f0'][1], '.2f')} / {num(p['f70'][1], '.2f')} s" for p in packs))


def print_calibrated_tcon(by_h):
    """t_con at 0 and 70 kHz of one geometry at KAPPA: at theta_m (the
    ramps), 1, 2 and 3 deg above each packing's theta_m (the tcon_cal set)
    and at 19 deg at 6 d beside paper 000's 1.15 / 0.30 s; the thicknesses
    with t_con runs only."""
    heights = [H for H, packs in sorted(by_h.items()) if any(p["tcon_f0"] or p["tcon_f70"] for p in packs)]
    if not heights:
        return
    print(f"\n### t_con at {CALIBRATED_LABEL} (mean ± s.d. (runs) over the packings)\n")
    print("| H/d | frequency | at θ_m (the ramp) | " + " | ".join(f"θ_m + {s:g}°" for s in TCON_STEPS)
          + f" | at {PAPER_TCON_ANGLE_H6:g}° | paper 000 |")
    print("|---|---|---|" + "---|" * len(TCON_STEPS) + "---|---|")
    for H in heights:
        packs = by_h[H]
        for k, tag in enumerate(("f0", "f70")):
            at_m = [p[tag][1] for p in packs if np.isfinite(p[tag][0])]
            steps = [times_text(tcon_above(packs, tag, s)) for s in TCON_STEPS]
            at_angle = (times_text(tcon_runs_at_angle(packs, tag, PAPER_TCON_ANGLE_H6)) if H == 6.0 else "—")
            paper = (f"{PAPER_TCON_H6_19DEG[k]:g} s at {PAPER_TCON_ANGLE_H6:g}° (stated)" if H == 6.0 else "—")
            print(f"| {H:g} | {tag[1:]} kHz | {times_text(at_m)} | " + " | ".join(steps)
                  + f" | {at_angle} | {paper} |")


def print_sensitivity(rows, tops=None):
    """The sensitivity set's table (sensitivity_study's rows; tops: the
    band top of each row's packing at its coupling, {(H, seed, kappa): Hz})
    and the shift at each kappa_scale, on stdout; nothing without rows."""
    if not rows:
        return
    tops = tops or {}
    print(f"\n### 70 kHz shift against kappa_scale at H = {SENSITIVITY_H:g} d (free ends, {DEFAULT_LAYER} d; "
          f"the band top read 5 kHz lower or higher; θ_m at 0 kHz of the same packing at kappa_scale {KAPPA:g})\n")
    print("| kappa_scale | packing | band top (kHz) | θ_m 0 kHz | θ_m 70 kHz | shift | mean μ*/μ before θ_m "
          "| shift of the first spreading flow |")
    print("|---|---|---|---|---|---|---|---|")
    for k, H, seed, t0, t70, shift, mu, onset_shift in rows:
        top = tops.get((H, seed, k), np.nan) / 1e3
        print(f"| {k:g} | {seed} | {num(top, '.1f')} | {num(t0)}° | {t70:g}° | {num(shift)}° | {num(mu, '.3f')} "
              f"| {num(onset_shift)}° |")
    print("\n(band top: 99.9 % of the packing's modes below it, from its calibration in band/ "
          "(`study.py calibrate --band`) scaled as kappa_scale^(1/3); — without one)")
    print("\nmean ± s.d. (s.e.) over the packings:")
    for k, (t70, shift) in sensitivity_summary(rows).items():
        print(f"- kappa_scale {k:g}: θ_m 70 kHz {with_error(t70)}° (n = {t70[2]}), shift {with_error(shift)}° "
              f"(pairs: {shift[2]})")


def spreading_angles(result):
    """The angles of a ramp's result from its first spreading flow
    ("partial" or "uniform") up to the first uniform one (theta_m), or []
    without a spreading flow."""
    angles = (result or {}).get("angles", [])
    first = next((k for k, a in enumerate(angles) if a["state"] in ("partial", "uniform")), None)
    if first is None:
        return []
    last = next((k for k, a in enumerate(angles) if a["state"] == "uniform"), len(angles) - 1)
    return angles[first:last + 1]


def print_paper_length(ens, summary, keys):
    """The free-ends layers of another length than DEFAULT_LAYER
    (in.material's contact law; the paper_length set) beside the
    DEFAULT_LAYER d ones at the same H (keys: {label: geometry} of the
    ensembles ens), on stdout; nothing without them."""
    main = geometry_label((1, float(DEFAULT_LAYER), None, None))
    longer = [label for label in ens if keys[label][0] == 1 and keys[label][1] != DEFAULT_LAYER
              and keys[label][2] is None and keys[label][3] is None]
    if not longer:
        return
    print(f"\n### layers of paper 000's length beside the {DEFAULT_LAYER} d layers ({CALIBRATED_LABEL}; "
          "mean ± s.d. over the packings)\n")
    print("| H/d | layer, window | packings | grains + base | θ_m 0 kHz | θ_m 70 kHz | shift (s.e.) "
          "| t_con at θ_m 0 / 70 kHz (s) | wall time per ramp 0 / 70 kHz (s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for label in longer:
        for H in sorted(ens[label]):
            for name in (label, main):
                if name not in ens or H not in ens[name]:
                    continue
                layer = keys[name][1]
                windows = sorted({p["window"] if p["window"] is not None else layer / 2 for p in ens[name][H]})
                r = next(row for row in summary[name][0] if row["H"] == H)
                print(f"| {H:g} | {layer:g} d, {', '.join(f'{w:g}' for w in windows)} d | {r['n']} "
                      f"| {r['grains']} + {r['base']} | {fmt(r['theta0'])}° | {fmt(r['theta70'])}° "
                      f"| {with_error(r['shift'])}° | {fmt(r['tcon0'])} / {fmt(r['tcon70'])} "
                      f"| {num(r['wall0'], '.0f')} / {num(r['wall70'], '.0f')} |")
    print("\nfrom the first spreading flow to θ_m, per packing (θ: state, largest fraction of the window's "
          "grains faster than v_mob, σ_1 / σ_2 at the end of the angle; uniform: σ_1 < 0.3, σ_2 < 0.9):")
    for label in longer:
        for H in sorted(ens[label]):
            for name in (label, main):
                for p in (ens[name].get(H, []) if name in ens else []):
                    for tag, f_khz in (("f0", 0), ("f70", 70)):
                        angles = spreading_angles(study.read_result(p["dirs"][tag]) if tag in p["dirs"] else None)
                        if angles:
                            print(f"- H = {H:g} d, {keys[name][1]:g} d, packing {p['seed']}, {f_khz} kHz: " +
                                  "; ".join(f"{a['theta']:g}°: {a['state']}, {a['max_mobile']:.2f}, "
                                            f"{a['sigma1']:.3g} / {a['sigma2']:.3g}" for a in angles))


def print_table1(rows):
    """Table 1 as paper 000 measures it (table1_study's rows) on stdout;
    nothing without rows."""
    if not rows:
        return
    print(f"\n### Table 1: the cost of the ultrasound, (t70 − t0)/t70 ({CALIBRATED_LABEL}; one angle held, the same "
          "simulated time at 0 and 70 kHz, LAMMPS's wall times as the jobs record them)\n")
    print("| H/d | grains + base, length | time at the angle 0 / 70 kHz (s) | wall time 0 / 70 kHz (s) "
          "| (t70 − t0)/t70 | paper 000 |")
    print("|---|---|---|---|---|---|")
    for H, grains, base, length, h0, h70, w0, w70, cost, n, paper in rows:
        ptxt = f"{100 * paper:.0f} % (N = {n})" if n else "—"
        print(f"| {H:g} | {grains} + {base}, {length:g} d | {h0:g} / {h70:g} | {w0:.0f} / {w70:.0f} "
              f"| {100 * cost:.0f} % | {ptxt} |")


def print_calibrated(cal):
    """The markdown of the study at the calibrated coupling (calibrated_study) on stdout."""
    print(f"\n## The study at {CALIBRATED_LABEL}")
    for label, by_h in cal["ensembles"].items():
        print_calibrated_thetam(label, by_h, cal["summary"][label])
        print_calibrated_tcon(by_h)
    print_sensitivity(cal["sensitivity"], cal.get("band_tops"))
    print_paper_length(cal["ensembles"], cal["summary"], cal["geometries"])
    print_table1(cal["table1"])
    print_percolation(cal.get("percolation", []))
    print_snapshots(cal.get("snapshots", []))
    print_fields(cal.get("fields", []))


def percolation_table(rows):
    """{H: [(angle, mean largest moving fraction at 0 kHz, packings, at 70
    kHz, packings)]} from percolation_rows: Fig. 11 in numbers."""
    out = {}
    for H in sorted({r[0] for r in rows}):
        lines = []
        for theta in sorted({r[3] for r in rows if r[0] == H}):
            at = [[r[4] for r in rows if r[0] == H and r[3] == theta and r[2] == f] for f in (0.0, 70.0)]
            lines.append((theta, float(np.mean(at[0])) if at[0] else np.nan, len(at[0]),
                          float(np.mean(at[1])) if at[1] else np.nan, len(at[1])))
        out[H] = lines
    return out


def print_percolation(rows):
    """Fig. 11 in numbers: the largest moving fraction at each angle, mean over the packings."""
    if not rows:
        return
    print("\n### Fig. 11 in numbers: the largest fraction of the observed grains moving at each tested angle "
          "(mean over the packings tested there)\n")
    for H, lines in percolation_table(rows).items():
        cells = ", ".join(f"{theta:g}°: {num(m0, '.3f')} / {num(m70, '.3f')}" for theta, m0, n0, m70, n70 in lines)
        print(f"- H = {H:g} d (0 / 70 kHz): {cells}")


def snapshot_rows(jobs):
    """Rows (f kHz, U0/d, t ms, snapshot_numbers...) of the snapshot jobs
    (Figs. 10, 12, 13), sorted by frequency, amplitude and time."""
    from .avalanche_snapshots import read_snapshots, snapshot_numbers
    rows = []
    for job in _jobs(jobs).values():
        s = job["settings"]
        if s.get("kind") == "snapshot":
            for t, snap in read_snapshots(job["dir"], s).items():
                rows.append((float(s["freq"]) / 1e3, float(s["U0"]), t) + snapshot_numbers(snap))
    return sorted(rows, key=lambda r: (-r[0], -r[1], r[2]))


def print_snapshots(rows):
    """Figs. 10, 12, 13 in numbers."""
    if not rows:
        return
    print("\n### Figs. 10, 12, 13 in numbers: the network under the drive (14.4 d at 15°, 30 d of the "
          "layer's middle)\n")
    print("| f (kHz) | U0/d | t (ms) | contacts | μ*/μ < 0.5: all / within 3 d of the base / above 6 d "
          "| median \\|q\\|/U0, 0-2, 2-4, 4-6, 6-8 d above the base |")
    print("|---|---|---|---|---|---|")
    for f, u, t, n, share, low, high, medians in rows:
        print(f"| {f:g} | {u:.0e} | {t:g} | {n} | {100 * share:.0f} % / {100 * low:.0f} % / {100 * high:.0f} % "
              f"| {', '.join(f'{m:.2g}' for m in medians)} |")


def _first_held_below(t, values, limit, hold=0.01, mobile=None, fspread=av.FSPREAD):
    """The first time from which values stay below limit for hold (the
    ramps' hold of the criteria, at least two samples) while more than
    fspread of the observed grains are mobile (the ramps' uniform criterion;
    mobile None: not asked), nan if never: low samples of a layer that barely
    moves, as just after the tilt, do not count."""
    t = np.asarray(t, dtype=float)
    if len(t) < 2:
        return np.nan
    need = max(2, int(round(hold / (t[1] - t[0]))))
    counts = np.asarray(values) < limit
    if mobile is not None:
        counts &= np.asarray(mobile, dtype=float) > fspread
    run = 0
    for k, below in enumerate(counts):
        run = run + 1 if below else 0
        if run >= need:
            return float(t[k - need + 1])
    return np.nan


def fields_rows(jobs):
    """Rows (H, title, time from which sigma_2 stays below its criterion
    with more than half the observed grains mobile (_first_held_below),
    sigma_1's,
    [(t, share of the layer's columns moving faster than a tenth of the
    mean)]) of the motion below and at theta_m of packing 1 (Figs. 6/9, 14)."""
    from .avalanche_fields import as_array
    from .avalanche_study import FIELDS_H
    rows = []
    for H in FIELDS_H:
        for key, (title, f) in sorted(fields_runs(jobs, float(H)).items()):
            t = np.array(f["sigma_t"])
            moving = []
            for snap in f["snapshots"]:
                columns = as_array(snap["columns"])
                columns = columns[np.isfinite(columns)]          # a column without a grain says nothing
                moving.append((snap["t"], float(np.mean(columns / np.mean(columns) > 0.1))))
            mobile = as_array(f["mobile"]) if "mobile" in f else None
            rows.append((float(H), title, _first_held_below(t, as_array(f["sigma2"]), av.EPS_SIGMA2, mobile=mobile),
                         _first_held_below(t, as_array(f["sigma1"]), av.EPS_SIGMA1, mobile=mobile), moving))
    return rows


def print_fields(rows):
    """Figs. 6/9 and 14 in numbers."""
    if not rows:
        return
    print("\n### Figs. 6/9 and 14 in numbers: packing 1 below and at θ_m\n")
    print(f"| H/d | run | σ_2 < {av.EPS_SIGMA2:g} from (s) | σ_1 < {av.EPS_SIGMA1:g} from (s) "
          "| columns along the layer faster than 0.1 × the mean, at t (s) |")
    print("|---|---|---|---|---|")
    for H, title, t2, t1, moving in rows:
        print(f"| {H:g} | {title} | {num(t2, '.2f')} | {num(t1, '.2f')} | "
              f"{', '.join(f'{t:.1f}: {100 * m:.0f} %' for t, m in moving)} |")
    print("\n(σ_l < criterion from: the first time from which it holds 10 ms with more than half of the "
          "observed grains mobile, as in the ramps' uniform criterion)")


def study_data(top):
    """Everything the tables and figures are made of, read from the jobs in
    top: a dict with the ensembles ("ensembles": {label: {H: [packings]}}),
    their summaries ("summary": {label: (rows, slope 0 kHz, slope 70 kHz)}),
    the kappa_scale studies ("kappa": {name: rows}), the switch-on study
    ("switch_on": rows) and its other couplings ("couplings"), and the
    tables of the figures ("thetam", "thetam_free", "couplings_tables",
    "tcon", "kappa_tables"; each None or empty where there is nothing to
    draw)."""
    jobs = load(top)
    all_ens = ensembles(jobs)
    summary = {label: summarise(by_h) for label, by_h in all_ens.items()}
    kappa = {name: kappa_study(jobs, free) for free, (name, _) in KAPPA_STUDIES.items()}
    switch_on = switch_on_study(jobs)
    couplings = coupling_summary(switch_on)
    data = {"ensembles": all_ens, "summary": summary, "kappa": kappa, "switch_on": switch_on,
            "couplings": couplings, "label": None, "free": None, "thetam": None, "thetam_free": None,
            "couplings_tables": [], "tcon": [], "kappa_tables": {}, "calibrated": calibrated_study(jobs, band_tops(top)),
            "paper_tcon": [("paper000_H6_0kHz", PAPER_TCON_ANGLE_H6, PAPER_TCON_H6_19DEG[0]),
                           ("paper000_H6_70kHz", PAPER_TCON_ANGLE_H6, PAPER_TCON_H6_19DEG[1])]}
    label = "periodic" if "periodic" in all_ens else next(iter(all_ens), None)
    if label is not None:
        free = next((g for g in summary if g.startswith("free")), None)
        data.update(label=label, free=free, thetam=thetam_table(summary[label][0]))
        if free and free != label:
            data["thetam_free"] = thetam_table(summary[free][0])
        measured = {r["H"]: r["H_measured"] for r in summary[free or label][0]}
        data["couplings_tables"] = [(kappa_scale, [(measured.get(H, H), t[0], t[1]) for H, t, _ in points])
                                    for kappa_scale, points in couplings.items()]
        data["tcon"] = tcon_rows(all_ens, label, free)
    for free, (name, geometry_name) in KAPPA_STUDIES.items():
        if kappa[name]:
            geometry_name = geometry_name.replace(" ", "_")
            data["kappa_tables"][name] = [(k, H, seed, shift, mu, onset_shift, geometry_name)
                                          for k, H, seed, t0, t70, shift, mu, onset_shift in kappa[name]]
    cal = data["calibrated"]
    if cal is not None:
        main = cal["label"]
        cal["thetam"] = thetam_table(cal["summary"][main][0]) if main else None
        cal["tcon"] = tcon_rows(cal["ensembles"], main, None) if main else []
        cal["kappa_table"] = [(k, H, seed, shift, mu, onset_shift, "free_ends")
                              for k, H, seed, t0, t70, shift, mu, onset_shift in cal["sensitivity"]
                              if np.isfinite(shift)]
    return data


def tables_markdown(data):
    """The markdown tables of every geometry and study (what collect prints):
    the study at the calibrated coupling first where it is there
    (print_calibrated), then the sets run before the calibration."""
    text, calibrated = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(text):
        print_tables(data["ensembles"], data["summary"])
        for free, (name, label) in KAPPA_STUDIES.items():
            print_kappa(data["kappa"][name], label)
        print_switch_on(data["switch_on"])
        print_couplings(data["couplings"])
    if data.get("calibrated") is None:
        return text.getvalue()
    with contextlib.redirect_stdout(calibrated):
        print_calibrated(data["calibrated"])
        if text.getvalue():
            print(f"\n## Before the calibration: {BEFORE_LABEL}")
    return calibrated.getvalue() + text.getvalue()


def write_tables(data, tables):
    """Into the directory tables: tables.md (tables_markdown), summary.json
    (the rows and slopes of each geometry) and the tables of the figures:
    thetam.txt (Fig. 7, the first geometry), thetam_free.txt (the free-ends
    one when it is not the first), thetam_k<kappa>.txt (theta_m at 70 kHz
    at other couplings), tcon.txt (Fig. 8), kappa.txt and kappa_free.txt
    (the kappa_scale studies).  Returns the markdown."""
    os.makedirs(tables, exist_ok=True)
    markdown = tables_markdown(data)
    with open(os.path.join(tables, "tables.md"), "w") as f:
        f.write(markdown)
    if data["thetam"] is not None:
        with open(os.path.join(tables, "thetam.txt"), "w") as f:
            f.write(_table_text(data["thetam"]))
    if data["thetam_free"] is not None:
        with open(os.path.join(tables, "thetam_free.txt"), "w") as f:
            f.write(_table_text(data["thetam_free"]))
    for kappa_scale, rows in data["couplings_tables"]:
        with open(os.path.join(tables, f"thetam_k{kappa_scale:g}.txt"), "w") as f:
            f.write(_table_text(rows))
    if data["label"] is not None:
        with open(os.path.join(tables, "tcon.txt"), "w") as f:
            f.writelines(f"{name} {th:g} {t:g} {kind}\n" for name, th, t, kind in data["tcon"])
            f.writelines(f"{name} {theta:g} {t}\n" for name, theta, t in data["paper_tcon"])
    for name, rows in data["kappa_tables"].items():
        with open(os.path.join(tables, f"{name}.txt"), "w") as f:
            f.writelines(f"{k:g} {H:g} {seed} {shift:g} {mu:g} {onset:g} {g}\n" for k, H, seed, shift, mu, onset, g in rows)
    with open(os.path.join(tables, "summary.json"), "w") as f:
        json.dump({label: {"rows": rows, "slope0": s0, "slope70": s70}
                   for label, (rows, s0, s70) in data["summary"].items()}, f, indent=1, default=float)
    cal = data.get("calibrated")
    if cal is not None:
        write_calibrated_tables(cal, tables)
    return markdown


def write_calibrated_tables(cal, tables):
    """The tables of the study at the calibrated coupling (calibrated_study,
    completed by study_data) into the directory tables, those with data
    only: thetam_calibrated.txt (Fig. 7), tcon_calibrated.txt (Fig. 8),
    kappa_calibrated.txt (the sensitivity set, kappa.txt's format),
    table1.txt ("H grains base length wall0 wall70 cost paperN paper")
    and summary_calibrated.json (the rows and slopes of each geometry, the
    sensitivity set's rows and summary, Table 1's rows)."""
    if cal["thetam"] is not None:
        with open(os.path.join(tables, "thetam_calibrated.txt"), "w") as f:
            f.write(_table_text(cal["thetam"]))
    if cal["tcon"]:
        with open(os.path.join(tables, "tcon_calibrated.txt"), "w") as f:
            f.writelines(f"{name} {th:g} {t:g} {kind}\n" for name, th, t, kind in cal["tcon"])
    if cal["kappa_table"]:
        with open(os.path.join(tables, "kappa_calibrated.txt"), "w") as f:
            f.writelines(f"{k:g} {H:g} {seed} {shift:g} {mu:g} {onset:g} {g}\n"
                         for k, H, seed, shift, mu, onset, g in cal["kappa_table"])
    if cal["table1"]:
        with open(os.path.join(tables, "table1.txt"), "w") as f:
            f.writelines(f"{H:g} {n} {nb} {length:g} {w0:g} {w70:g} {cost:g} {pn or 'nan'} {paper:g}\n"
                         for H, n, nb, length, h0, h70, w0, w70, cost, pn, paper in cal["table1"])
    with open(os.path.join(tables, "summary_calibrated.json"), "w") as f:
        json.dump({"kappa_scale": KAPPA,
                   "geometries": {label: {"rows": rows, "slope0": s0, "slope70": s70}
                                  for label, (rows, s0, s70) in cal["summary"].items()},
                   "sensitivity": {"rows": cal["sensitivity"],
                                   "summary": {f"{k:g}": v
                                               for k, v in sensitivity_summary(cal["sensitivity"]).items()}},
                   "table1": cal["table1"]}, f, indent=1, default=float)


def draw_figures(data, figdir):
    """Fig. 7 (with theta_m at 70 kHz at the other couplings beside it),
    Fig. 8, the kappa_scale shifts, and from the dumps and series where they
    are there (not in a record) Figs. 3, 6/9 and 10 and the sigma_l of the
    longest-held t_con runs, into figdir; returns the paths written."""
    os.makedirs(figdir, exist_ok=True)
    written = []

    def out(name):
        written.append(os.path.join(figdir, name))
        return written[-1]

    label, cal = data["label"], data.get("calibrated")
    couplings = [(rows, f"kappa_scale {kappa_scale:g}" + (" (the calibrated coupling)" if kappa_scale == KAPPA
                                                           else "") + ", switched on at rest")
                 for kappa_scale, rows in data["couplings_tables"]]
    coupling = f"kappa_scale {SET_KAPPA:g}" + (" (run before the calibration)" if SET_KAPPA != KAPPA else "")
    if cal is not None and cal["thetam"] is not None:
        # the study's result at the calibrated coupling; the free-ends set
        # before the calibration beside it, labelled as the sensitivity study
        before = data["thetam_free"] if data["thetam_free"] is not None else (
            data["thetam"] if label is not None and data["free"] == label else None)
        figs.fig_thetam(out("fig7_thetam.png"), cal["thetam"],
                        f"{cal['label']}, {CALIBRATED_LABEL}: the study's result",
                        before, f"{data['free']}, {BEFORE_LABEL}", couplings, dpi=100)
    elif label is not None:
        figs.fig_thetam(out("fig7_thetam.png"), data["thetam"], label, data["thetam_free"], data["free"], couplings,
                        dpi=100, coupling=coupling)
    if cal is not None and cal["tcon"]:
        figs.fig_tcon(out("fig8_tcon.png"), cal["tcon"] + data["paper_tcon"], dpi=125, coupling=CALIBRATED_LABEL)
        if data["tcon"]:
            figs.fig_tcon(out(f"fig8_tcon_k{SET_KAPPA:g}.png"), data["tcon"] + data["paper_tcon"], dpi=100,
                          coupling=BEFORE_LABEL)
    elif label is not None:
        figs.fig_tcon(out("fig8_tcon.png"), data["tcon"] + data["paper_tcon"], dpi=125, coupling=coupling)
    if cal is not None and cal["label"] is not None:
        rows = percolation_rows(cal["ensembles"][cal["label"]])
        if rows:
            figs.fig_percolation(out("fig11_percolation.png"), rows, CALIBRATED_LABEL, dpi=100)
    if label is not None or (cal is not None and cal["label"] is not None):
        # the figures from dumps and series: the calibrated ensemble's where it is there
        by_h = cal["ensembles"][cal["label"]] if cal is not None and cal["label"] is not None \
            else data["ensembles"][label]
        for H in (6.0, 14.4):
            packs = by_h.get(H, [])
            if not packs:
                continue
            p = packs[0]
            run = p["dirs"].get("f70", "")
            dump, cont = os.path.join(run, "f70.dump"), os.path.join(run, "f70.contacts")
            if run and os.path.exists(dump) and os.path.exists(cont):
                frames = read_dump(dump)
                tm = p["f70"][0] if np.isfinite(p["f70"][0]) else 90.0
                below = [i for i, fr in enumerate(frames) if fr["v_th"][0] < tm - 1e-6]
                last, first = frames[below[-1] if below else -1], frames[0]
                figs.fig_chains(out(f"fig10_chains_H{H:g}.png"), last,
                                av.contact_columns(av.contacts_at(cont, last.timestep)), dpi=80)
                figs.fig_modes(out(f"fig3_modes_H{H:g}.png"),
                               network=(first, av.contact_columns(av.contacts_at(cont, first.timestep))), dpi=80)
            sers = [(os.path.join(p["dirs"][tag], f"{tag}.series"), p[tag][0]) for tag in ("f0", "f70")
                    if np.isfinite(p[tag][0]) and tag in p["dirs"]
                    and os.path.exists(os.path.join(p["dirs"][tag], f"{tag}.series"))]
            if sers:
                figs.fig_sigma(out(f"fig6_9_sigma_H{H:g}.png"),
                               figs.sigma_runs([s for s, _ in sers], [th for _, th in sers]), dpi=110)
        # the runs with longer holds of the uniform criterion are the sets' before the calibration
        held = held_series(data["ensembles"][label].get(6.0, []) if label is not None else [], "f0",
                           PAPER_TCON_ANGLE_H6)
        if held:
            figs.fig_sigma(out("tcon_hold_sigma_H6.png"),
                           figs.sigma_runs(held, [PAPER_TCON_ANGLE_H6] * len(held)), dpi=110)
    for name, rows in data["kappa_tables"].items():
        figs.fig_kappa(out("kappa_shift" + name[len("kappa"):] + ".png"),
                       [(k, H, shift, mu, onset, g) for k, H, _, shift, mu, onset, g in rows], dpi=200)
    if cal is not None and cal["kappa_table"]:
        figs.fig_kappa(out("kappa_shift_calibrated.png"),
                       [(k, H, shift, mu, onset, g) for k, H, _, shift, mu, onset, g in cal["kappa_table"]], dpi=200)
    return written


def percolation_rows(by_h):
    """Rows (H, packing, f (kHz), angle, largest mobile fraction, state) of
    every tested angle of the ramps of an ensemble ({H: [packings]}): how far
    the moving zones spread at each slope (paper 000's Fig. 11)."""
    rows = []
    for H, packs in sorted(by_h.items()):
        for p in packs:
            for tag, f in (("f0", 0.0), ("f70", 70.0)):
                r = study.read_result(p["dirs"][tag]) if tag in p["dirs"] else None
                for a in (r or {}).get("angles", []):
                    rows.append((H, p["seed"], f, float(a["theta"]), float(a["max_mobile"]), a["state"]))
    return rows


def held_series(packs, tag, theta):
    """The series of each packing's t_con run at theta with the longest hold
    of the uniform criterion (setting tuniform), where it is there: the run
    followed longest after its flow first became uniform."""
    paths = []
    for p in packs:
        runs = sorted((h, run_dir, run_tag) for h, th, _, run_dir, run_tag in p[f"tcon_{tag}_held"] if th == theta)
        path = os.path.join(runs[-1][1], f"{runs[-1][2]}.series") if runs else ""
        if os.path.exists(path):
            paths.append(path)
    return paths


def print_kappa(rows, label):
    """The markdown table of one kappa_scale study (kappa_study's rows) on
    stdout; nothing without rows."""
    if not rows:
        return
    print(f"\n### 70 kHz shift against kappa_scale ({label}; packings of the {label} set)\n")
    print("| kappa_scale | H/d | packing | θ_m 0 kHz | θ_m 70 kHz | shift | mean μ*/μ before θ_m "
          "| shift of the first spreading flow |")
    print("|---|---|---|---|---|---|---|---|")
    for k, H, seed, t0, t70, shift, mu, onset_shift in rows:
        print(f"| {k:g} | {H:g} | {seed} | {t0:g}° | {t70:g}° | {shift:g}° | {mu:.3f} | {onset_shift:g}° |")


def print_switch_on(rows):
    """The markdown table of the switch-on study (switch_on_study's rows) on
    stdout; nothing without rows."""
    if not rows:
        return
    print("\n### 70 kHz switched on at the first tested angle, after a tilt at rest without it "
          "(free ends; beside the ramps of the free-ends set)\n")
    print("| H/d | packing | kappa_scale | first tested angle | θ_m 0 kHz | θ_m 70 kHz "
          "| first spreading flow 70 kHz | time followed before it (s) | mean μ*/μ before θ_m |")
    print("|---|---|---|---|---|---|---|---|---|")
    for H, seed, kappa, start, t0, t70, onset, creep, mu in rows:
        print(f"| {H:g} | {seed} | {num(kappa)} | {start:g}° | {num(t0)}° | {t70:g}° | {num(onset)}° "
              f"| {num(creep, '.2f')} | {num(mu, '.3f')} |")


def print_couplings(couplings):
    """theta_m at 70 kHz and its shift at each other coupling
    (coupling_summary) on stdout."""
    for kappa, points in couplings.items():
        print(f"\nθ_m at 70 kHz with kappa_scale {kappa:g} (switched on at rest; mean ± s.d., the shift paired "
              "by packing):")
        for H, t70, shift in points:
            print(f"- H = {H:g} d: {fmt(t70)}° (n = {t70[2]}), shift {fmt(shift)}° (s.e. {fmt(standard_error(shift))}°)")


def print_other_frequencies(by_h):
    """The ramps at other drive frequencies of the packings of one geometry
    ({H: [packings]}) beside their 0 and 70 kHz ramps, on stdout."""
    rows = [(H, p, r) for H, packs in sorted(by_h.items()) for p in packs for r in p["other"]]
    if not rows:
        return
    print("\nother drive frequencies (packing: θ_m, t_con, first spreading flow, mean μ*/μ before θ_m; "
          "the same packing at 0 / 70 kHz):")
    for H, p, (khz, tm, tc, onset, mu) in rows:
        print(f"- H = {H:g} d s{p['seed']}, {khz:g} kHz: {num(tm)}°, {num(tc, '.2f')} s, {num(onset)}°, "
              f"{num(mu, '.2f')}; 0 / 70 kHz: θ_m {num(p['f0'][0])} / {num(p['f70'][0])}°, "
              f"first spreading flow {num(p['f0_onset'])} / {num(p['f70_onset'])}°")


def collect(top, tables):
    """The tables of the jobs in top (write_tables) into the directory
    tables; returns the markdown."""
    return write_tables(study_data(top), tables)


# paper 000's snapshot figures: (file, [(frequency, U0/d, ms after the tilt)],
# the times paper 000 shows)
SNAPSHOT_FIGURES = (
    ("fig10_snapshots.png", ((70e3, 1e-5, 51), (70e3, 1e-5, 52)), "Fig. 10: 0.051 and 0.052 s"),
    ("fig12_snapshot_30kHz.png", ((30e3, 1e-5, 72),), "Fig. 12: 0.072 s"),
    ("fig13_amplitudes.png", ((70e3, 1e-3, 18), (70e3, 1e-4, 18), (70e3, 1e-5, 18), (70e3, 1e-6, 18)),
     "Fig. 13: 0.018 s"))


def snapshot_figures(top, figdir):
    """Figs. 10, 12 and 13 from the snapshot jobs in top (the record's
    snapshot_*ms.json, or a production's dumps), those whose snapshots are
    all there; returns the paths written."""
    from .avalanche_snapshots import read_snapshots
    found = {}
    for job in _jobs(top).values():
        s = job["settings"]
        if s.get("kind") == "snapshot":
            for t, snap in read_snapshots(job["dir"], s).items():
                found[(float(s["freq"]), float(s["U0"]), t)] = snap
    written = []
    for name, wanted, paper in SNAPSHOT_FIGURES:
        snaps = [found.get((f, u, t)) for f, u, t in wanted]
        if any(snap is None for snap in snaps):
            continue
        titles = [f"f = {snap['freq'] / 1e3:g} kHz, $U_0/d$ = {snap['U0_over_d']:.0e}, "
                  f"$\\theta$ = {snap['theta']:g}°, t = {snap['t_ms']:g} ms after the drive ({paper})"
                  for snap in snaps]
        os.makedirs(figdir, exist_ok=True)
        written.append(os.path.join(figdir, name))
        figs.fig_snapshots(written[-1], snaps, titles, dpi=72)
    return written


def band_figures(top, figdir):
    """Paper 000's Fig. 3 at the calibrated coupling: the density of states
    of the band calibration kept in top/band/ (`study.py calibrate --band`
    on a deposit, its JSON) of the snapshots' packing (SNAPSHOT_H,
    SNAPSHOT_SEED: one figure; the other packings' calibrations give the
    band tops of the sensitivity table) at the study's coupling; returns
    the paths written."""
    from .avalanche_study import SNAPSHOT_H, SNAPSHOT_SEED
    written = []
    for path in glob.glob(os.path.join(str(top), "band", f"free{DEFAULT_LAYER:g}_H{SNAPSHOT_H:g}_s{SNAPSHOT_SEED}.json")):
        with open(path) as handle:
            band = json.load(handle)
        at = band.get("at_check")
        if not at or "histogram" not in at:
            continue
        name = os.path.splitext(os.path.basename(path))[0]
        title = (f"{name} ({band['grains']} atoms, base included), kappa_scale {at['kappa']:g}: 99.9 % of the modes below "
                 f"{at['top'] / 1e3:.1f} kHz (paper 000: 75 kHz), {100 * at['in_5_45kHz']:.0f} % in 5-45 kHz")
        os.makedirs(figdir, exist_ok=True)
        written.append(os.path.join(figdir, f"fig3_modes_{name}.png"))
        figs.fig_modes(written[-1], histogram=np.array(at["histogram"]), histogram_name=title, dpi=260)
    return written


def job_fields(job):
    """The fields of a calibrated job (avalanche_fields): its fields.json in
    a record, or made from its dumps in a production; None without."""
    from .avalanche_fields import job_fields as from_dumps, read_fields
    from .avalanche_study import geometry_variables, keeps_fields
    kept = read_fields(job["dir"])
    if kept is not None or not keeps_fields(job["settings"]):
        return kept
    g = geometry_variables(job["settings"])
    return from_dumps(job["dir"], job["settings"], job["result"], (float(g["obslo"]), float(g["obshi"])))


def fields_runs(top, H, seed="1"):
    """{(f kHz, "below" or "at"): (title, fields of one angle)} of packing
    `seed` at H/d: the last angle below theta_m that its ramp followed, and
    theta_m held 1.2 s (the fields set's t_con run at theta_m, else the
    ramp's own theta_m, cut short when the flow became uniform), on the
    study's 400 d layer (not the paper_length set's 2000 d one)."""
    from .avalanche_study import packing_settings
    layer = packing_settings(H, seed)["layer"]
    jobs = [j for j in _jobs(top).values() if _in_ensemble(j, KAPPA) and j["settings"].get("free") == 1
            and float(j["settings"].get("layer", layer)) == layer
            and abs(float(j["settings"]["H"]) - H) < 1e-9 and str(j["settings"]["seed"]) == str(seed)]
    out = {}
    for f_khz, tag in ((0, "f0"), (70, "f70")):
        ramp = next((j for j in jobs if j["settings"]["kind"] == "ramp" and j["settings"]["tag"] == tag), None)
        fields = job_fields(ramp) if ramp is not None else None
        if fields is None:
            continue
        tm = fields["theta_m"]
        below = [a for a in fields["angles"] if tm is None or a["theta"] < tm - 1e-6]
        if below:
            a = below[-1]
            what = f"θ_m − {tm - a['theta']:g}°" if tm is not None else "no flow"
            out[(f_khz, "below")] = (f"{f_khz} kHz, θ = {a['theta']:g}° ({what})", a)
        hold = next((j for j in jobs if j["settings"]["kind"] == "tcon" and j["settings"].get("ramp_tag") == tag
                     and tm is not None and abs(float(j["settings"]["theta"]) - tm) < 1e-6
                     and j["settings"].get("tuniform") is not None), None)
        held = job_fields(hold) if hold is not None else None
        at = held["angles"][0] if held else next((a for a in fields["angles"] if tm is not None
                                                  and abs(a["theta"] - tm) < 1e-6), None)
        if at is not None:
            out[(f_khz, "at")] = (f"{f_khz} kHz, θ = {at['theta']:g}° (θ_m" + (", held" if held else
                                                                              ", until uniform") + ")", at)
    return out


def spread_runs(top, H, seed="1"):
    """[(layer (d), f kHz, fields of the ramp)] of packing `seed` at H/d at
    the calibrated coupling, every layer length that has ramps with fields
    (the study's 400 d layer and the paper_length set's 2000 d one)."""
    runs = []
    for j in sorted(_jobs(top).values(), key=lambda j: j["dir"]):
        st = j["settings"]
        if not (_in_ensemble(j, KAPPA) and st.get("free") == 1 and st["kind"] == "ramp"
                and abs(float(st["H"]) - H) < 1e-9 and str(st["seed"]) == str(seed)):
            continue
        fields = job_fields(j)
        if fields is not None:
            runs.append((float(st.get("layer", DEFAULT_LAYER)), float(st["freq"]) / 1e3, fields))
    return runs


def fields_figures(top, figdir):
    """Figs. 6/9 (the motion below and at theta_m, 0 and 70 kHz) and Fig. 14
    (speed along the layer at theta_m, 0 against 70 kHz) of packing 1 at
    each thickness of FIELDS_H whose fields are there, and, where packing 1
    also has a paper-length layer, how the flows cover each layer's window
    (paper_length_spread_H<H>.png); returns the paths."""
    from .avalanche_study import FIELDS_H
    written = []
    for H in FIELDS_H:
        runs = fields_runs(top, float(H))
        order = [(0, "below"), (0, "at"), (70, "below"), (70, "at")]
        if not runs:
            continue
        os.makedirs(figdir, exist_ok=True)
        written.append(os.path.join(figdir, f"fig6_9_fields_H{H:g}.png"))
        figs.fig_fields(written[-1], [runs[k] for k in order if k in runs])
        front = [(f"{k[0]} kHz, " + runs[k][0].split(", ", 1)[1], k[0], runs[k][1]) for k in order
                 if k in runs and k[1] == "at"]
        if front:
            written.append(os.path.join(figdir, f"fig14_front_H{H:g}.png"))
            figs.fig_front(written[-1], front)
        spread = spread_runs(top, float(H))
        if len({layer for layer, _, _ in spread}) > 1:
            written.append(os.path.join(figdir, f"paper_length_spread_H{H:g}.png"))
            figs.fig_spread(written[-1], spread)
    return written


def figures(top, figdir):
    """The figures of the jobs in top (draw_figures, snapshot_figures,
    band_figures, fields_figures) into figdir."""
    return (draw_figures(study_data(top), figdir) + snapshot_figures(top, figdir) + band_figures(top, figdir)
            + fields_figures(top, figdir))
