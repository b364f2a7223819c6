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
                          over the central portions (3..9 of 10) for several
                          I_M, zero records apart (their fraction in the legend)
  fig_volume_fraction     Phi* against I_M
  fig4_force_vortex       F/(PLd) against ell/L with the Eq. 5 fit
  fig8_autocorrelation    C(F(t), F(t + Delta t)) of the whole wall for
                          several I_M, the inset against (U/d) Delta t
  fig11_particle_pairs    particle-scale PDFs of several (N_U, N_P) at one I_M
  fig20_loglinear         the PDFs of Figs. 12 and 13 on a log-linear scale
  fig_memory              <Delta t_c> against I_M in d/U and in seconds,
                          each run by its N_U, the mean and standard error
                          per I_M
  fig_us_effects          the drive's effect on F/(PLd), <Delta t_c>, CV
                          against the fraction of the modes below the drive
  fig5_orientations       the principal directions of the strain rate and
                          of the stress over the cavity
  fig6_mu_map             (mu_loc - mu_th) / mu_th over the cavity
  fig19_mu_I              mu_loc against I in the region of Fig. 19, Eq. 20

The PDFs of forces (Figs. 11-14, 20) leave the zero records out of the
density and give their fraction p0: the histogram integrates to 1 - p0 and
is drawn with (1 - p0) Eq. 7, fitted to the positive records scaled by the
mean of all of them (cavity.fit_eq7_with_zeros, cavity.pdf_with_zeros).
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import cavity  # noqa: E402

DPI = 250   # the narrowest figure (5 in) 1 250 px wide, as the avalanche's


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
    """PDFs of values / mean for each I_M (zero records apart: their
    fraction p0 in the legend, the density of the others integrates to
    1 - p0) with (1 - p0) Eq. 7 (dashed) and Eq. 7's parameters against I_M
    (open markers: a fit at Eq. 7's Gaussian limit, cavity.eq7_location_spread);
    fits: I_M -> cavity.fit_eq7_with_zeros's dict or (mu, sigma, f0)"""
    ims = sorted(samples)
    fits = dict(fits or {})
    for im in ims:
        if im not in fits:
            fits[im] = cavity.fit_eq7_with_zeros(samples[im])
        elif not isinstance(fits[im], dict):
            mu, sigma, f0 = fits[im]
            fits[im] = {"mu": mu, "sigma": sigma, "f0": f0, "p0": cavity.zero_fraction(samples[im])}
    edges = np.linspace(0.0, 6.0, int(bins) + 1) if np.ndim(bins) == 0 else np.asarray(bins, float)
    fig, (left, right) = plt.subplots(1, 2, figsize=(8.0, 3.6))
    for colour, im in zip(_im_colours(ims), ims):
        x, dens, p0 = cavity.pdf_with_zeros(samples[im], edges)
        left.plot(x, dens, color=colour, lw=1.0, label=f"$I_M$ = {im:.2g}, $p_0$ = {p0:.2f}")
        fit = fits[im]
        if np.isfinite(fit["mu"]):
            grid = np.linspace(1e-6, edges[-1], 300)
            left.plot(grid, (1 - p0) * cavity.trunc_lognormal_pdf(grid, fit["mu"], fit["sigma"], fit["f0"]), "--",
                      color=colour, lw=0.8)
    left.set_xlim(0.0, edges[-1])
    left.set_xlabel(xlabel)
    left.set_ylabel("PDF (zeros apart)")
    left.set_title("(a)")
    left.legend(frameon=False, fontsize=6)
    params = np.array([[fits[im]["mu"], fits[im]["sigma"], fits[im]["f0"]] for im in ims])
    limit = np.array([cavity.eq7_location_spread(*row)[2] for row in params], bool)
    for k, (name, marker) in enumerate(((r"$\mu$", "o"), (r"$\sigma$", "s"), (r"$f_0$", "^"))):
        line, = right.plot(ims, params[:, k], marker + "-", label=name)
        if limit.any():      # open markers: the fit at Eq. 7's Gaussian limit
            right.plot(np.asarray(ims)[limit], params[limit, k], marker, mfc="white", color=line.get_color())
    right.set_xscale("log")
    right.set_yscale("symlog", linthresh=0.1)      # f0 runs to 1e5 at the Gaussian limit, mu may be < 0
    lowest = np.nanmin(params) if np.isfinite(params).any() else 0.0
    right.set_ylim(bottom=min(0.0, 3.0 * lowest))
    right.set_xlabel(r"$I_M$" + (f"  (open: Gaussian limit, $f_0$ > {cavity.EQ7_GAUSSIAN_F0:g})" if limit.any() else ""))
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


def fig14_meso_pdfs(series, series_by_IM, path, bins=40, portions=(3, 9), title="", xmax=4.0):
    """Fig. 14: (a) PDFs of F_i / mean(F_i) of the portions of one run
    (series is (time, portion), bottom first; blue: below portions[0],
    orange: the central portions, red: above portions[1]); (b) the mean over
    the central portions for each I_M of series_by_IM (each (time, portion),
    portions as in (a) when there are 10 of them, else cavity.central_portions).
    Zero records are apart: the densities integrate to 1 - p0, the mean p0
    of the central portions is in the legend; x from 0 to xmax."""
    series = np.asarray(series, float)
    n = series.shape[1]
    edges = np.linspace(0.0, xmax, int(bins) + 1)
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.0, 3.8))

    def central(m):
        return list(range(portions[0] - 1, portions[1])) if m == 10 else cavity.central_portions(m)

    middle = central(n)
    for i in range(n):
        colour = "C1" if i in middle else ("C0" if i < min(middle, default=0) else "C3")
        x, dens, p0 = cavity.pdf_with_zeros(series[:, i], edges)
        label = f"i = {i + 1}" if i in (0, middle[0] if middle else 0, n - 1) else None
        left.plot(x, dens, color=colour, lw=0.8, label=label)
    left.set_xlim(0.0, xmax)
    left.set_xlabel(r"$F_i/\bar F_i$")
    left.set_ylabel("PDF (zeros apart)")
    left.set_title("(a) portions")
    left.legend(frameon=False, fontsize=7)
    ims = sorted(series_by_IM)
    for colour, im in zip(_im_colours(ims), ims):
        block = np.asarray(series_by_IM[im], float)
        cols = central(block.shape[1])
        curves, zeros = [], []
        for i in cols:
            x, dens, p0 = cavity.pdf_with_zeros(block[:, i], edges)
            if np.isfinite(p0):
                curves.append(dens)
                zeros.append(p0)
        if curves:
            right.plot(x, np.mean(curves, axis=0), color=colour, lw=1.0,
                       label=f"$I_M$ = {im:.2g}, $p_0$ = {np.mean(zeros):.2f}")
    right.set_xlim(0.0, xmax)
    right.set_xlabel(r"$F_i/\bar F_i$")
    right.set_ylabel("mean PDF, central portions")
    right.set_title("(b)")
    right.legend(frameon=False, fontsize=6)
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


def fig4_force_vortex(ell_over_L, Fnorm, IM, path, fit=None, title=""):
    """Fig. 4: F/(PLd) against ell/L (colour: log I_M), the Eq. 5 fit
    ((c1, c2)) and the paper's (0.88, 0.5)"""
    ell = np.asarray(ell_over_L, float)
    fig, ax = plt.subplots(figsize=(5.0, 4.0))
    ax.scatter(ell, Fnorm, c=np.log10(np.asarray(IM, float)), cmap="viridis", s=20)
    grid = np.linspace(0.0, 1.0, 50)
    if fit is not None:
        ax.plot(grid, fit[0] - fit[1] * grid, "C3-", lw=1.0, label=f"Eq. 5: $c_1$ = {fit[0]:.2f}, $c_2$ = {fit[1]:.2f}")
    c1, c2 = cavity.PAPER_EQ5
    ax.plot(grid, c1 - c2 * grid, "k--", lw=0.8, label=f"paper: {c1}, {c2}")
    ax.set_xlim(0.0, 1.0)
    ax.set_xlabel(r"$\ell/L$")
    ax.set_ylabel(r"$\bar F/(PLd)$")
    ax.set_title(title)
    ax.legend(frameon=False, fontsize=8)
    _save(fig, path)


def fig8_autocorrelation(curves, path, title="", max_periods=5.0):
    """Fig. 8: C(F(t), F(t + Delta t)) of the whole wall against Delta t (s)
    for several I_M; inset: against (U/d) Delta t.  curves: I_M -> (dt_rec
    (s), C (lag k at k dt_rec), d/U (s))"""
    ims = sorted(curves)
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    inset = ax.inset_axes([0.45, 0.45, 0.5, 0.45])
    for colour, im in zip(_im_colours(ims), ims):
        dt, C, period = curves[im]
        lags = np.arange(len(C)) * dt
        ax.plot(lags, C, color=colour, lw=0.9, label=f"$I_M$ = {im:.2g}")
        keep = lags <= max_periods * period
        inset.plot(lags[keep] / period, C[keep], color=colour, lw=0.8)
    ax.set_xscale("log")
    ax.axhline(cavity.THRESHOLD, color="k", ls="--", lw=0.7)
    ax.set_xlabel(r"$\Delta t$ (s)")
    ax.set_ylabel(r"$C(F(t), F(t+\Delta t))$")
    ax.legend(frameon=False, fontsize=7, loc="lower left")
    inset.axhline(0.0, color="0.6", lw=0.5)
    inset.set_xlabel(r"$(U/d)\Delta t$", fontsize=7)
    inset.tick_params(labelsize=6)
    ax.set_title(title)
    _save(fig, path)


def fig11_particle_pairs(groups, path, bins=40, xmax=6.0, title="grain-wall contact forces"):
    """Fig. 11: at each I_M (a panel), the particle-scale PDFs of f / mean(f)
    of each (N_U, N_P) pair; groups: I_M -> {(N_U, N_P): forces}"""
    ims = sorted(groups)
    fig, axes = plt.subplots(1, max(1, len(ims)), figsize=(3.2 * max(1, len(ims)), 3.4), squeeze=False)
    edges = np.linspace(0.0, xmax, int(bins) + 1)
    for ax, im in zip(axes[0], ims):
        for k, (pair, f) in enumerate(sorted(groups[im].items())):
            x, dens, p0 = cavity.pdf_with_zeros(f, edges)
            ax.plot(x, dens, color=f"C{k}", lw=1.0, label=f"$N_U$ = {pair[0]:g}, $N_P$ = {pair[1]:.3g}")
        ax.set_title(f"$I_M$ = {im:.2g}", fontsize=9)
        ax.set_xlabel(r"$f/\bar f$")
        ax.legend(frameon=False, fontsize=6)
    axes[0][0].set_ylabel("PDF")
    fig.suptitle(title)
    _save(fig, path)


def fig20_loglinear(particle, wall, path, fits_particle=None, fits_wall=None, bins=50, xmax=8.0):
    """Fig. 20: the PDFs of (a) f / mean(f) and (b) F / mean(F) on a
    log-linear scale with (1 - p0) Eq. 7; particle, wall: I_M -> records"""
    fig, axes = plt.subplots(1, 2, figsize=(8.5, 3.6))
    edges = np.linspace(0.0, xmax, int(bins) + 1)
    for ax, samples, fits, label in ((axes[0], particle, fits_particle, r"$f/\bar f$"),
                                     (axes[1], wall, fits_wall, r"$F/\bar F$")):
        ims = sorted(samples)
        for colour, im in zip(_im_colours(ims), ims):
            x, dens, p0 = cavity.pdf_with_zeros(samples[im], edges)
            ax.semilogy(x, np.where(dens > 0, dens, np.nan), "o", ms=2.5, color=colour, label=f"$I_M$ = {im:.2g}")
            fit = (fits or {}).get(im) or cavity.fit_eq7_with_zeros(samples[im])
            if np.isfinite(fit["mu"]):
                grid = np.linspace(1e-6, xmax, 300)
                ax.semilogy(grid, (1 - p0) * cavity.trunc_lognormal_pdf(grid, fit["mu"], fit["sigma"], fit["f0"]),
                            "-", color=colour, lw=0.8)
        ax.set_ylim(1e-4, 5.0)
        ax.set_xlim(0.0, xmax)
        ax.set_xlabel(label)
        ax.set_ylabel("PDF (zeros apart)")
        ax.legend(frameon=False, fontsize=6)
    axes[0].set_title("(a) particle scale")
    axes[1].set_title("(b) whole wall")
    _save(fig, path)


def fig6_mu_map(x, y, I, mu, path, L, h, params=cavity.PAPER_MU_I, title=""):
    """Fig. 6: the map of (mu_loc - mu_th) / mu_th, mu_th of Eq. 20 with
    params, over the cavity (x, y bin centres; I, mu (ny, nx)); the colour
    scale from -1 to 1"""
    with np.errstate(invalid="ignore", divide="ignore"):
        th = cavity.mu_I_model(I, *params)
        rel = (mu - th) / th
    keep = (y > 0) & (y < h)
    fig, ax = plt.subplots(figsize=(9.0, 9.0 * h / L * 1.2 + 1.2))
    image = ax.pcolormesh(x, y[keep], rel[keep], cmap="RdBu_r", vmin=-1, vmax=1, shading="nearest")
    fig.colorbar(image, ax=ax, label=r"$(\mu_{loc}-\mu_{th})/\mu_{th}$", shrink=0.8)
    ax.set_xlim(0.0, L)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(title)
    _save(fig, path)


def fig19_mu_I(points, path, fit=None, title="the region of Fig. 19"):
    """Fig. 19: mu_loc against I of the bins of each run's region (points:
    I_M -> (I, mu)), Eq. 20 fitted (fit: (mu1, mu2, I0)) and the paper's"""
    ims = sorted(points)
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    allI = []
    for colour, im in zip(_im_colours(ims), ims):
        I, mu = points[im]
        ax.semilogx(I, mu, ".", ms=2, color=colour, label=f"$I_M$ = {im:.2g}")
        allI.append(np.asarray(I, float))
    finite = np.concatenate(allI) if allI else np.array([1e-3])
    finite = finite[np.isfinite(finite) & (finite > 0)]
    grid = np.logspace(np.log10(max(finite.min(), 1e-6)) if finite.size else -5, 0.5, 200)
    if fit is not None:
        ax.semilogx(grid, cavity.mu_I_model(grid, *fit), "C3-", lw=1.0,
                    label=f"Eq. 20: {fit[0]:.2f}, {fit[1]:.2f}, {fit[2]:.2g}")
    ax.semilogx(grid, cavity.mu_I_model(grid, *cavity.PAPER_MU_I), "k--", lw=0.8, label="paper: 0.12, 0.40, 0.13")
    ax.set_ylim(-0.2, 1.0)
    ax.set_xlabel(r"$I$ (Eq. 18)")
    ax.set_ylabel(r"$\mu_{loc}$ (Eq. 19)")
    ax.set_title(title)
    ax.legend(frameon=False, fontsize=6)
    _save(fig, path)


def fig5_orientations(x, y, sxx, syy, sxy, Dxx, Dyy, Dxy, path, L, h, every=3, title=""):
    """Fig. 5: the principal directions (segments, every `every` bins) of
    (a) the strain rate (major extension) and (b) the stress (major
    compression, stress counted positive in compression) over the cavity"""
    X, Y = np.meshgrid(x, y)
    keep = (Y > 0) & (Y < h)
    sub = (slice(None, None, every), slice(None, None, every))
    fig, axes = plt.subplots(2, 1, figsize=(9.0, 2 * (9.0 * h / L + 0.8)))
    for ax, (a, b, c), label in ((axes[0], (Dxx, Dyy, Dxy), "(a) strain rate, major extension"),
                                 (axes[1], (sxx, syy, sxy), "(b) stress, major compression")):
        theta = cavity.principal_direction(a, b, c)
        good = keep & np.isfinite(theta)
        u, v = np.where(good, np.cos(theta), np.nan), np.where(good, np.sin(theta), np.nan)
        ax.quiver(X[sub], Y[sub], u[sub], v[sub], pivot="middle", headwidth=0, headlength=0, headaxislength=0,
                  scale=60, width=0.002)
        ax.set_xlim(0.0, L)
        ax.set_ylim(0.0, h)
        ax.set_aspect("equal")
        ax.set_title(label, fontsize=9)
    axes[1].set_xlabel("x (m)")
    if title:
        fig.suptitle(title)
    _save(fig, path)


def fig_memory(rows, groups, path, title=""):
    """<Delta t_c> (mean over the portions) against I_M: (a) in units of
    d/U, (b) in ms; rows: one dict per run (I_M, NU, dtc_mean_dU,
    dtc_mean_s), marked by N_U; groups: I_M -> {"dtc_mean_dU": (mean, sem,
    n), "dtc_mean_s": ...} (cavity_collect.by_im), drawn with error bars"""
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.8))
    markers = {}
    for r in rows:
        k = markers.setdefault(r["NU"], len(markers))
        for ax, key, scale in ((axes[0], "dtc_mean_dU", 1.0), (axes[1], "dtc_mean_s", 1e3)):
            ax.plot(r["I_M"], scale * r[key], "osd^v"[k % 5], color=f"C{k}", ms=4, alpha=0.7,
                    label=f"$N_U$ = {r['NU']:g}" if ax is axes[0] else None)
    ims = sorted(groups)
    for ax, key, scale in ((axes[0], "dtc_mean_dU", 1.0), (axes[1], "dtc_mean_s", 1e3)):
        mean = np.array([groups[im][key][0] for im in ims]) * scale
        sem = np.array([groups[im][key][1] for im in ims]) * scale
        ax.errorbar(ims, mean, yerr=np.nan_to_num(sem), fmt="k_", ms=14, capsize=3, lw=1, label="mean ± s.e.")
        ax.set_xscale("log")
        ax.set_xlabel(r"$I_M$")
    handles, labels = axes[0].get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    axes[0].legend(unique.values(), unique.keys(), frameon=False, fontsize=7)
    axes[0].set_ylabel(r"$\langle \Delta t_c \rangle$ (d/U)")
    axes[1].set_ylabel(r"$\langle \Delta t_c \rangle$ (ms)")
    axes[1].set_yscale("log")
    axes[0].set_title("(a) in units of d/U")
    axes[1].set_title("(b) in seconds")
    if title:
        fig.suptitle(title)
    _save(fig, path)


def fig_us_effects(effects, path, title="the drive's effect (driven minus undriven, same packing)"):
    """The effect of the ultrasound against where the drive falls in the
    network's spectrum (the fraction of the modes below it), one curve per
    N_U: effects is cavity_collect.us_effects's {(NU, f): {quantity: (mean,
    sem, n)}}; panels F/(PLd), <Delta t_c> (d/U), CV of F"""
    fig, axes = plt.subplots(1, 3, figsize=(11.0, 3.6))
    nus = sorted({NU for NU, _ in effects})
    for k, NU in enumerate(nus):
        keys = sorted(f for n, f in effects if n == NU)
        for ax, q, label in zip(axes, ("Fnorm", "dtc_mean_dU", "cv_wall"),
                                (r"$\Delta \bar F/(PLd)$", r"$\Delta\langle\Delta t_c\rangle$ (d/U)", r"$\Delta$ CV of $F$")):
            x = [effects[(NU, f)]["modes_below_drive"][0] for f in keys]
            x = [xi if np.isfinite(xi) else f / 1e5 for xi, f in zip(x, keys)]
            y = [effects[(NU, f)].get(q, (np.nan, np.nan, 0))[0] for f in keys]
            e = [effects[(NU, f)].get(q, (np.nan, np.nan, 0))[1] for f in keys]
            im = effects[(NU, keys[0])]["I_M"]
            ax.errorbar(x, y, yerr=np.nan_to_num(e), fmt="o-", color=f"C{k}", capsize=3, ms=4,
                        label=f"$N_U$ = {NU:g}, $I_M$ = {im:.2g}")
            ax.axhline(0.0, color="0.6", lw=0.6)
            ax.set_xlabel("fraction of the modes below the drive")
            ax.set_ylabel(label)
    axes[0].legend(frameon=False, fontsize=7)
    fig.suptitle(title)
    _save(fig, path)
