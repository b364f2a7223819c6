"""Analysis of inclined-plane avalanche runs (paper 000, examples/avalanche).

Reads LAMMPS dump files (dump custom of the grains, dump local of the contacts
written by fix acoustic/mindlin; read with acoustic_tools.lammps_output) and the
per-millisecond series file written by examples/avalanche/in.avalanche, and
computes

  sigma_l     Eq. 3.1 of paper 000: normalised standard deviation of the
              downslope velocity in the top (l = 1) and bottom (l = 2) halves of
              the layer, split at the centre of mass of the observed grains;
  E_k/E_t     kinetic over total energy, E_t = E_k + sum m g (y - y_b);
  stability   the 0.1 s window test E_k/E_t < eps_E and the arrest test;
  t_con       the delay from the tilt to a uniform flow (sigma_1 < 0.3 and
              sigma_2 < 0.9 held for a while);
  theta_m     the first angle of a tilt ramp with a uniform flow;
  flow shape  mean velocity of the bottom half over that of the top half
              of the uniform flow (0.40 for Bagnold's profile, 1 for a plug);
  sigma parts what makes sigma_1 of a dump frame: a flow uneven along the
              slope, the velocity profile, grain-scale fluctuations;
  profile     mu*/mu and f_n of the contacts in bins of height above the
              base, at the last dump frame of an angle;
  spectrum    eigenfrequencies of the normal-spring network (paper 000 Eq. 2.9,
              the model of fix acoustic/mindlin "model normal") from a dump
              local with k_n and a dump of the positions and masses.

Units are those of the run (SI for examples/avalanche).  Command line:

    python3 -m acoustic_tools.avalanche sigma   run.dump [--g 9.81]     sigma_1, sigma_2, E_k/E_t per frame
    python3 -m acoustic_tools.avalanche ramp    run.series              state of each angle, theta_m, t_con,
                                                                flow shape at theta_m, sigma_1 of
                                                                the spreading flows
    python3 -m acoustic_tools.avalanche uniform run.series [--theta 19] [--holds 0.01 0.1]
                                                                uniform stretches of one angle, t_con
                                                                with the criteria held longer
    python3 -m acoustic_tools.avalanche sigma-parts run.dump [--obs 0.3 0.7] [--dx 20] [--theta 14 14.5] [--per-frame]
                                                                the parts of sigma_1 at each angle
    python3 -m acoustic_tools.avalanche profile run.dump run.contacts --theta 10.5 [--dz 2] [--obs 0.3 0.7]
                                                                mu*/mu against the height
    python3 -m acoustic_tools.avalanche spectrum run.dump run.contacts  frequency quantiles of the network
                                     [--frame 0] [--above 70e3]  and the fraction of modes above 70 kHz
    python3 -m acoustic_tools.avalanche band modes.hist [--drive 70e3] [--shares 0.99 0.999]
                                                                where the drive falls in a density of
                                                                states (in.modes, method dense or kpm)
"""
import argparse
import sys
from dataclasses import dataclass

import numpy as np

from .lammps_output import Snapshot, read_ave_time_vector, read_dump

EPS_E = 3e-8      # paper 000: E_k/E_t threshold of a stable state
EPS_SIGMA1 = 0.3  # paper 000: sigma_1 (top half) of a uniform flow
EPS_SIGMA2 = 0.9  # paper 000: sigma_2 (bottom half) of a uniform flow
FSPREAD = 0.5     # in.avalanche: mobile fraction of a flow that spreads


# ---------------------------------------------------------------- reading

CONTACT_COLUMNS = ["i", "j", "fn", "kn", "Ut", "mu_ratio"]


def contact_columns(frame):
    """Name the six columns of fix acoustic/mindlin's local array (dump local f_ID[1..6])."""
    names = list(frame.columns)
    if all(c in frame.columns for c in CONTACT_COLUMNS):
        return frame
    if len(names) != 6:
        raise ValueError(f"expected the 6 columns of fix acoustic/mindlin, got {names}")
    return Snapshot(frame.timestep, frame.box,
                    {new: frame.columns[old] for new, old in zip(CONTACT_COLUMNS, names)})


def rows_of(atoms, ids):
    """Row of each atom ID (e.g. a contact's i or j column) in a dump frame."""
    index = {int(t): k for k, t in enumerate(atoms["id"])}
    return np.array([index[int(t)] for t in ids], int)


SERIES_COLUMNS = ["time", "theta", "ratio", "sigma1", "sigma2", "vx1", "vx2", "mobile",
                  "mu_mean", "frac_weak"]


def read_series(path):
    """The per-millisecond series of in.avalanche (fix print): a dict of arrays."""
    data = np.loadtxt(path, comments="#", ndmin=2)
    return {name: data[:, c] for c, name in enumerate(SERIES_COLUMNS[:data.shape[1]])}


# ---------------------------------------------------------------- per frame

def layer_masks(y, split=None):
    """Top and bottom halves of a layer, split at `split` (default: mean height)."""
    y = np.asarray(y, float)
    if split is None:
        split = y.mean()
    return y > split, y <= split


def sigma_l(vx):
    """Eq. 3.1: std(vx) / |mean(vx)| of one layer (inf when the mean is zero)."""
    vx = np.asarray(vx, float)
    if vx.size == 0:
        return np.inf
    mean = vx.mean()
    std = np.sqrt(max(np.mean(vx * vx) - mean * mean, 0.0))
    return std / abs(mean) if mean != 0 else np.inf


def sigma_layers(y, vx, split=None):
    """(sigma_1, sigma_2) of the top and bottom halves of the observed grains."""
    top, bottom = layer_masks(y, split)
    vx = np.asarray(vx, float)
    return sigma_l(vx[top]), sigma_l(vx[bottom])


def energy_ratio(mass, y, vx, vy, g, yb, radius=None, omega=None):
    """E_k / E_t with E_t = E_k + sum m g (y - yb); rotations counted when given."""
    mass = np.asarray(mass, float)
    ek = 0.5 * np.sum(mass * (np.asarray(vx) ** 2 + np.asarray(vy) ** 2))
    if radius is not None and omega is not None:
        ek += 0.5 * np.sum(0.4 * mass * np.asarray(radius) ** 2 * np.asarray(omega) ** 2)
    ep = np.sum(mass * g * (np.asarray(y, float) - yb))
    return ek / (ek + ep)


def observed_grains(frame, obs=(0.0, 1.0), grain_type=1, base_type=2):
    """Mask of the grains in the observed x range (fractions of the box),
    their mean diameter and the top of the base."""
    t = frame["type"]
    lo, hi = frame.box[0]
    x = frame["x"]
    inobs = (t == grain_type) & (x >= lo + obs[0] * (hi - lo)) & (x < lo + obs[1] * (hi - lo))
    d = 2.0 * np.mean(frame["radius"][t == grain_type])
    yb = frame["y"][t == base_type].max() if np.any(t == base_type) else frame["y"].min()
    return inobs, d, yb


def frame_observables(frame, g=9.81, grain_type=1, base_type=2, obs=(0.0, 1.0)):
    """sigma_1, sigma_2, E_k/E_t and the angle column (if any) of one dump frame."""
    grains = frame["type"] == grain_type
    inobs, _, yb = observed_grains(frame, obs, grain_type, base_type)
    s1, s2 = sigma_layers(frame["y"][inobs], frame["vx"][inobs])
    omega = frame.columns.get("omegaz")
    radius = frame.columns.get("radius")
    ratio = energy_ratio(frame["mass"][grains], frame["y"][grains], frame["vx"][grains],
                         frame["vy"][grains], g, yb,
                         None if radius is None else radius[grains],
                         None if omega is None else omega[grains])
    theta = frame["v_th"][0] if "v_th" in frame and len(frame) else np.nan
    return {"timestep": frame.timestep, "theta": theta, "sigma1": s1, "sigma2": s2, "ratio": ratio}


def one_hot(labels):
    """Indicator matrix of integer labels, one column per distinct label."""
    _, k = np.unique(labels, return_inverse=True)
    return np.eye(k.max() + 1)[k]


def sigma1_parts(frame, obs=(0.0, 1.0), dx=20.0, dz=1.0):
    """What makes sigma_1 (Eq. 3.1, top half of the observed layer) of one
    frame.  The downslope velocities of the top half are fitted by a mean
    plus an effect of the column (dx grain diameters along the slope) plus
    an effect of the height (dz diameters above the base), by least squares:

      along     std of the column effects / mean: a flow that has not spread
                evenly along the layer,
      depth     std of the height effects / mean: the velocity profile,
      residual  std of what is left / mean: grain-scale fluctuations,
      fluct_over_shear  std of what is left / (shear rate d), the shear rate
                being (v1 - v2) over the distance between the mean heights
                of the top and bottom halves,

    with v1, v2 the mean velocities of the top and bottom halves, sigma1
    itself and the mean grain diameter d.  For orthogonal parts sigma1^2 = along^2 + depth^2 + residual^2."""
    inobs, d, yb = observed_grains(frame, obs)
    x, y, vx = frame["x"][inobs], frame["y"][inobs], frame["vx"][inobs]
    top, bottom = layer_masks(y)
    v1, v2 = vx[top].mean(), vx[bottom].mean()
    column = np.floor((x[top] - x.min()) / (dx * d)).astype(int)
    height = np.floor((y[top] - yb) / (dz * d) + 1e-9).astype(int)
    cols, rows = one_hot(column), one_hot(height)
    design = np.hstack([cols, rows])
    coef = np.linalg.lstsq(design, vx[top] - v1, rcond=None)[0]
    along = cols @ coef[:cols.shape[1]]
    depth = rows @ coef[cols.shape[1]:]
    residual = vx[top] - v1 - along - depth
    shear_rate = (v1 - v2) / (y[top].mean() - y[bottom].mean())
    return {"v1": v1, "v2": v2, "sigma1": sigma_l(vx[top]), "along": np.std(along) / abs(v1),
            "depth": np.std(depth) / abs(v1), "residual": np.std(residual) / abs(v1),
            "fluct_over_shear": np.std(residual) / abs(shear_rate * d), "d": d}


SIGMA1_PARTS = ("sigma1", "along", "depth", "residual", "fluct_over_shear")


def sigma1_parts_by_angle(frames, obs=(0.0, 1.0), dx=20.0, thetas=None):
    """[(theta, medians of sigma1_parts over the frames at theta)] for the
    angles of a ramp dump (or those in `thetas`), with the number of frames
    ("frames")."""
    by_angle = {}
    for frame in frames:
        theta = float(frame["v_th"][0])
        if thetas is None or np.any(np.isclose(theta, thetas)):
            by_angle.setdefault(theta, []).append(sigma1_parts(frame, obs, dx))
    out = []
    for theta, rows in sorted(by_angle.items()):
        med = {k: float(np.median([r[k] for r in rows])) for k in rows[0]}
        med["frames"] = len(rows)
        out.append((theta, med))
    return out


def contact_heights(atoms, contacts, grain_type=1, base_type=2):
    """Height of each contact's midpoint above the top of the base, in mean
    grain diameters, and its x (that of the contact's first grain)."""
    contacts = contact_columns(contacts)
    i, j = rows_of(atoms, contacts["i"]), rows_of(atoms, contacts["j"])
    t = atoms["type"]
    d = 2.0 * np.mean(atoms["radius"][t == grain_type])
    yb = atoms["y"][t == base_type].max() if np.any(t == base_type) else atoms["y"].min()
    return (0.5 * (atoms["y"][i] + atoms["y"][j]) - yb) / d, atoms["x"][i]


def binned_means(z, values, edges):
    """Mean of `values` and their count in the bins [edges[k], edges[k + 1])
    of z (nan where a bin is empty)."""
    z, values = np.asarray(z, float), np.asarray(values, float)
    k = np.digitize(z, edges) - 1
    inside = (k >= 0) & (k < len(edges) - 1)
    count = np.bincount(k[inside], minlength=len(edges) - 1)
    total = np.bincount(k[inside], values[inside], minlength=len(edges) - 1)
    with np.errstate(invalid="ignore", divide="ignore"):
        return total / count, count


def friction_profile(atoms, contacts, dz=2.0, obs=(0.0, 1.0)):
    """mu*/mu against the height above the base: one row (z_lo, z_hi,
    contacts, mean mu*/mu, fraction with mu*/mu < 0.5, mean f_n) per
    non-empty bin of height dz (grain diameters), over the contacts whose
    first grain lies in the observed x range (fractions of the box)."""
    c = contact_columns(contacts)
    z, x = contact_heights(atoms, c)
    lo, hi = atoms.box[0]
    inobs = (x >= lo + obs[0] * (hi - lo)) & (x < lo + obs[1] * (hi - lo))
    z, mu, fn = z[inobs], c["mu_ratio"][inobs], c["fn"][inobs]
    edges = np.arange(0.0, z.max() + dz, dz)
    mean_mu, n = binned_means(z, mu, edges)
    weak, mean_fn = binned_means(z, mu < 0.5, edges)[0], binned_means(z, fn, edges)[0]
    return [(edges[k], edges[k + 1], n[k], mean_mu[k], weak[k], mean_fn[k]) for k in np.flatnonzero(n)]


def contacts_at(path, timestep):
    """The frame of a contacts dump local written at `timestep`."""
    match = [c for c in read_dump(path) if c.timestep == timestep]
    if not match:
        sys.exit(f"no contact frame at timestep {timestep} in {path}")
    return match[0]


def last_frame_at(frames, theta):
    """The last frame of a dump whose angle column v_th is theta."""
    at = [f for f in frames if len(f) and np.isclose(f["v_th"][0], theta)]
    if not at:
        raise ValueError(f"no dump frame at {theta:g} deg; angles are "
                         f"{sorted({float(f['v_th'][0]) for f in frames if len(f)})}")
    return at[-1]


# ---------------------------------------------------------------- protocol

def runs_of(flags):
    """Length of the run of True ending at each sample."""
    out = np.zeros(len(flags), int)
    n = 0
    for k, f in enumerate(flags):
        n = n + 1 if f else 0
        out[k] = n
    return out


@dataclass
class AngleResult:
    theta: float
    state: str            # stable | stopped | local | partial | uniform
    duration: float       # time spent at this angle
    t_con: float          # delay to a uniform flow (nan unless uniform)
    max_ratio: float      # max E_k/E_t after the first nhold samples


def classify_angle(time, ratio, sigma1, sigma2, mobile, dt=1e-3, twin=0.1, thold=0.01,
                   eps_e=EPS_E, eps1=EPS_SIGMA1, eps2=EPS_SIGMA2, fspread=FSPREAD, theta=np.nan, tfollow=1.2):
    """Paper 000's test at one angle, on samples taken every dt after the tilt.

    Same rules as in.avalanche: uniform as soon as sigma_1 < eps1, sigma_2 < eps2
    and more than fspread of the grains mobile hold for thold (t_con = time of the
    first of those samples, measured from the tilt); static (stable, or stopped
    if E_k/E_t exceeded eps_E after the first thold) once the window twin is over
    and E_k/E_t < eps_E held for thold; a rearrangement is followed until it
    arrests or twin + tfollow have passed: local if still moving then with at
    most fspread of the grains mobile; partial otherwise (also a series that
    ends earlier, as the last angle of an interrupted run).
    `time` is the sample time measured from the tilt (first sample at dt).
    """
    time, ratio = np.asarray(time, float), np.asarray(ratio, float)
    sigma1, sigma2, mobile = (np.asarray(a, float) for a in (sigma1, sigma2, mobile))
    nhold = int(round(thold / dt))
    nwin = int(round(twin / dt))
    ntot = int(round((twin + tfollow) / dt))
    quiet = runs_of(ratio < eps_e)
    uniform = runs_of((sigma1 < eps1) & (sigma2 < eps2) & (mobile > fspread))
    rmax = 0.0
    for k in range(len(time)):
        ic = k + 1
        if ic > nhold:
            rmax = max(rmax, ratio[k])
        if uniform[k] >= nhold:
            first = k - nhold + 1
            return AngleResult(theta, "uniform", time[k], time[first] - dt, rmax)
        if ic >= nwin and quiet[k] >= nhold:
            return AngleResult(theta, "stable" if rmax < eps_e else "stopped", time[k], np.nan, rmax)
        if ic == ntot and mobile[k] < fspread:
            return AngleResult(theta, "local", time[k], np.nan, rmax)
    return AngleResult(theta, "partial", time[-1] if len(time) else 0.0, np.nan, rmax)


def split_by_angle(series):
    """Consecutive samples of a series at the same angle: list of (theta, index array)."""
    theta = np.asarray(series["theta"])
    if theta.size == 0:
        return []
    edges = np.flatnonzero(np.diff(theta) != 0) + 1
    return [(theta[idx[0]], idx) for idx in np.split(np.arange(theta.size), edges)]


def angle_samples(series, dt=1e-3):
    """(theta, time since the tilt, index array) of each angle of a series.
    The tilt happened at the last sample of the previous angle; a sample
    printed at that same time (fix print at the set-up of a run) is dropped."""
    for theta, idx in split_by_angle(series):
        t0 = series["time"][idx[0] - 1] if idx[0] > 0 else series["time"][idx[0]] - dt
        idx = idx[series["time"][idx] > t0 + 1e-9 * dt]
        yield theta, series["time"][idx] - t0, idx


def ramp_results(series, dt=1e-3, first_theta=None, **kw):
    """classify_angle() for each angle of a tilt-ramp series (pre-ramp angles skipped)."""
    results = []
    for theta, time, idx in angle_samples(series, dt):
        if first_theta is not None and theta < first_theta - 1e-9:
            continue
        results.append(classify_angle(time, series["ratio"][idx], series["sigma1"][idx], series["sigma2"][idx],
                                      series["mobile"][idx], dt=dt, theta=theta, **kw))
    return results


def theta_m(results):
    """(theta_m, t_con) of the first uniform angle of a ramp, (nan, nan) if none."""
    for r in results:
        if r.state == "uniform":
            return r.theta, r.t_con
    return np.nan, np.nan


def bottom_to_top_velocity(series, theta, nsamples=10):
    """Mean downslope velocity of the bottom half of the observed layer over
    that of its top half (series columns vx2 / vx1) in the last `nsamples`
    samples at angle `theta`: the shape of a flow, 0.40 for Bagnold's profile
    v ~ 1 - (1 - z/H)^(3/2), 1/3 for a linear one, 1 for a plug sliding on
    its base.  At theta_m these are the samples of the uniform hold, where
    in.avalanche stops a ramp."""
    idx = np.flatnonzero(np.isclose(series["theta"], theta))[-nsamples:]
    return float(np.mean(series["vx2"][idx]) / np.mean(series["vx1"][idx]))


def sigma1_spread(series, theta, fspread=FSPREAD):
    """(median, 10th percentile) of sigma_1 over the samples at angle `theta`
    in which more than fspread of the grains are mobile (nan if none): how
    far a spreading flow is from the criterion, and how deep it dips."""
    idx = np.flatnonzero(np.isclose(series["theta"], theta) & (series["mobile"] > fspread))
    if idx.size == 0:
        return np.nan, np.nan
    values = series["sigma1"][idx]
    return float(np.median(values)), float(np.percentile(values, 10))


def uniform_streaks(time, sigma1, sigma2, mobile=None, eps1=EPS_SIGMA1, eps2=EPS_SIGMA2, fspread=FSPREAD):
    """(time of the first sample, number of samples) of every stretch of
    consecutive samples with sigma_1 < eps1 and sigma_2 < eps2 (and more
    than fspread of the grains mobile, when `mobile` is given)."""
    ok = (np.asarray(sigma1) < eps1) & (np.asarray(sigma2) < eps2)
    if mobile is not None:
        ok &= np.asarray(mobile) > fspread
    n = runs_of(ok)
    ends = np.flatnonzero(ok & np.append(~ok[1:], True))
    time = np.asarray(time, float)
    return [(float(time[k - n[k] + 1]), int(n[k])) for k in ends]


def t_con(time, sigma1, sigma2, eps1=EPS_SIGMA1, eps2=EPS_SIGMA2, hold=1, mobile=None, fspread=FSPREAD):
    """First time from which the criteria of uniform_streaks() hold for `hold` samples."""
    for start, samples in uniform_streaks(time, sigma1, sigma2, mobile, eps1, eps2, fspread):
        if samples >= hold:
            return start
    return np.nan


def uniform_at_angle(series, theta=None, holds=(0.01, 0.05, 0.1, 0.2, 0.4), dt=1e-3):
    """The uniform stretches of one angle of a series (default: the last
    one, the angle of a t_con run): (theta, duration of the series at that
    angle, [(start, length)] in s from the tilt, {hold: t_con} with the
    criteria held that long (nan if not within the series), fraction of the
    time uniform from the first stretch to the end).  Times count as
    in.avalanche's t_con: from the tilt to the start of a sample's ms."""
    found = [a for a in angle_samples(series, dt) if theta is None or np.isclose(a[0], theta)]
    if not found:
        raise ValueError(f"no samples at theta = {theta}")
    theta, time, idx = found[-1]
    cols = (time - dt, series["sigma1"][idx], series["sigma2"][idx])
    streaks = uniform_streaks(*cols, mobile=series["mobile"][idx])
    tcons = {h: t_con(*cols, hold=int(round(h / dt)), mobile=series["mobile"][idx]) for h in holds}
    covered = sum(n for _, n in streaks) * dt / (time[-1] - streaks[0][0]) if streaks else np.nan
    return theta, float(time[-1]), [(t, n * dt) for t, n in streaks], tcons, covered


# ---------------------------------------------------------------- vibration network

def network_spectrum(atoms, contacts, fixed_types=(2,), dim=2):
    """Eigenfrequencies (Hz if SI) of the normal-spring network of paper 000.

    K = sum_c k_n (e_i - e_j)(e_i - e_j)^T (x) n n^T over the contacts of the dump
    local (tags i, j and k_n of fix acoustic/mindlin), M = diag(m); atoms of
    `fixed_types` are clamped (the frozen base).  Periodic images along x are
    resolved with the box of the atom frame.  Returns sorted frequencies of the
    free degrees of freedom (zero modes included).
    """
    contacts = contact_columns(contacts)
    ids = atoms["id"].astype(int)
    free = ~np.isin(atoms["type"].astype(int), fixed_types)
    dof = -np.ones(len(ids), int)
    dof[free] = np.arange(free.sum())
    nfree = free.sum() * dim
    K = np.zeros((nfree, nfree))
    pos = np.column_stack([atoms["x"], atoms["y"]])[:, :dim]
    lx = atoms.box[0, 1] - atoms.box[0, 0]
    for a, b, kn in zip(rows_of(atoms, contacts["i"]), rows_of(atoms, contacts["j"]), contacts["kn"]):
        r = pos[a] - pos[b]
        r[0] -= lx * np.round(r[0] / lx)
        n = r / np.linalg.norm(r)
        block = kn * np.outer(n, n)
        for p, q, sign in ((a, a, 1), (b, b, 1), (a, b, -1), (b, a, -1)):
            if dof[p] >= 0 and dof[q] >= 0:
                K[dof[p] * dim:dof[p] * dim + dim, dof[q] * dim:dof[q] * dim + dim] += sign * block
    m = np.repeat(atoms["mass"][free], dim)
    D = K / np.sqrt(np.outer(m, m))
    w2 = np.linalg.eigvalsh(D)
    return np.sqrt(np.clip(w2, 0.0, None)) / (2.0 * np.pi)


def nonzero_modes(frequencies):
    """The frequencies above 1e-6 of the highest (the zero modes left out)."""
    return frequencies[frequencies > 1e-6 * frequencies.max()]


def fraction_above(frequencies, f):
    """Fraction of the non-zero modes with a frequency above f: where a
    drive at f falls in the band."""
    return float((nonzero_modes(frequencies) > f).mean())


def band_from_density(centres, density, drive, shares=(0.99, 0.999)):
    """Where a drive falls in a density of states given on equal bins
    (compute vibration/modes ... bins, e.g. method kpm on a layer too large
    for the dense eigensolver): the share of the modes below the drive, and
    the frequencies below which the given shares of the modes lie (the top
    of the band).  The density is per unit frequency at the bin centres and
    taken uniform within a bin; negative values (the noise of the stochastic
    traces of method kpm, where the true density is small) count as none."""
    width = centres[1] - centres[0]
    upper = centres + width / 2.0
    cumulative = np.concatenate(([0.0], np.cumsum(np.clip(density, 0.0, None) * width)))
    cumulative /= cumulative[-1]
    edges = np.concatenate(([upper[0] - width], upper))
    below = float(np.interp(drive, edges, cumulative))
    return below, [float(np.interp(s, cumulative, edges)) for s in shares]


# ---------------------------------------------------------------- command line

def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("sigma", help="sigma_1, sigma_2, E_k/E_t of each dump frame")
    s.add_argument("dump")
    s.add_argument("--g", type=float, default=9.81)
    s.add_argument("--obs", type=float, nargs=2, default=(0.0, 1.0), help="observed x range (fractions of the box)")
    r = sub.add_parser("ramp", help="angle-by-angle states, theta_m and t_con from a series file")
    r.add_argument("series")
    r.add_argument("--theta0", type=float, default=None, help="first tested angle (skips the pre-ramp)")
    r.add_argument("--epsE", type=float, default=EPS_E)
    r.add_argument("--tfollow", type=float, default=1.2, help="s a rearrangement is followed after the window "
                   "(in.avalanche's tfollow; the demo uses 0.3)")
    u = sub.add_parser("uniform", help="where the flow of one angle is uniform (a t_con run: the last angle), "
                       "and t_con with the criteria held for several times")
    u.add_argument("series")
    u.add_argument("--theta", type=float, default=None, help="angle (deg; default the last of the series)")
    u.add_argument("--holds", type=float, nargs="+", default=[0.01, 0.05, 0.1, 0.2, 0.4], help="hold times (s)")
    u.add_argument("--min", type=float, default=0.005, help="shortest uniform stretch listed (s)")
    pr = sub.add_parser("profile", help="mu*/mu and f_n of the contacts against the height above the base")
    pr.add_argument("dump")
    pr.add_argument("contacts")
    pr.add_argument("--theta", type=float, required=True, help="angle (deg): its last dump frame is used")
    pr.add_argument("--dz", type=float, default=2.0, help="bin height in grain diameters")
    pr.add_argument("--obs", type=float, nargs=2, default=(0.0, 1.0), help="observed x range (fractions of the box)")
    sg = sub.add_parser("sigma-parts", help="what makes sigma_1 at each angle: flow along the slope, "
                        "velocity profile, grain-scale fluctuations (medians over the angle's frames)")
    sg.add_argument("dump")
    sg.add_argument("--g", type=float, default=9.81)
    sg.add_argument("--obs", type=float, nargs=2, default=(0.0, 1.0), help="observed x range (fractions of the box)")
    sg.add_argument("--dx", type=float, default=20.0, help="column width along the slope, grain diameters")
    sg.add_argument("--theta", type=float, nargs="*", default=None, help="angles to report (default: all)")
    sg.add_argument("--per-frame", action="store_true", help="one line per dump frame (first column the "
                    "timestep) instead of the medians of each angle")
    bd = sub.add_parser("band", help="where a drive falls in a density of states (histogram file of "
                        "examples/avalanche/in.modes, any method)")
    bd.add_argument("hist")
    bd.add_argument("--drive", type=float, default=70e3)
    bd.add_argument("--shares", type=float, nargs="+", default=[0.99, 0.999])
    sp = sub.add_parser("spectrum", help="eigenfrequencies of the contact network")
    sp.add_argument("dump")
    sp.add_argument("contacts")
    sp.add_argument("--frame", type=int, default=-1)
    sp.add_argument("--above", type=float, nargs="+", default=[],
                    help="also print the fraction of the non-zero modes above these frequencies")
    a = p.parse_args(argv)
    if a.cmd == "sigma":
        print("# step theta sigma1 sigma2 Ek/Et")
        for fr in read_dump(a.dump):
            o = frame_observables(fr, g=a.g, obs=a.obs)
            print(f"{o['timestep']} {o['theta']:g} {o['sigma1']:.4g} {o['sigma2']:.4g} {o['ratio']:.4g}")
    elif a.cmd == "ramp":
        series = read_series(a.series)
        res = ramp_results(series, first_theta=a.theta0, eps_e=a.epsE, tfollow=a.tfollow)
        for x in res:
            spread = ""
            if x.state in ("partial", "uniform"):
                spread = "  sigma1 median {:.3f}, 10th percentile {:.3f}".format(*sigma1_spread(series, x.theta))
            print(f"theta {x.theta:5.2f}  {x.state:8s} after {x.duration:.3f} s  max Ek/Et {x.max_ratio:.2e}"
                  + (f"  t_con {x.t_con:.3f} s" if x.state == "uniform" else "") + spread)
        tm, tc = theta_m(res)
        print(f"theta_m = {tm:g} deg  t_con = {tc:.3f} s")
        if np.isfinite(tm):
            print(f"bottom/top half velocity of the uniform flow: {bottom_to_top_velocity(series, tm):.3f} "
                  "(Bagnold profile 0.40, linear 0.33, plug 1)")
    elif a.cmd == "uniform":
        theta, end, streaks, tcons, covered = uniform_at_angle(read_series(a.series), a.theta, a.holds)
        print(f"theta {theta:g} deg, {end:.3f} s after the tilt; uniform stretches of {a.min * 1e3:g} ms or more "
              "(start s, length ms): " + ", ".join(f"{t:.3f} {n * 1e3:.0f}" for t, n in streaks if n >= a.min - 1e-9))
        print(f"uniform {covered:.0%} of the time from the first stretch to the end" if streaks else "never uniform")
        print("t_con with the criteria held " + ", ".join(
            f"{h:g} s: " + (f"{t:.3f} s" if np.isfinite(t) else "—") for h, t in tcons.items()))
    elif a.cmd == "profile":
        atoms = last_frame_at(read_dump(a.dump), a.theta)
        print(f"# timestep {atoms.timestep}, {a.theta:g} deg: z/d (bin) contacts mean_mu*/mu "
              f"fraction_mu*/mu<0.5 mean_f_n")
        for z0, z1, n, mu, weak, fn in friction_profile(atoms, contacts_at(a.contacts, atoms.timestep), a.dz, a.obs):
            print(f"{z0:g}-{z1:g} {n} {mu:.3f} {weak:.2f} {fn:.4g}")
    elif a.cmd == "sigma-parts":
        def line(first, theta, parts):
            return (f"{first} {theta:5.2f} {parts['v1'] / np.sqrt(a.g * parts['d']):.3f} "
                    f"{parts['v2'] / parts['v1']:.3f} " + " ".join(f"{parts[k]:.3f}" for k in SIGMA1_PARTS))
        frames = read_dump(a.dump)
        print(f"# {'timestep' if a.per_frame else 'frames'} theta v1/sqrt(gd) v2/v1 sigma1 along depth "
              "residual fluct/(shear_rate d)")
        if a.per_frame:
            for frame in frames:
                theta = float(frame["v_th"][0])
                if a.theta is None or np.any(np.isclose(theta, a.theta)):
                    print(line(frame.timestep, theta, sigma1_parts(frame, a.obs, a.dx)))
        else:
            for theta, parts in sigma1_parts_by_angle(frames, a.obs, a.dx, a.theta):
                print(line(parts["frames"], theta, parts))
    elif a.cmd == "band":
        rows = read_ave_time_vector(a.hist)[-1][1]              # last block: centre, density[, error]
        below, tops = band_from_density(rows[:, 0], rows[:, 1], a.drive, a.shares)
        print(f"{below:.2%} of the modes below {a.drive:g}; " + ", ".join(
            f"{s:.1%} below {f:.4g}" for s, f in zip(a.shares, tops)))
    elif a.cmd == "spectrum":
        atoms = read_dump(a.dump)[a.frame]
        f = network_spectrum(atoms, contacts_at(a.contacts, atoms.timestep))
        nz = nonzero_modes(f)
        q = np.percentile(nz, [1, 10, 50, 90, 99, 100])
        print(f"{len(f)} modes, {len(f) - len(nz)} zero; frequency percentiles 1/10/50/90/99/100: "
              + " ".join(f"{v:.4g}" for v in q))
        for x in a.above:
            print(f"fraction of the non-zero modes above {x:g}: {fraction_above(f, x):.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
