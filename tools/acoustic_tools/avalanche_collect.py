"""Collect the ensembles of examples/avalanche (run_ensemble.sh and the studies
of run_production.sh) into the tables and figures of its RESULTS.md;
examples/avalanche/collect.py is the command line.

OUT (the production outputs, or the record of avalanche_record) holds
ensemble_periodic/H<H>/s<seed>/, ensemble/H<H>/s<seed>/ (free ends, 400 d),
ensemble_L<length>/... (free ends of another length), ensemble_E<modulus>/...
and ensemble_e<restitution>/... (another contact law), each packing with
log.deposit, log.f0, log.f70 and the t_con runs log.tcon_f*_<theta>[_u<hold>];
kappa/k<kappa>/... and kappa_free/k<kappa>/... (the 70 kHz shift against
kappa_scale) and switch_on/at<angle>[_k<kappa>]/... (70 kHz switched on at
rest).  Reading:

  ensembles, packing, result, deposit, other_frequencies, angle_lines,
  flow_onset, last_mu_factor, first_angle, time_before_onset, kappa_scale
                        the logs of each packing, geometry by geometry
  kappa_study, switch_on_study, paired_packings, coupling_summary
                        the studies beside the packings of a set
  summarise, theta_slope, slope, tcon_one_degree_above, tcon_at_angle,
  tcon_runs_at_angle, tcon_against_hold, mean_with_censored, held_series
                        ensemble statistics
  print_tables, print_kappa, print_switch_on, print_couplings, ...
                        the markdown tables on stdout
  figures, kappa_figure, thetam_table, tcon_rows, tcon_table_lines
                        the figures (avalanche_figures) and their tables
  collect               all of it: what collect.py does
"""
import glob
import json
import os
import re
import sys

import numpy as np

from . import avalanche as av
from . import avalanche_figures as figs
from .lammps_log import wall_time
from .lammps_output import read_dump
from .stats import mean_sd

# paper 000, §3.1-3.2 text: H = 3 d: 20 deg without, 14.5 deg with 70 kHz;
# H = 14.4 d: 17 deg without (Fig. 6), flows at 16 deg with 70 kHz (Fig. 9);
# the other values are only drawn in Fig. 7: "about 2 deg lower with 70 kHz";
# theta_m(H/d) falls by about 0.26 deg per d (issue 13's reading of Fig. 7)
PAPER = {3.0: (20.0, 14.5), 14.4: (17.0, np.nan)}
PAPER_SLOPE = -0.26
PAPER_TCON_H6_19DEG = (1.15, 0.30)

RESULT = re.compile(r"theta_m = ([0-9.]+|none) deg\s+t_con = ([-0-9.]+) s")
GEOMETRIES = (("ensemble_periodic", "periodic"), ("ensemble", "free ends, 400 d"))
PAPER_TCON_ANGLE_H6 = 19.0
DEFAULT_TUNIFORM = 0.01   # s, in.avalanche's uniform hold (its thold)
FOLLOW = 1.3              # s, twin + tfollow: how long a t_con run follows its angle
TCON_LOG = re.compile(r"([0-9.]+)(?:_u([0-9.e-]+))?")   # log.tcon_TAG_<theta>[_u<tuniform>]


def geometries(top):
    """(directory, label) of the ensembles in top: the periodic set, the
    free-ends set (400 d), then the free-ends sets of other lengths
    (ensemble_L<length>, run_ensemble.sh with AVALANCHE_LAYER) or another
    contact law (..._E<modulus>_e<restitution>, AVALANCHE_EDEM and
    AVALANCHE_REST), by length and modulus."""
    other = []
    for d in glob.glob(os.path.join(top, "ensemble_*")):
        m = re.fullmatch(r"ensemble(?:_L([0-9]+))?(?:_E([0-9.e+]+))?(?:_e([0-9.]+))?", os.path.basename(d))
        if not m or not any(m.groups()):
            continue
        length, modulus, restitution = m.groups()
        label = f"free ends, {length or 400} d"
        label += f", E = {float(modulus):g} Pa" if modulus else ""
        label += f", restitution {restitution}" if restitution else ""
        key = (int(length or 400), float(modulus or 0), float(restitution or 0))
        other.append((key, label, os.path.basename(d)))
    return list(GEOMETRIES) + [(sub, label) for _, label, sub in sorted(other)]


def result(log):
    """(theta_m, t_con) of an in.avalanche log; nan when absent or none."""
    if not os.path.exists(log):
        return np.nan, np.nan
    for line in open(log):
        m = RESULT.search(line)
        if m:
            tm = float(m.group(1)) if m.group(1) != "none" else np.nan
            return tm, float(m.group(2)) if np.isfinite(tm) else np.nan
    return np.nan, np.nan


def deposit(log):
    """(grains, base grains, measured H/d, length/d) of a log.deposit; zeros
    and nan without its deposit line."""
    for line in open(log):
        if line.startswith("deposit:"):
            n = re.search(r"(\d+) grains on (\d+) base", line)
            h = re.search(r"H = ([0-9.]+) d", line)
            length = re.search(r"box ([0-9.]+) d long", line)
            return int(n.group(1)), int(n.group(2)), float(h.group(1)), float(length.group(1))
    return 0, 0, np.nan, np.nan


def packing(path):
    """Everything about one packing directory."""
    n, nb, hm, length = deposit(os.path.join(path, "log.deposit"))
    p = {"path": path, "seed": os.path.basename(path)[1:], "grains": n, "base": nb, "H_measured": hm,
         "length": length}
    for tag in ("f0", "f70"):
        log = os.path.join(path, f"log.{tag}")
        p[tag] = result(log)
        p[f"{tag}_wall"] = wall_time(log) if os.path.exists(log) else np.nan
        rest = ""
        if os.path.exists(log):
            m = re.search(r"\((at rest|NOT at rest after tsettle|no pre-ramp)\)", open(log).read())
            rest = m.group(1) if m else ""
        p[f"{tag}_rest"] = rest
        p[f"{tag}_onset"] = flow_onset(log) if os.path.exists(log) and np.isfinite(p[tag][0]) else np.nan
        p[f"tcon_{tag}"], p[f"tcon_{tag}_held"] = [], []
        for t in sorted(glob.glob(os.path.join(path, f"log.tcon_{tag}_*"))):
            m = TCON_LOG.fullmatch(os.path.basename(t)[len(f"log.tcon_{tag}_"):])
            if not m:
                continue
            if m.group(2):            # AVALANCHE_TUNIFORM: (hold, theta, t_con, run tag)
                p[f"tcon_{tag}_held"].append((float(m.group(2)), float(m.group(1)), result(t)[1],
                                              os.path.basename(t)[len("log."):]))
            else:
                p[f"tcon_{tag}"].append((float(m.group(1)), result(t)[1]))
    p["other"] = other_frequencies(path)
    return p


def other_frequencies(path):
    """Ramps of a packing at drive frequencies other than 0 and 70 kHz
    (run_ensemble.sh ... H SEED 60e3 writes log.f60): [(kHz, theta_m, t_con,
    first spreading flow, mean mu*/mu of the last angle before theta_m)]."""
    rows = []
    for log in glob.glob(os.path.join(path, "log.f*")):
        m = re.fullmatch(r"log\.f([0-9.]+)", os.path.basename(log))
        if not m or m.group(1) in ("0", "70"):
            continue
        tm, tc = result(log)
        if np.isfinite(tm):
            rows.append((float(m.group(1)), tm, tc, flow_onset(log), last_mu_factor(log)))
    return sorted(rows)


def ensembles(top):
    """{geometry label: {H: [packings]}} for the geometries present."""
    out = {}
    for sub, label in geometries(top):
        by_h = {}
        for d in sorted(glob.glob(os.path.join(top, sub, "H*"))):
            H = float(os.path.basename(d)[1:])
            packs = [packing(s) for s in sorted(glob.glob(os.path.join(d, "s*")))
                     if os.path.exists(os.path.join(s, "log.deposit"))]
            packs = [p for p in packs if np.isfinite(p["f0"][0]) or np.isfinite(p["f70"][0])]
            if packs:
                by_h[H] = packs
        if by_h:
            out[label] = by_h
    return out


ANGLE_LINE = re.compile(r"^angle +([0-9.]+) deg: (\w+) after ([0-9.]+) s .* mean mu\*/mu ([0-9.]+)")


def angle_lines(log):
    """[(angle, state, time followed (s), mean mu*/mu at its end)] of the
    tested angles of an in.avalanche log, in order."""
    return [(float(m.group(1)), m.group(2), float(m.group(3)), float(m.group(4)))
            for m in map(ANGLE_LINE.match, open(log)) if m]


def flow_onset(log):
    """The first angle of a ramp that ended with a flow: partial (more than
    half of the observed grains still mobile after 0.1 + tfollow s, not
    uniform) or uniform; nan if none.  It is at or below theta_m."""
    for theta, state, _, _ in angle_lines(log):
        if state in ("partial", "uniform"):
            return theta
    return np.nan


def last_mu_factor(log):
    """mean mu*/mu at the end of the last angle before theta_m (nan if none)."""
    values = [mu for _, state, _, mu in angle_lines(log) if state != "uniform"]
    return values[-1] if values else np.nan


def first_angle(log):
    """The first tested angle of a ramp (nan if none)."""
    lines = angle_lines(log)
    return lines[0][0] if lines else np.nan


def time_before_onset(log):
    """Simulated time (s) the layer was followed at the tested angles before
    the first spreading flow (nan without a flow); under 70 kHz it creeps
    all that time (the pre-ramp and its hold, at most tsettle, come on top)."""
    lines = angle_lines(log)
    spreading = [i for i, (_, state, _, _) in enumerate(lines) if state in ("partial", "uniform")]
    return sum(t for _, _, t, _ in lines[:spreading[0]]) if spreading else np.nan


# the kappa_scale studies of run_production.sh: directory -> (the geometry
# whose ramps at the default kappa_scale 0.3 they stand beside, its label)
KAPPA_SETS = {"kappa": ("ensemble_periodic", "periodic"), "kappa_free": ("ensemble", "free ends")}
SET_KAPPA = 0.3               # kappa_scale of the ensembles (run_ensemble.sh's default)


def paired_packings(top, study, prefix, reference):
    """(value, H, seed, packing dir, reference dir) for every packing
    OUT/<study>/<prefix><value>/H<H>/s<seed> of a study beside a set (value:
    the rest of the directory name, a string): the
    same packing in OUT/<reference>.  A packing whose deposit differs from
    the reference's (grains, base, H, length of log.deposit) is not the same
    packing: it is left out, with a note on stderr."""
    pairs = []
    for d in sorted(glob.glob(os.path.join(top, study, prefix + "*", "H*", "s*"))):
        vdir, hdir = os.path.dirname(os.path.dirname(d)), os.path.dirname(d)
        value, H = os.path.basename(vdir)[len(prefix):], float(os.path.basename(hdir)[1:])
        ref = os.path.join(top, reference, os.path.basename(hdir), os.path.basename(d))
        if not os.path.exists(os.path.join(ref, "log.deposit")) or \
                deposit(os.path.join(d, "log.deposit")) != deposit(os.path.join(ref, "log.deposit")):
            print(f"collect: {d} left out: its deposit is not that of {ref}", file=sys.stderr)
            continue
        pairs.append((value, H, os.path.basename(d)[1:], d, ref))
    return pairs


def kappa_study(top, kset="kappa"):
    """Rows (kappa, H, seed, theta_m 0 Hz, theta_m 70 kHz, shift, mean mu*/mu
    below theta_m, shift of the first spreading flow) of the 70 kHz ramps in OUT/<kset>/k<kappa>/H<H>/s<seed>,
    each beside the same packing's ramps at the default kappa_scale 0.3 in
    the geometry of KAPPA_SETS[kset] (paired_packings)."""
    rows = {}                 # (kappa, H, seed) -> row: the reference ramps appear once
    for kappa, H, seed, d, ref in paired_packings(top, kset, "k", KAPPA_SETS[kset][0]):
        t0 = result(os.path.join(ref, "log.f0"))[0]
        onset0 = flow_onset(os.path.join(ref, "log.f0"))
        for k, path in ((SET_KAPPA, ref), (float(kappa), d)):
            log = os.path.join(path, "log.f70")
            if os.path.exists(log) and np.isfinite(result(log)[0]):
                t70 = result(log)[0]
                rows[(k, H, seed)] = (k, H, seed, t0, t70, t0 - t70, last_mu_factor(log), onset0 - flow_onset(log))
    return [rows[key] for key in sorted(rows)]


# the switch-on study of run_production.sh (set switch_on): 70 kHz ramps of
# packings of the free-ends set tilted at rest without ultrasound to an angle
# and driven from 0.5 deg higher on (AVALANCHE_SWITCH_ON), in
# OUT/switch_on/at<angle>[_k<kappa_scale>]/H<H>/s<seed>, beside the set's own ramps
SWITCH_ON_SET = ("switch_on", "at", "ensemble")
KAPPA_SCALE = re.compile(r"kappa_scale ([0-9.eE+-]+)")


def kappa_scale(log):
    """kappa_scale of a ramp, from the first line of its log that gives it"""
    for line in open(log):
        m = KAPPA_SCALE.search(line)
        if m:
            return float(m.group(1))
    return np.nan


def switch_on_study(top):
    """Rows (H, seed, kappa_scale, first tested angle, theta_m 0 Hz, theta_m
    70 kHz, first spreading flow at 70 kHz, time followed at the angles
    before it (s), mean mu*/mu before theta_m) of the 70 kHz ramps of the
    switch-on study and of the same packings' ramps in the free-ends set
    (ultrasound on from the pre-ramp), sorted by H, packing, kappa_scale and
    first angle: does the creep at the angles before the flow lower theta_m?"""
    rows = {}
    for _, H, seed, d, ref in paired_packings(top, *SWITCH_ON_SET):
        t0 = result(os.path.join(ref, "log.f0"))[0]
        for path in (ref, d):
            log = os.path.join(path, "log.f70")
            t70 = result(log)[0]
            if np.isfinite(t70):
                key = (H, seed, kappa_scale(log), first_angle(log))
                rows[key] = key + (t0, t70, flow_onset(log), time_before_onset(log), last_mu_factor(log))
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
    (in.avalanche's tuniform; run_ensemble.sh with AVALANCHE_TUNIFORM):
    [(hold, [t_con of each run, packing by packing])], the default hold
    first (tcon_runs_at_angle); nan for a run that was not uniform within
    0.1 + tfollow s."""
    rows = [(DEFAULT_TUNIFORM, tcon_runs_at_angle(packs, tag, theta))]
    held = [(h, t) for p in packs for h, th, t, _ in p[f"tcon_{tag}_held"] if th == theta]
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
        print(f"\nslope of θ_m(H/d), all packings: 0 kHz {slope_text(s0)}, "
              f"70 kHz {slope_text(s70)} (paper 000 ≈ {PAPER_SLOPE}°/d)")
        t0, t70 = theta_slope(by_h, "f0", 6.0), theta_slope(by_h, "f70", 6.0)
        print(f"the same from H = 6 d up (paper 000's grey zone of Fig. 7 left out): 0 kHz {slope_text(t0)}, "
              f"70 kHz {slope_text(t70)}")
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
    where runs with another hold (AVALANCHE_TUNIFORM) are there."""
    cases = sorted({(H, tag, th) for H, packs in by_h.items() for p in packs
                    for tag in ("f0", "f70") for _, th, _, _ in p[f"tcon_{tag}_held"]})
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


def thetam_table(rows, path):
    """Fig. 7's table of summarise's rows, written to path and returned:
    H/d, theta_m mean and s.d. at 0 and 70 kHz, paper 000's values."""
    table = [(r["H_measured"], r["theta0"][0], r["theta0"][1], r["theta70"][0], r["theta70"][1])
             + PAPER.get(r["H"], (np.nan, np.nan)) for r in rows]
    with open(path, "w") as f:
        f.writelines(" ".join(f"{v:g}" for v in row) + "\n" for row in table)
    return table


def tcon_rows(all_ens, label, free):
    """Rows ("H<H>_<f>kHz[_free_ends]", theta, t_con) of Fig. 8: theta_m and
    the t_con runs of every packing at H = 6, 11.4 and 14.4 d, each geometry
    once (label: the first geometry; free: the free-ends one, may be the
    same)."""
    geometries = [(label, "_free_ends" if label.startswith("free") else "")]
    if free and free != label:
        geometries.append((free, "_free_ends"))
    rows = []
    for geometry, suffix in geometries:
        for H in (6.0, 11.4, 14.4):
            for p in all_ens.get(geometry, {}).get(H, []):
                for tag in ("f0", "f70"):
                    for th, t in [(p[tag][0], p[tag][1])] + p[f"tcon_{tag}"]:
                        if np.isfinite(th) and np.isfinite(t):
                            rows.append((f"H{H:g}_{tag[1:]}kHz{suffix}", th, t))
    return rows


def tcon_table_lines(all_ens, label, free):
    """The rows of tcon_rows as lines "H<H>_<f>kHz[_free_ends] theta t_con"."""
    return [f"{name} {th:g} {t:g}\n" for name, th, t in tcon_rows(all_ens, label, free)]


def figures(all_ens, summary, top, figdir, couplings=None):
    """Fig. 7 (and, with couplings (coupling_summary), theta_m at 70 kHz at
    other couplings beside it), Fig. 8, and from the dumps where they are
    there Figs. 3, 6/9 and 10, into figdir; their tables (thetam.txt,
    thetam_free.txt, thetam_k<kappa>.txt, tcon.txt) into top."""
    os.makedirs(figdir, exist_ok=True)
    label = "periodic" if "periodic" in all_ens else next(iter(all_ens), None)
    if label is None:
        return
    table7 = thetam_table(summary[label][0], os.path.join(top, "thetam.txt"))
    free = next((g for g in summary if g.startswith("free")), None)
    table7_free = None
    if free and free != label:
        table7_free = thetam_table(summary[free][0], os.path.join(top, "thetam_free.txt"))
    measured = {r["H"]: r["H_measured"] for r in summary[free or label][0]}
    coupling_tables = []
    for kappa, points in (couplings or {}).items():
        table = [(measured.get(H, H), t[0], t[1]) for H, t, _ in points]
        with open(os.path.join(top, f"thetam_k{kappa:g}.txt"), "w") as f:
            f.writelines(" ".join(f"{v:g}" for v in row) + "\n" for row in table)
        coupling_tables.append((table, f"kappa_scale {kappa:g}, switched on at rest"))
    figs.fig_thetam(os.path.join(figdir, "fig7_thetam.png"), table7, label, table7_free, free, coupling_tables, dpi=80)
    by_h = all_ens[label]
    a = PAPER_TCON_ANGLE_H6
    paper = [("paper000_H6_0kHz", a, PAPER_TCON_H6_19DEG[0]), ("paper000_H6_70kHz", a, PAPER_TCON_H6_19DEG[1])]
    with open(os.path.join(top, "tcon.txt"), "w") as f:
        f.writelines(tcon_table_lines(all_ens, label, free))
        f.writelines(f"{name} {theta:g} {t}\n" for name, theta, t in paper)
    figs.fig_tcon(os.path.join(figdir, "fig8_tcon.png"), tcon_rows(all_ens, label, free) + paper, dpi=80)
    for H in (6.0, 14.4):
        packs = by_h.get(H, [])
        if not packs:
            continue
        p = packs[0]
        dump, cont = os.path.join(p["path"], "f70.dump"), os.path.join(p["path"], "f70.contacts")
        if os.path.exists(dump) and os.path.exists(cont):
            frames = read_dump(dump)
            tm = p["f70"][0] if np.isfinite(p["f70"][0]) else 90.0
            below = [i for i, fr in enumerate(frames) if fr["v_th"][0] < tm - 1e-6]
            last, first = frames[below[-1] if below else -1], frames[0]
            figs.fig_chains(os.path.join(figdir, f"fig10_chains_H{H:g}.png"), last,
                            av.contact_columns(av.contacts_at(cont, last.timestep)), dpi=80)
            figs.fig_modes(os.path.join(figdir, f"fig3_modes_H{H:g}.png"),
                           network=(first, av.contact_columns(av.contacts_at(cont, first.timestep))), dpi=80)
        sers = [(os.path.join(p["path"], f"{tag}.series"), p[tag][0]) for tag in ("f0", "f70")
                if np.isfinite(p[tag][0]) and os.path.exists(os.path.join(p["path"], f"{tag}.series"))]
        if sers:
            figs.fig_sigma(os.path.join(figdir, f"fig6_9_sigma_H{H:g}.png"),
                           figs.sigma_runs([s for s, _ in sers], [th for _, th in sers]), dpi=80)
    held = held_series(by_h.get(6.0, []), "f0", PAPER_TCON_ANGLE_H6)
    if held:
        figs.fig_sigma(os.path.join(figdir, "tcon_hold_sigma_H6.png"),
                       figs.sigma_runs(held, [PAPER_TCON_ANGLE_H6] * len(held)), dpi=80)


def held_series(packs, tag, theta):
    """The series of each packing's t_con run at theta with the longest hold
    of the uniform criterion (AVALANCHE_TUNIFORM), where it is there: the
    run followed longest after its flow first became uniform."""
    paths = []
    for p in packs:
        runs = sorted((h, run) for h, th, _, run in p[f"tcon_{tag}_held"] if th == theta)
        path = os.path.join(p["path"], f"{runs[-1][1]}.series") if runs else ""
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


def kappa_figure(rows, kset, top, figdir):
    """The table OUT/<kset>.txt and the figure kappa_shift<suffix>.png of one
    kappa_scale study (rows of kappa_study; suffix "" for kappa, "_free" for
    kappa_free): one figure per study, so that a record holding one of them
    redraws it without touching the other's."""
    if not rows:
        return
    geometry = KAPPA_SETS[kset][1].replace(" ", "_")
    with open(os.path.join(top, f"{kset}.txt"), "w") as f:
        for k, H, seed, t0, t70, shift, mu, onset_shift in rows:
            f.write(f"{k:g} {H:g} {seed} {shift:g} {mu:g} {onset_shift:g} {geometry}\n")
    name = "kappa_shift" + kset[len("kappa"):] + ".png"
    figs.fig_kappa(os.path.join(figdir, name),
                   [(k, H, shift, mu, onset_shift, geometry) for k, H, _, _, _, shift, mu, onset_shift in rows], dpi=80)


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


def collect(top, figdir):
    """Everything of collect.py: the tables of every geometry and study on
    stdout, the figures into figdir, their tables and summary.json (the rows
    and slopes of each geometry) into top."""
    all_ens = ensembles(top)
    summary = {label: summarise(by_h) for label, by_h in all_ens.items()}
    print_tables(all_ens, summary)
    kappa_rows = {kset: kappa_study(top, kset) for kset in KAPPA_SETS}
    for kset, rows in kappa_rows.items():
        print_kappa(rows, KAPPA_SETS[kset][1])
    switch_on = switch_on_study(top)
    print_switch_on(switch_on)
    couplings = coupling_summary(switch_on)
    print_couplings(couplings)
    figures(all_ens, summary, top, figdir, couplings)
    for kset, rows in kappa_rows.items():
        kappa_figure(rows, kset, top, figdir)
    with open(os.path.join(top, "summary.json"), "w") as f:
        json.dump({label: {"rows": rows, "slope0": s0, "slope70": s70} for label, (rows, s0, s70) in summary.items()},
                  f, indent=1, default=float)
