"""Figures of paper 004 (granular lid-driven cavity) from the results of
cavity runs; matplotlib (Agg), PNG.  Each function takes plain arrays or
dicts (not file paths) and the output path, so an example's collect script
or a user's own runs can call them:

  fig2_streamlines        time-averaged streamlines and the vortex centre
  fig3_vortex_and_force   ell/L and F/(PLd) against I_M, Eq. 4 fit and the
                          paper's curve (r1 0.53, r2 0.86, I_M^0 0.02)
  fig9_autocorrelation    C^i(Delta t) of the wall portions, threshold 0.15
  fig10_correlation_times Delta t_c^i and their mean against I_M
  fig12_particle_pdfs     PDFs of f / mean(f) with truncated log-normal fits
                          and their parameters against I_M
  fig13_wall_pdfs         the same for the total force F / mean(F)
  fig14_meso_pdfs         PDFs of F_i / mean(F_i) per portion and the mean
                          over portions 3..9 for several I_M
  fig_volume_fraction     Phi* against I_M
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import cavity  # noqa: E402

DPI = 110


def _save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def _im_colours(values):
    """one viridis colour per I_M, ordered by log I_M"""
    logs = np.log10(np.asarray(values, float))
    span = np.ptp(logs) if len(logs) > 1 else 1.0
    return [plt.cm.viridis(0.9 * (v - logs.min()) / (span or 1.0)) for v in logs]


def fig3_vortex_and_force(IM, ell_over_L, Fnorm, path, fit=None, title=""):
    """Fig. 3: (a) ell/L and (b) F/(PLd) against I_M; fit = (r1, r2, I0) of
    Eq. 4 (fitted here when None and there are at least 4 points)"""
    IM = np.asarray(IM, float)
    Fnorm = np.asarray(Fnorm, float)
    fig, (left, right) = plt.subplots(1, 2, figsize=(8.0, 3.6))
    left.semilogx(IM, ell_over_L, "o")
    left.axhline(0.5, color="0.6", ls=":", lw=0.8)
    left.set_xlabel(r"$I_M$")
    left.set_ylabel(r"$\ell/L$")
    left.set_title("(a) vortex centre")
    right.semilogx(IM, Fnorm, "o", label="runs")
    grid = np.logspace(np.log10(min(np.nanmin(IM), 1e-3)), np.log10(max(np.nanmax(IM), 1.0)), 200)
    if fit is None and np.isfinite(Fnorm).sum() >= 4:
        try:
            fit = cavity.fit_mean_force(IM, Fnorm)[0]
        except (RuntimeError, ValueError):
            fit = None
    if fit is not None:
        right.plot(grid, cavity.mean_force_model(grid, *fit), "C3-", lw=1.0,
                   label=f"Eq. 4: {fit[0]:.2f}, {fit[1]:.2f}, {fit[2]:.2g}")
    right.plot(grid, cavity.mean_force_model(grid, *cavity.PAPER_EQ4), "k--", lw=0.8,
               label="paper: 0.53, 0.86, 0.02")
    right.set_xlabel(r"$I_M$")
    right.set_ylabel(r"$\bar F/(PLd)$")
    right.set_title("(b) mean force")
    right.legend(frameon=False, fontsize=8)
    if title:
        fig.suptitle(title)
    _save(fig, path)


def fig9_autocorrelation(dt, C_portions, path, title="", threshold=cavity.THRESHOLD):
    """Fig. 9: C^i against Delta t for the portions i = 1 (bottom) .. n (top);
    C_portions is (portion, lag), lag k at k dt"""
    C_portions = np.atleast_2d(np.asarray(C_portions, float))
    n = len(C_portions)
    fig, ax = plt.subplots(figsize=(5.0, 4.0))
    lags = np.arange(C_portions.shape[1]) * dt
    for i, C in enumerate(C_portions):
        ax.plot(lags, C, color=plt.cm.plasma(0.9 * i / max(n - 1, 1)), lw=0.8, label=f"i = {i + 1}")
    ax.axhline(threshold, color="k", ls="--", lw=0.8)
    ax.axhline(0.0, color="0.6", lw=0.5)
    ax.set_xlabel(r"$\Delta t$")
    ax.set_ylabel(r"$C^i(F(t), F(t+\Delta t))$")
    ax.set_title(title)
    ax.legend(frameon=False, fontsize=7, ncol=2)
    _save(fig, path)


def fig10_correlation_times(IM, dtc, path, title=""):
    """Fig. 10: Delta t_c^i (crosses) and their mean over the portions
    (circles) against I_M; dtc is (run, portion), NaN where C never fell
    to the threshold"""
    IM = np.asarray(IM, float)
    dtc = np.atleast_2d(np.asarray(dtc, float))
    fig, ax = plt.subplots(figsize=(5.0, 4.0))
    for im, row in zip(IM, dtc):
        ax.plot(np.full(len(row), im), row, "x", color="0.6")
    with np.errstate(all="ignore"):
        mean = np.array([np.nanmean(row) if np.isfinite(row).any() else np.nan for row in dtc])
    ax.plot(IM, mean, "ko", label=r"$\langle \Delta t_c \rangle$")
    ax.set_xscale("log")
    ax.set_xlabel(r"$I_M$")
    ax.set_ylabel(r"$\Delta t_c^i$")
    ax.set_title(title)
    ax.legend(frameon=False)
    _save(fig, path)


def _pdfs_with_fits(samples, path, fits, bins, xlabel, title):
    """PDFs of values / mean for each I_M with the truncated log-normal of
    Eq. 7 (dashed) and the parameters against I_M"""
    ims = sorted(samples)
    fits = dict(fits or {})
    for im in ims:
        if im not in fits:
            v = np.asarray(samples[im], float)
            fits[im] = cavity.fit_trunc_lognormal(v / v.mean())
    fig, (left, right) = plt.subplots(1, 2, figsize=(8.0, 3.6))
    for colour, im in zip(_im_colours(ims), ims):
        x, dens = cavity.normalised_pdf(samples[im], bins)
        left.plot(x, dens, color=colour, lw=1.0, label=f"$I_M$ = {im:.2g}")
        grid = np.linspace(1e-6, x.max(), 300)
        left.plot(grid, cavity.trunc_lognormal_pdf(grid, *fits[im]), "--", color=colour, lw=0.8)
    left.set_xlim(0.0, 6.0)
    left.set_xlabel(xlabel)
    left.set_ylabel("PDF")
    left.set_title("(a)")
    left.legend(frameon=False, fontsize=7)
    params = np.array([fits[im] for im in ims])
    for k, (name, marker) in enumerate(((r"$\mu$", "o"), (r"$\sigma$", "s"), (r"$f_0$", "^"))):
        right.semilogx(ims, params[:, k], marker + "-", label=name)
    right.set_xlabel(r"$I_M$")
    right.set_ylabel("Eq. 7 parameters")
    right.set_title("(b)")
    right.legend(frameon=False)
    if title:
        fig.suptitle(title)
    _save(fig, path)


def fig12_particle_pdfs(samples, path, fits=None, bins=60, title="grain-wall contact forces"):
    """Fig. 12: samples is I_M -> contact forces f (all records merged);
    fits is I_M -> (mu, sigma, f0) of f / mean(f), fitted here when absent"""
    _pdfs_with_fits(samples, path, fits, bins, r"$f/\bar f$", title)


def fig13_wall_pdfs(samples, path, fits=None, bins=60, title="total force on the wall"):
    """Fig. 13: samples is I_M -> series of the total force F on the wall"""
    _pdfs_with_fits(samples, path, fits, bins, r"$F/\bar F$", title)


def fig14_meso_pdfs(series, series_by_IM, path, bins=50, portions=(3, 9), title=""):
    """Fig. 14: (a) PDFs of F_i / mean(F_i) of the portions of one run
    (series is (time, portion), bottom first; blue: i = 1, 2, orange: the
    central portions, red: the top one); (b) the mean over portions
    portions[0] .. portions[1] for each I_M of series_by_IM"""
    series = np.asarray(series, float)
    n = series.shape[1]
    fig, (left, right) = plt.subplots(1, 2, figsize=(8.0, 3.6))
    for i in range(n):
        colour = "C0" if i + 1 < portions[0] else ("C3" if i + 1 > portions[1] else "C1")
        x, dens = cavity.normalised_pdf(series[:, i], bins)
        left.plot(x, dens, color=colour, lw=0.8, label=f"i = {i + 1}" if i + 1 in (1, portions[0], n) else None)
    left.set_xlabel(r"$F_i/\bar F_i$")
    left.set_ylabel("PDF")
    left.set_title("(a) portions")
    left.legend(frameon=False, fontsize=7)
    ims = sorted(series_by_IM)
    for colour, im in zip(_im_colours(ims), ims):
        x, dens = cavity.mean_portion_pdf(series_by_IM[im], bins, portions)
        right.plot(x, dens, color=colour, lw=1.0, label=f"$I_M$ = {im:.2g}")
    right.set_xlabel(r"$F_i/\bar F_i$")
    right.set_ylabel(f"mean PDF, i = {portions[0]}..{portions[1]}")
    right.set_title("(b)")
    right.legend(frameon=False, fontsize=7)
    if title:
        fig.suptitle(title)
    _save(fig, path)


def fig_volume_fraction(IM, phi, path, title=""):
    """Solid fraction Phi* (3D-equivalent, 2/3 of the 2D one) against I_M
    (paper 004 §VI discusses its slight variation)"""
    fig, ax = plt.subplots(figsize=(5.0, 4.0))
    ax.semilogx(np.asarray(IM, float), np.asarray(phi, float), "o-")
    ax.set_xlabel(r"$I_M$")
    ax.set_ylabel(r"$\Phi_*$ (3D equivalent)")
    ax.set_title(title)
    _save(fig, path)


def fig2_streamlines(xc, yc, vx, vy, L, path, centre=None, title=""):
    """Fig. 2: streamlines of a time-averaged velocity field on bin centres
    (flat arrays of fix ave/chunk bin/2d, NaN where empty), the side walls at
    0 and L, the vortex centre (x, y) marked when given"""
    x, y, u = cavity.to_grid(xc, yc, vx)
    _, _, v = cavity.to_grid(xc, yc, vy)
    rows = np.isfinite(u).any(axis=1)
    x_in = (x > 0) & (x < L)
    x, y, u, v = x[x_in], y[rows], u[rows][:, x_in], v[rows][:, x_in]
    speed = np.hypot(u, v)
    fig, ax = plt.subplots(figsize=(8.0, 8.0 * np.ptp(y) / max(L, 1e-30) + 1.5))
    ax.streamplot(x, y, np.nan_to_num(u), np.nan_to_num(v), color=np.nan_to_num(speed), cmap="viridis",
                  density=1.2, linewidth=0.7)
    if centre is not None:
        ax.plot(centre[0], centre[1], "r+", ms=12, mew=2)
        ax.axvline(centre[0], color="r", ls=":", lw=0.8)
    ax.set_xlim(0.0, L)
    half = 0.5 * (np.diff(y).mean() if len(y) > 1 else 1.0)
    ax.set_ylim(y.min() - half, y.max() + half)
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_title(title)
    _save(fig, path)
