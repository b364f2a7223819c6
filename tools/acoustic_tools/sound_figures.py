"""Figures of paper 003 (sound in confined packings) from the results that
examples/sound/collect.py gathers; matplotlib, PNG.  Each function takes
plain arrays or dicts, so it also serves users' own runs."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import sound  # noqa: E402


def _save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def fig4_signals(signals, mean_signal, path, title):
    """Fig. 4: F_sig(t) of several samples (grey), their mean and RMS"""
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for t, f in signals:
        ax.plot(t, f, color="0.75", lw=0.6)
    t, mean, rms = mean_signal
    ax.plot(t, mean, color="C0", lw=1.5, label="ensemble mean")
    ax.plot(t, rms, color="C3", lw=1.0, label="RMS deviation")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("t")
    ax.set_ylabel(r"$F_{sig}$ (unit pulse)")
    ax.set_title(title)
    ax.legend(frameon=False)
    _save(fig, path)


def fig6_arrival_times(heights, t10, t_peak, t_zero, path, title):
    """Fig. 6: arrival times of the coherent peak against the source-detector
    distance, with the linear fit of the 10 % arrival"""
    fig, ax = plt.subplots(figsize=(5.0, 4.0))
    ax.plot(heights, t10, "^", label="10 % of the peak")
    ax.plot(heights, t_peak, "o", mfc="none", label="peak")
    ax.plot(heights, t_zero, "s", label="first zero crossing")
    slope, intercept = np.polyfit(heights, t10, 1)
    x = np.linspace(0.0, max(heights) * 1.05, 10)
    ax.plot(x, slope * x + intercept, "k--", lw=0.8, label=f"$c_{{tof}}$ = {1.0 / slope:.3f}")
    ax.set_xlabel("source-detector distance L")
    ax.set_ylabel("arrival time")
    ax.set_title(title)
    ax.legend(frameon=False)
    _save(fig, path)


def fig7_exponents(curves, path):
    """Fig. 7: effective exponents gamma_eff = -d log A / d log L and
    alpha_eff = d log W / d log L; curves: label -> (L, A, W)"""
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(5.5, 6.0), sharex=True)
    for k, (label, (length, amplitude, width)) in enumerate(curves.items()):
        x, gamma = sound.effective_exponents(length, amplitude)
        _, alpha = sound.effective_exponents(length, width)
        top.plot(x, -gamma, "o-", color=f"C{k}", label=label)
        bottom.plot(x, alpha, "o-", color=f"C{k}", label=label)
    for value, style in ((2.0 / 3.0, ":"), (1.0, "--"), (1.5, "-.")):
        top.axhline(value, color="0.5", ls=style, lw=0.8)
    for value, style in ((1.0 / 3.0, ":"), (1.0, "--")):
        bottom.axhline(value, color="0.5", ls=style, lw=0.8)
    top.set_ylabel(r"$\gamma_{eff}$")
    bottom.set_ylabel(r"$\alpha_{eff}$")
    bottom.set_xlabel("L")
    top.set_xscale("log")
    top.legend(frameon=False, fontsize=8)
    _save(fig, path)


def fig8_speeds(pressure, c_tof, c_tof_err, c_l, c_t, path):
    """Fig. 8: sound speeds against pressure, with paper 003's Eqs. 18-19
    and the p^(1/6) law"""
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    p = np.asarray(pressure)
    ax.errorbar(p, c_tof, yerr=c_tof_err, fmt="o", label=r"$c_{tof}$ (2D disordered, this package)")
    ax.plot(p, c_l, "s", mfc="none", label=r"$c_\ell = \sqrt{C_{22}/\Phi_3^*}$")
    ax.plot(p, 2.0 * np.asarray(c_t), "v", mfc="none", label=r"$2 c_t$")
    grid = np.logspace(np.log10(p.min()) - 0.3, np.log10(p.max()) + 0.3, 50)
    ax.plot(grid, [sound.triangular_lattice_speed(x) for x in grid], "k-", lw=0.8,
            label="triangular lattice, Eq. 18")
    ax.plot(grid, [sound.triangular_lattice_speed(x, eta=1.0) for x in grid], "k--", lw=0.8,
            label=r"triangular lattice, Eq. 19 ($\eta$ = 1)")
    ax.plot(grid, 0.26 * (grid / 1e-4) ** (1.0 / 6.0), color="0.6", ls=":", label=r"$0.26\,(p/10^{-4})^{1/6}$")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"$p / E^*$")
    ax.set_ylabel(r"$c / \sqrt{E^*/\rho}$")
    ax.legend(frameon=False, fontsize=7)
    _save(fig, path)


def fig9_spectrum(frequencies, path, title):
    """Fig. 9a: squared eigenfrequencies against the mode number"""
    omega2 = (2.0 * np.pi * np.asarray(frequencies)) ** 2
    fig, ax = plt.subplots(figsize=(5.5, 4.0))
    ax.plot(np.arange(len(omega2)), omega2, ".", ms=2)
    ax.set_xlabel("mode n")
    ax.set_ylabel(r"$\omega_n^2$")
    ax.set_title(title)
    _save(fig, path)


def stress_ratio_against_overshoot(overshoot, ratio, pressure, path):
    """sigma_1/sigma_2 of each packing against the largest pressure of its
    compression over the final one (p_peak/p): how overconsolidated the
    packing is; one colour per pressure"""
    fig, ax = plt.subplots(figsize=(5.0, 4.0))
    overshoot, ratio, pressure = map(np.asarray, (overshoot, ratio, pressure))
    for k, p in enumerate(sorted(set(pressure.tolist()))):
        chosen = pressure == p
        ax.plot(overshoot[chosen], ratio[chosen], "o", color=f"C{k}", label=f"p = {p:g}")
    ax.axhspan(0.71 - 0.04, 0.79 + 0.06, color="0.85", label="paper 003, Table II")
    ax.set_xscale("log")
    ax.set_xlabel(r"$p_{peak} / p$ during the compression")
    ax.set_ylabel(r"$\sigma_1/\sigma_2$")
    ax.legend(frameon=False, fontsize=8)
    _save(fig, path)
