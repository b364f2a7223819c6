"""Analysis of granular lid-driven cavity runs (paper 004, Kneib et al., PRE 96,
042906, 2017; examples/cavity).

Turns the standard LAMMPS outputs of a cavity run, read with
acoustic_tools.lammps_output, into paper 004's quantities:

  chunks      time_average_chunks (the blocks of fix ave/chunk on a bin/2d
              grid averaged in time: the mean velocity field);
  Eq. 1-3     pressure_from_NP, velocity_from_NU, inertial_number (I_M) and
              inertial_number_from_NP_NU;
  Eq. 4       mean_force_model and fit_mean_force (F/(PLd) against I_M);
  Fig. 3a     stream_function and vortex_centre (ell/L, the distance of the
              vortex centre from the right wall over L);
  Eq. 6       autocorrelation, correlation_time and portion_correlation_times
              (Delta t_c at C = 0.15, Figs. 8-10);
  Eq. 7       trunc_lognormal_pdf, trunc_lognormal_cdf, sample_trunc_lognormal,
              trunc_lognormal_loglik and fit_trunc_lognormal (maximum
              likelihood, Nelder-Mead, Figs. 12-14), eq7_location_spread
              (what stays determined in the Gaussian limit f0 -> infinity);
  PDFs        normalised_pdf (density of values / mean), mean_portion_pdf (the
              mean over portions 3..9 of Fig. 14b);
  wall        portion_forces and portion_force_series (force on n equal
              portions of the wall, bottom first, from contact positions);
  Sec. II     volume_fraction_3d (Phi_3D = 2/3 Phi_2D).

Units are those of the run (SI for examples/cavity).  Typical use:

    from acoustic_tools import cavity, lammps_output
    wall = lammps_output.read_ave_time("run.wall.txt")   # F, F_1 .. F_10
    C = cavity.autocorrelation(wall["F_5"], 2000)
    dtc = cavity.correlation_time(C, dt_record)
    flow, counts = cavity.time_average_chunks(lammps_output.read_ave_chunk("run.flow"))
    x0, y0, ell_L = cavity.vortex_centre(flow["Coord1"], flow["Coord2"],
                                         flow["vx"], flow["vy"], L)
    mu, sigma, f0 = cavity.fit_trunc_lognormal(F / F.mean())

numpy and scipy only; figures are in cavity_figures.py.
"""
import math

import numpy as np
from scipy import optimize, special

PAPER_EQ4 = (0.53, 0.86, 0.02)    # paper 004 Fig. 3b: r1, r2, I_M^0 of Eq. 4
THRESHOLD = 0.15                  # paper 004 Eq. 6: C(Delta t_c) = 0.15


# ---------------------------------------------------------------------------
# the mean flow

def time_average_chunks(blocks, first_step=None):
    """Average of the blocks of lammps_output.read_ave_chunk (those with timestep >=
    first_step if given): (columns, total_counts).

    Each value column is the Ncount-weighted mean over the blocks, NaN in
    chunks whose total count is zero; 'Chunk', 'OrigID' and 'Coord*' are
    those of the first block; 'Ncount' is the mean count per block.
    total_counts is the sum of Ncount over the blocks."""
    if first_step is not None:
        blocks = [(step, cols) for step, cols in blocks if step >= first_step]
    if not blocks:
        raise ValueError("no block to average")
    nchunk = len(blocks[0][1]["Ncount"])
    if any(len(cols["Ncount"]) != nchunk for _, cols in blocks):
        raise ValueError("the blocks have different numbers of chunks; average them by hand")
    counts = np.array([cols["Ncount"] for _, cols in blocks])
    total = counts.sum(axis=0)
    first = blocks[0][1]
    out = {}
    for name in first:
        if name in ("Chunk", "OrigID") or name.startswith("Coord"):
            out[name] = first[name].copy()
        elif name == "Ncount":
            out[name] = total / len(blocks)
        else:
            weighted = sum(cols[name] * n for (_, cols), n in zip(blocks, counts))
            with np.errstate(invalid="ignore", divide="ignore"):
                out[name] = np.where(total > 0, weighted / np.where(total > 0, total, 1.0), np.nan)
    return out, total


# ---------------------------------------------------------------------------
# Eq. 1-4: control parameters and the mean force

def pressure_from_NP(NP, phi, rho_p, g, H):
    """Eq. 1: P = N_P Phi rho_p g H"""
    return NP * phi * rho_p * g * H


def velocity_from_NU(NU, g, d):
    """Eq. 2: U = N_U sqrt(g d)"""
    return NU * np.sqrt(g * d)


def inertial_number(d, rho_p, phi, P, H, U):
    """Eq. 3: I_M = d sqrt(rho / P) / (H / U), rho = Phi rho_p"""
    return d * np.sqrt(phi * rho_p / P) * U / H


def inertial_number_from_NP_NU(NP, NU, d_over_H):
    """Eq. 3 through Eq. 1 and 2: I_M = N_U N_P^(-1/2) (d/H)^(3/2),
    independent of g, rho_p and Phi.  Paper 004's quoted I_M (6.09e-2 for
    N_U = 10, N_P = 1; 1.2e-3 for N_U = 1, N_P = 25) are those of d/H = 1/30."""
    return NU / np.sqrt(NP) * d_over_H ** 1.5


def volume_fraction_3d(phi2d):
    """Sec. II: the 3D equivalent of a 2D solid fraction, Phi_3D = 2/3 Phi_2D"""
    return 2.0 / 3.0 * np.asarray(phi2d, float)


def mean_force_model(I, r1, r2, I0):
    """Eq. 4 over P L d: F/(PLd) = r1 + (r2 - r1) / (1 + I0 / I)"""
    I = np.asarray(I, float)
    return r1 + (r2 - r1) / (1.0 + I0 / I)


def fit_mean_force(I, Fnorm, sigma=None):
    """Least-squares fit of Eq. 4 to F/(PLd) against I_M (ln I0 is the fitted
    parameter).  sigma: optional standard deviations of Fnorm; without them
    the errors are scaled by the scatter of the residuals.  Returns
    ((r1, r2, I0), (s_r1, s_r2, s_I0)), standard errors from the covariance
    (s_I0 = I0 s_lnI0)."""
    I = np.asarray(I, float)
    Fnorm = np.asarray(Fnorm, float)
    keep = np.isfinite(I) & np.isfinite(Fnorm) & (I > 0)
    I, Fnorm = I[keep], Fnorm[keep]
    if sigma is not None:
        sigma = np.asarray(sigma, float)[keep]
    if len(I) < 4:
        raise ValueError(f"Eq. 4 has 3 parameters; {len(I)} points are too few")
    order = np.argsort(I)
    quarter = max(1, len(I) // 4)
    r1 = Fnorm[order[:quarter]].mean()
    r2 = Fnorm[order[-quarter:]].mean()
    # I0 where F/(PLd) is closest to half-way
    lnI0 = math.log(I[np.argmin(np.abs(Fnorm - 0.5 * (r1 + r2)))])

    def model(x, a, b, c):
        return a + (b - a) / (1.0 + np.exp(c) / x)

    p, cov = optimize.curve_fit(model, I, Fnorm, p0=(r1, r2, lnI0), sigma=sigma,
                                absolute_sigma=sigma is not None, maxfev=20000)
    err = np.sqrt(np.diag(cov))
    I0 = math.exp(p[2])
    return (p[0], p[1], I0), (err[0], err[1], I0 * err[2])


# ---------------------------------------------------------------------------
# Fig. 3a: the vortex

def _grid_index(values):
    """(sorted distinct values, index of each value) of bin centres written
    with %g: values within 1e-6 of the span are the same"""
    values = np.asarray(values, float)
    span = np.ptp(values) if values.size else 0.0
    tol = 1e-6 * (span if span > 0 else 1.0)
    uniq, inverse = np.unique(np.rint(values / tol), return_inverse=True)
    centres = np.bincount(inverse, weights=values) / np.bincount(inverse)
    return centres, inverse


def to_grid(xc, yc, values):
    """Bin centres and values of a bin/2d chunk field (flat, any order) on a
    regular grid: (x (nx,), y (ny,), grid (ny, nx)); NaN where no bin."""
    x, ix = _grid_index(xc)
    y, iy = _grid_index(yc)
    grid = np.full((len(y), len(x)), np.nan)
    grid[iy, ix] = np.asarray(values, float)
    return x, y, grid


def stream_function(xc, yc, vx, vy=None):
    """Stream function of a time-averaged velocity field on bin centres:
    (x, y, psi (ny, nx)), psi = integral of vx dy from the bottom of the grid
    (psi = 0 below the first row; vx = dpsi/dy, vy = -dpsi/dx), evaluated at
    the bin centres by the midpoint rule; empty bins (NaN) count as zero
    velocity and are NaN in psi.  With vy, psi is the mean of that and of
    -integral of vy dx from the left of the grid, which are equal for a
    divergence-free field: each then fixes the centre best along the
    direction across which it integrates."""
    x, y, u = to_grid(xc, yc, vx)
    dy = np.diff(y).mean() if len(y) > 1 else 1.0
    u0 = np.nan_to_num(u)
    psi = dy * (np.cumsum(u0, axis=0) - 0.5 * u0)
    if vy is not None:
        _, _, v = to_grid(xc, yc, vy)
        dx = np.diff(x).mean() if len(x) > 1 else 1.0
        v0 = np.nan_to_num(v)
        psi = 0.5 * (psi - dx * (np.cumsum(v0, axis=1) - 0.5 * v0))
    psi[~np.isfinite(u)] = np.nan
    return x, y, psi


def _quadratic_extremum(patch):
    """Offset (du, dw), in bins, of the extremum of a 3x3 patch (rows w = -1,
    0, 1; columns u = -1, 0, 1) from its centre: least-squares quadratic
    surface, or parabolas along each axis when that has no extremum nearby."""
    w, u = np.mgrid[-1:2, -1:2]
    u, w, z = u.ravel(), w.ravel(), patch.ravel()
    A = np.column_stack([np.ones(9), u, w, u * u, u * w, w * w])
    a = np.linalg.lstsq(A, z, rcond=None)[0]
    hess = np.array([[2 * a[3], a[4]], [a[4], 2 * a[5]]])
    if np.linalg.det(hess) > 0:
        du, dw = np.linalg.solve(hess, -a[1:3])
        if abs(du) <= 1.0 and abs(dw) <= 1.0:
            return du, dw

    def parabola(m, c, p):
        curv = m - 2 * c + p
        return 0.0 if curv == 0 else float(np.clip(0.5 * (m - p) / curv, -0.5, 0.5))

    return parabola(*patch[1]), parabola(*patch[:, 1])


def vortex_centre(xc, yc, vx, vy, L, x_right=None):
    """Centre of the cavity's vortex from a time-averaged velocity field on
    bin centres (flat arrays as fix ave/chunk bin/2d writes them, NaN or
    whatever count-weighted mean empty bins have): the interior extremum of
    the stream function with the largest |psi| (interior: its 8 neighbours
    are non-empty bins), refined by a quadratic fit over them.  vy may be
    None (psi from vx only).  Returns (x_centre, y_centre, ell / L), ell =
    x_right - x_centre the distance to the right wall (x_right = L by
    default: walls at 0 and L); paper 004 Fig. 3a."""
    x, y, psi = stream_function(xc, yc, vx, vy)
    if len(x) < 3 or len(y) < 3:
        raise ValueError("the grid needs at least 3 x 3 bins")
    finite = np.isfinite(psi)
    interior = np.zeros_like(finite)
    interior[1:-1, 1:-1] = True
    for dj in (-1, 0, 1):
        for di in (-1, 0, 1):
            interior[1:-1, 1:-1] &= finite[1 + dj:len(y) - 1 + dj, 1 + di:len(x) - 1 + di]
    if not interior.any():
        raise ValueError("no interior bin with 8 non-empty neighbours")
    score = np.where(interior, np.abs(np.nan_to_num(psi)), -np.inf)
    j, i = np.unravel_index(np.argmax(score), score.shape)
    du, dw = _quadratic_extremum(psi[j - 1:j + 2, i - 1:i + 2])
    xcen = x[i] + du * 0.5 * (x[i + 1] - x[i - 1])
    ycen = y[j] + dw * 0.5 * (y[j + 1] - y[j - 1])
    x_right = L if x_right is None else x_right
    return xcen, ycen, (x_right - xcen) / L


# ---------------------------------------------------------------------------
# Eq. 6: autocorrelation and the critical time

def autocorrelation(F, max_lag):
    """Normalised autocorrelation C(k), k = 0 .. max_lag, of a series: mean
    removed, biased estimator sum_n f_n f_{n+k} / sum_n f_n^2 (C(0) = 1),
    computed by FFT with zero padding.  NaN for a constant series."""
    f = np.asarray(F, float)
    f = f - f.mean()
    n = len(f)
    max_lag = min(int(max_lag), n - 1)
    size = 1 << int(math.ceil(math.log2(2 * n))) if n > 1 else 2
    spectrum = np.fft.rfft(f, size)
    acov = np.fft.irfft(spectrum * np.conj(spectrum), size)[:max_lag + 1]
    if acov[0] <= 0:
        return np.full(max_lag + 1, np.nan)
    return acov / acov[0]


def correlation_time(C, dt, threshold=THRESHOLD):
    """Eq. 6: the lowest lag at which C falls to threshold, linearly
    interpolated between the two samples around the first crossing, times
    dt; 0 if C(0) is already at or below it, NaN if C never reaches it."""
    C = np.asarray(C, float)
    below = np.nonzero(C <= threshold)[0]
    if len(below) == 0:
        return np.nan
    k = below[0]
    if k == 0:
        return 0.0
    return dt * (k - 1 + (C[k - 1] - threshold) / (C[k - 1] - C[k]))


def portion_correlation_times(series, dt, max_lag, threshold=THRESHOLD):
    """Delta t_c^i of each column of series (time, portion) and their mean
    over the portions that cross (Fig. 10): (array, mean)"""
    series = np.asarray(series, float)
    times = np.array([correlation_time(autocorrelation(series[:, i], max_lag), dt, threshold)
                      for i in range(series.shape[1])])
    mean = np.nanmean(times) if np.isfinite(times).any() else np.nan
    return times, mean


# ---------------------------------------------------------------------------
# Eq. 7: the truncated log-normal

def _z0(mu, sigma, f0):
    return (math.log(f0) - mu) / sigma


def trunc_lognormal_pdf(f, mu, sigma, f0):
    """Eq. 7: the density of f > 0 such that f + f0 is log-normal (ln(f + f0)
    normal with mean mu, standard deviation sigma) restricted to f + f0 > f0;
    S = P(X > f0) for X log-normal(mu, sigma), the survival function of the
    untruncated log-normal at f0.  Zero for f <= 0."""
    f = np.asarray(f, float)
    x = np.where(f > 0, f + f0, 1.0)
    log_s = special.log_ndtr(-_z0(mu, sigma, f0))
    z = (np.log(x) - mu) / sigma
    dens = np.exp(-0.5 * z * z - log_s) / (sigma * math.sqrt(2 * math.pi) * x)
    return np.where(f > 0, dens, 0.0)


def trunc_lognormal_cdf(f, mu, sigma, f0):
    """P(f' <= f) of Eq. 7 (0 for f <= 0)"""
    f = np.asarray(f, float)
    x = np.where(f > 0, f + f0, f0)
    z0 = _z0(mu, sigma, f0)
    z = (np.log(x) - mu) / sigma
    return 1.0 - special.ndtr(-z) / special.ndtr(-z0)


def sample_trunc_lognormal(n, mu, sigma, f0, rng):
    """n samples of Eq. 7 by inverse-CDF sampling: the survival function
    S(z)/S(z0) of f is uniform in (0, 1]"""
    v = 1.0 - rng.random(n)                        # (0, 1]
    z = -special.ndtri(v * special.ndtr(-_z0(mu, sigma, f0)))
    z = np.maximum(z, _z0(mu, sigma, f0))
    return np.exp(mu + sigma * z) - f0


def trunc_lognormal_loglik(samples, mu, sigma, f0):
    """log-likelihood of Eq. 7 for positive samples"""
    x = np.asarray(samples, float) + f0
    z = (np.log(x) - mu) / sigma
    return (-0.5 * np.sum(z * z) - np.sum(np.log(x))
            - len(x) * (math.log(sigma) + 0.5 * math.log(2 * math.pi)
                        + special.log_ndtr(-_z0(mu, sigma, f0))))


def fit_trunc_lognormal(samples, starts=(0.1, 1.0)):
    """Maximum-likelihood (mu, sigma, f0) of Eq. 7 for positive samples
    (non-positive ones are dropped), by Nelder-Mead over (mu, ln sigma,
    ln f0) as in paper 004; the best of the starts f0 = s * mean(samples),
    each with mu and sigma those of ln(samples + f0)."""
    f = np.asarray(samples, float)
    f = f[np.isfinite(f) & (f > 0)]
    if len(f) < 10:
        raise ValueError(f"{len(f)} positive samples are too few for a fit")
    scale = f.mean()

    def nll(p):
        value = -trunc_lognormal_loglik(f, p[0], math.exp(p[1]), math.exp(p[2]))
        return value if np.isfinite(value) else np.inf

    best = None
    for s in starts:
        f0 = s * scale
        logs = np.log(f + f0)
        p0 = np.array([logs.mean(), math.log(max(logs.std(), 1e-3)), math.log(f0)])
        res = optimize.minimize(nll, p0, method="Nelder-Mead",
                                options={"xatol": 1e-7, "fatol": 1e-7, "maxiter": 20000,
                                         "maxfev": 20000})
        if best is None or res.fun < best.fun:
            best = res
    return best.x[0], math.exp(best.x[1]), math.exp(best.x[2])


# ---------------------------------------------------------------------------
# PDFs and the wall portions

def normalised_pdf(values, bins=50):
    """Histogram density of values / mean(values): (bin centres, density);
    bins as numpy.histogram takes them (a count or the edges).  Empty arrays
    when there is no positive mean to scale by."""
    v = np.asarray(values, float)
    v = v[np.isfinite(v)]
    if len(v) == 0 or not v.mean() > 0:
        return np.array([]), np.array([])       # e.g. a portion of the wall no grain touched
    density, edges = np.histogram(v / v.mean(), bins=bins, density=True)
    return 0.5 * (edges[1:] + edges[:-1]), density


def mean_portion_pdf(series, bins=50, portions=(3, 9)):
    """Fig. 14b: the mean over portions i = portions[0] .. portions[1]
    (1-based, bottom first, inclusive) of the densities of F_i / mean(F_i);
    series is (time, portion).  A count of bins spans 0 .. the largest
    scaled force of those portions.  Returns (bin centres, mean density)."""
    series = np.asarray(series, float)
    cols = [i for i in range(portions[0] - 1, portions[1]) if np.nanmean(series[:, i]) > 0]
    if not cols:
        return np.array([]), np.array([])
    scaled = [series[:, i] / np.nanmean(series[:, i]) for i in cols]
    if np.ndim(bins) == 0:
        top = max(np.nanmax(s) for s in scaled)
        bins = np.linspace(0.0, top, int(bins) + 1)
    dens = [np.histogram(s[np.isfinite(s)], bins=bins, density=True)[0] for s in scaled]
    edges = np.asarray(bins, float)
    return 0.5 * (edges[1:] + edges[:-1]), np.mean(dens, axis=0)


def portion_forces(y, force, y_bottom, y_top, n=10):
    """Total force on each of n equal portions of the wall between y_bottom
    and y_top (bottom portion first) from the heights y of the contacts of
    one snapshot and their forces; contacts below y_bottom count in the
    first portion, above y_top in the last, so the portions sum to the
    total."""
    y = np.asarray(y, float)
    force = np.asarray(force, float)
    index = np.floor(n * (y - y_bottom) / (y_top - y_bottom)).astype(int)
    return np.bincount(np.clip(index, 0, n - 1), weights=force, minlength=n)


def portion_force_series(snapshots, y_bottom, y_top, n=10, ycol="v_ycontact", fcol="v_fwall"):
    """portion_forces of each snapshot of lammps_output.read_dump:
    (timesteps, (nsnap, n)); y_bottom and y_top are numbers or one per
    snapshot (a moving lid)."""
    nsnap = len(snapshots)
    counts = np.array([len(s[ycol]) for s in snapshots], dtype=np.int64)
    steps = np.array([s.timestep for s in snapshots], dtype=np.int64)
    if counts.sum() == 0:
        return steps, np.zeros((nsnap, n))
    y = np.concatenate([s[ycol] for s in snapshots]).astype(float)
    force = np.concatenate([s[fcol] for s in snapshots]).astype(float)
    ybot = np.repeat(np.broadcast_to(np.asarray(y_bottom, float), (nsnap,)), counts)
    ytop = np.repeat(np.broadcast_to(np.asarray(y_top, float), (nsnap,)), counts)
    index = np.clip(np.floor(n * (y - ybot) / (ytop - ybot)).astype(int), 0, n - 1)
    snap = np.repeat(np.arange(nsnap), counts)
    forces = np.bincount(snap * n + index, weights=force, minlength=nsnap * n)
    return steps, forces.reshape(nsnap, n)


# ---------------------------------------------------------------------------
# zeros: records in which no grain touches the wall (or a portion of it)

def zero_fraction(values, tol=0.0):
    """The fraction of the finite records of values (any shape) that are
    zero (|value| <= tol): the mass at F = 0 of a PDF"""
    v = np.asarray(values, float)
    v = v[np.isfinite(v)]
    return float(np.mean(np.abs(v) <= tol)) if v.size else np.nan


EQ7_GAUSSIAN_F0 = 100.0   # f0 above 100 mean forces: the fit has run to Eq. 7's Gaussian limit


def eq7_location_spread(mu, sigma, f0):
    """Eq. 7 before its truncation, f = X - f0 with X log-normal(mu, sigma):
    (location E[f], spread sd(f), gaussian_limit).  Where the data are
    Gaussian the likelihood climbs on towards f0 -> infinity, sigma -> 0
    (the log-normal's Gaussian limit) and mu, sigma, f0 stop being
    determined one by one; the location and spread stay determined.
    gaussian_limit: f0 > EQ7_GAUSSIAN_F0 (in units of the mean force)."""
    if not (np.isfinite(mu) and np.isfinite(sigma) and np.isfinite(f0)):
        return np.nan, np.nan, False
    mean_x = math.exp(mu + 0.5 * sigma * sigma)
    return mean_x - f0, mean_x * math.sqrt(math.expm1(sigma * sigma)), bool(f0 > EQ7_GAUSSIAN_F0)


def fit_eq7_with_zeros(values, tol=0.0):
    """Eq. 7 fitted to the records as the histograms show them: the values
    are scaled by the mean of all the records (zeros included); the zero
    records are a mass p0 at F = 0 (their maximum-likelihood weight in the
    mixture p0 delta(F) + (1 - p0) Eq. 7 is their fraction), Eq. 7 is fitted
    by maximum likelihood to the positive ones.  Returns {"p0", "mu",
    "sigma", "f0", "loc", "spread", "gaussian_limit", "n", "n_positive",
    "mean"} (mu, sigma, f0 of the scaled values, NaN when fewer than 10 are
    positive; loc, spread, gaussian_limit from eq7_location_spread)."""
    v = np.asarray(values, float).ravel()
    v = v[np.isfinite(v)]
    mean = float(v.mean()) if v.size else np.nan
    out = {"p0": zero_fraction(v, tol), "n": int(v.size), "mean": mean, "mu": np.nan, "sigma": np.nan,
           "f0": np.nan}
    positive = v[v > tol]
    out["n_positive"] = int(positive.size)
    if positive.size >= 10 and mean > 0:
        out["mu"], out["sigma"], out["f0"] = (float(x) for x in fit_trunc_lognormal(positive / mean))
    loc, spread, limit = eq7_location_spread(out["mu"], out["sigma"], out["f0"])
    out.update(loc=float(loc), spread=float(spread), gaussian_limit=limit)
    return out


def pdf_with_zeros(values, edges, tol=0.0):
    """The histogram of values / mean(all values) with the zero records
    taken out: (bin centres, density of the positive records normalised to
    1 - p0, p0), so that (1 - p0) Eq. 7 of fit_eq7_with_zeros is drawn
    against it and p0 is the mass at 0"""
    v = np.asarray(values, float).ravel()
    v = v[np.isfinite(v)]
    edges = np.asarray(edges, float)
    centres = 0.5 * (edges[1:] + edges[:-1])
    if v.size == 0 or not v.mean() > 0:
        return centres, np.full(len(centres), np.nan), np.nan
    p0 = zero_fraction(v, tol)
    scaled = v[v > tol] / v.mean()
    counts, _ = np.histogram(scaled, bins=edges)
    density = counts / (v.size * np.diff(edges))
    return centres, density, p0


# ---------------------------------------------------------------------------
# stationarity: the first half of a record against the second

def stationarity(series, blocks=10):
    """First half against second half of a record (time along axis 0; a 2D
    array: each column): the means, their difference over its standard
    error (each half's error from `blocks` block means, which holds for a
    correlated series) and the coefficients of variation of each half.
    Returns {"mean1", "mean2", "z", "cv1", "cv2", "rel"} (arrays for a 2D
    input; rel = (mean2 - mean1) / the mean of both)"""
    x = np.asarray(series, float)
    one = x.ndim == 1
    if one:
        x = x[:, None]
    half = len(x) // 2
    a, b = x[:half], x[half:2 * half]
    n = half // blocks
    if n < 1:
        raise ValueError(f"{len(x)} records are too few for {blocks} blocks per half")

    def block_sem(part):
        means = part[:n * blocks].reshape(blocks, n, -1).mean(axis=1)
        return means.std(axis=0, ddof=1) / math.sqrt(blocks)

    m1, m2 = a.mean(axis=0), b.mean(axis=0)
    s = np.hypot(block_sem(a), block_sem(b))
    with np.errstate(invalid="ignore", divide="ignore"):
        z = np.where(s > 0, (m2 - m1) / np.where(s > 0, s, 1.0), np.where(m2 == m1, 0.0, np.inf))
        cv1, cv2 = a.std(axis=0) / m1, b.std(axis=0) / m2
        rel = (m2 - m1) / (0.5 * (m1 + m2))
    out = {"mean1": m1, "mean2": m2, "z": z, "cv1": cv1, "cv2": cv2, "rel": rel}
    return {k: float(v[0]) for k, v in out.items()} if one else out


# ---------------------------------------------------------------------------
# Eq. 5: the mean force and the vortex

PAPER_EQ5 = (0.88, 0.5)          # paper 004 Fig. 4: c1, c2 of Eq. 5


def fit_eq5(ell_over_L, Fnorm):
    """Eq. 5, F/(PLd) = c1 - c2 ell/L, by least squares: ((c1, c2),
    (s_c1, s_c2), R^2); the points with a missing value are left out"""
    x = np.asarray(ell_over_L, float)
    y = np.asarray(Fnorm, float)
    keep = np.isfinite(x) & np.isfinite(y)
    x, y = x[keep], y[keep]
    if len(x) < 3:
        raise ValueError(f"Eq. 5 needs 3 points or more, got {len(x)}")
    A = np.column_stack([np.ones_like(x), -x])
    p, res, _, _ = np.linalg.lstsq(A, y, rcond=None)
    r = y - A @ p
    dof = max(1, len(x) - 2)
    cov = np.linalg.inv(A.T @ A) * (r @ r) / dof
    r2 = 1.0 - (r @ r) / np.sum((y - y.mean()) ** 2)
    return (float(p[0]), float(p[1])), (float(np.sqrt(cov[0, 0])), float(np.sqrt(cov[1, 1]))), float(r2)


# ---------------------------------------------------------------------------
# meso scale: portions of a given size

def central_portions(n, low=0.2, high=0.9):
    """the 0-based indices of the portions (n equal, bottom first) that lie
    between low and high of the height: portions 3..9 of 10 (paper 004
    Fig. 14b) for the defaults, the middle one of 3"""
    eps = 1e-9
    return [i for i in range(n) if i / n >= low - eps and (i + 1) / n <= high + eps]


# ---------------------------------------------------------------------------
# the local rheology (paper 004 Sec. III B, App. C: Eqs. 16-20)

PAPER_MU_I = (0.12, 0.40, 0.13)  # mu_1, mu_2, I_0 of Eq. 20


def mu_I_model(I, mu1, mu2, I0):
    """Eq. 20: mu_th(I) = mu1 + (mu2 - mu1) / (1 + I0 / I)"""
    I = np.asarray(I, float)
    return mu1 + (mu2 - mu1) / (1.0 + I0 / I)


def strain_rate_2d(x, y, vx, vy):
    """The strain-rate tensor D = (grad v + grad v^T) / 2 of a velocity field
    on a regular grid (x (nx,), y (ny,), vx, vy (ny, nx)) by centred
    differences: (Dxx, Dyy, Dxy), each (ny, nx); NaN next to a NaN"""
    dvx_dy, dvx_dx = np.gradient(np.asarray(vx, float), y, x)
    dvy_dy, dvy_dx = np.gradient(np.asarray(vy, float), y, x)
    return dvx_dx, dvy_dy, 0.5 * (dvx_dy + dvy_dx)


def local_rheology(sxx, syy, sxy, Dxx, Dyy, Dxy, d, rho_p):
    """Paper 004's Eqs. 16-19 applied to the planar fields, as 3x3 tensors
    with no z component (the contact stress of spheres whose centres lie in
    a plane has sigma_zz = 0; D_zz = 0): sigma = p I_3 + sigma' with the
    stress counted positive in compression, p = Tr(sigma) / 3; ||A|| =
    sqrt(Tr(A A^T) / 2); I = d sqrt(rho_p) ||D'|| / sqrt(p) (Eq. 18);
    mu_loc = -Tr(sigma' D') / 3 / (p ||D'||) (Eq. 19, its sign such that a
    stress that resists the deformation, i.e. dissipates, gives mu_loc > 0:
    the paper's Love-Weber sum f_c (x) l_c is negative in compression).  For
    a simple shear vx = gamma y with in-plane pressure p2 = (sxx + syy) / 2
    and the resisting shear stress sxy = -tau (compression positive) this
    is mu_loc = tau / p2 and I = sqrt(3/8) d gamma sqrt(rho_p / p2).
    sxx, syy, sxy: stress with compression positive (Pa); returns (I,
    mu_loc), NaN where p <= 0 or D' = 0."""
    sxx, syy, sxy = (np.asarray(a, float) for a in (sxx, syy, sxy))
    Dxx, Dyy, Dxy = (np.asarray(a, float) for a in (Dxx, Dyy, Dxy))
    p = (sxx + syy) / 3.0
    trD = (Dxx + Dyy) / 3.0
    # deviators (zz components -p and -trD)
    s_xx, s_yy, s_zz = sxx - p, syy - p, -p
    d_xx, d_yy, d_zz = Dxx - trD, Dyy - trD, -trD
    normD = np.sqrt((d_xx ** 2 + d_yy ** 2 + d_zz ** 2 + 2 * Dxy ** 2) / 2.0)
    contraction = s_xx * d_xx + s_yy * d_yy + s_zz * d_zz + 2 * sxy * Dxy
    with np.errstate(invalid="ignore", divide="ignore"):
        good = (p > 0) & (normD > 0)
        I = np.where(good, d * np.sqrt(rho_p) * normD / np.sqrt(np.where(p > 0, p, 1.0)), np.nan)
        mu = np.where(good, -contraction / 3.0 / (np.where(good, p * normD, 1.0)), np.nan)
    return I, mu


def fit_mu_I(I, mu):
    """Eq. 20 fitted by least squares to points (I, mu_loc) (ln I0 the
    fitted parameter): ((mu1, mu2, I0), (errors))"""
    I = np.asarray(I, float)
    mu = np.asarray(mu, float)
    keep = np.isfinite(I) & np.isfinite(mu) & (I > 0)
    I, mu = I[keep], mu[keep]
    if len(I) < 4:
        raise ValueError(f"Eq. 20 has 3 parameters; {len(I)} points are too few")
    order = np.argsort(I)
    q = max(1, len(I) // 5)

    def model(x, a, b, c):
        return a + (b - a) / (1.0 + np.exp(c) / x)

    p0 = (mu[order[:q]].mean(), mu[order[-q:]].mean(), math.log(np.median(I)))
    p, cov = optimize.curve_fit(model, I, mu, p0=p0, maxfev=20000)
    err = np.sqrt(np.diag(cov))
    return (p[0], p[1], math.exp(p[2])), (err[0], err[1], math.exp(p[2]) * err[2])


def stress_and_velocity_fields(columns, bin_area, thickness):
    """The time-averaged fields of in.cavity's TAG.stress (fix ave/chunk
    norm none on bins of d: per bin the sums over its grains of
    c_satom[1], [2], [4] and of vx, vy, and Ncount): (x, y, sxx, syy, sxy,
    vx, vy) on the grid (to_grid), the stress with compression positive in
    Pa (the sums of -W over the bin's area x thickness), the velocity the
    mean of the bin's grains; NaN in empty bins"""
    count = np.asarray(columns["Ncount"], float)
    with np.errstate(invalid="ignore", divide="ignore"):
        vx = np.where(count > 0, columns["vx"] / np.where(count > 0, count, 1.0), np.nan)
        vy = np.where(count > 0, columns["vy"] / np.where(count > 0, count, 1.0), np.nan)
    volume = bin_area * thickness
    s = [np.where(count > 0, -np.asarray(columns[name], float) / volume, np.nan)
         for name in ("c_satom[1]", "c_satom[2]", "c_satom[4]")]
    x, y, sxx = to_grid(columns["Coord1"], columns["Coord2"], s[0])
    grids = [to_grid(columns["Coord1"], columns["Coord2"], v)[2] for v in (s[1], s[2], vx, vy)]
    return (x, y, sxx, *grids)


def mean_blocks(blocks, first_step=None):
    """The plain mean over the blocks of lammps_output.read_ave_chunk (those
    with timestep > first_step if given) of every column: for norm none
    (sums per chunk), where time_average_chunks's count weighting does not
    apply"""
    if first_step is not None:
        blocks = [(step, cols) for step, cols in blocks if step > first_step]
    if not blocks:
        raise ValueError("no block to average")
    return {name: np.mean([cols[name] for _, cols in blocks], axis=0) for name in blocks[0][1]}


# ---------------------------------------------------------------------------
# where the drive falls in the vibration network's spectrum

def read_modes_histogram(path):
    """The last histogram of in.cavity's TAG.modes.hist (fix ave/time mode
    vector of compute vibration/modes's bins): (bin centres (Hz), density)"""
    rows, block = [], []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        words = line.split()
        if len(words) == 2:
            block = []
            rows.append(block)
        else:
            block.append((float(words[1]), float(words[2])))
    if not rows or not rows[-1]:
        raise ValueError(f"no histogram in {path}")
    data = np.array(rows[-1])
    return data[:, 0], data[:, 1]


def spectrum_position(centres, density, freq, top=0.999):
    """Where freq falls in a density of states on equal bins (centres,
    density normalised over the bins): (the fraction of the modes below
    freq, the frequency below which the fraction `top` of them lie), both
    linearly interpolated in the cumulative distribution"""
    centres = np.asarray(centres, float)
    density = np.clip(np.asarray(density, float), 0.0, None)
    width = np.diff(centres).mean() if len(centres) > 1 else 1.0
    edges = np.concatenate([[centres[0] - 0.5 * width], centres + 0.5 * width])
    cumulative = np.concatenate([[0.0], np.cumsum(density * width)])
    cumulative /= cumulative[-1]
    below = float(np.interp(freq, edges, cumulative))
    band = float(np.interp(top, cumulative, edges))
    return below, band


def principal_direction(axx, ayy, axy):
    """The angle (radians, from x, in (-pi/2, pi/2]) of the direction of
    the largest eigenvalue of a symmetric 2D tensor field: 0.5 atan2(2 axy,
    axx - ayy) (the major compression of a stress counted positive in
    compression, the major extension of a strain rate)"""
    return 0.5 * np.arctan2(2 * np.asarray(axy, float), np.asarray(axx, float) - np.asarray(ayy, float))


def smooth_field(grid, sigma_bins=0.5):
    """A field on a regular grid smoothed by a Gaussian kernel of standard
    deviation sigma_bins bins, NaN-aware (the kernel's weights normalised
    over the non-empty bins, as paper 004's Eq. 13 over the grains; empty
    bins stay NaN); paper 004 App. A: d/2 on a mesh of d"""
    from scipy import ndimage
    grid = np.asarray(grid, float)
    mask = np.isfinite(grid)
    num = ndimage.gaussian_filter(np.where(mask, grid, 0.0), sigma_bins, mode="constant")
    den = ndimage.gaussian_filter(mask.astype(float), sigma_bins, mode="constant")
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(mask & (den > 0), num / np.where(den > 0, den, 1.0), np.nan)
