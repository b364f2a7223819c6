"""Figures of paper 003 (sound in confined packings) from the results that
acoustic_tools.sound_collect gathers (Figs. 1-12); matplotlib, PNG.  Each function takes
plain arrays or dicts, so it also serves users' own runs."""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import sound  # noqa: E402


def _save(fig, path, dpi=120, colours=None, tight=True):
    """tight layout (unless told: a figure laid out already), PNG; colours:
    a palette of that many colours (the drawings of grains and arrows stay
    small files)"""
    if tight:
        fig.tight_layout()
    if colours is None:
        fig.savefig(path, dpi=dpi)
    else:
        import io

        from PIL import Image
        buffer = io.BytesIO()
        fig.savefig(buffer, dpi=dpi, format="png")
        buffer.seek(0)
        Image.open(buffer).convert("RGB").quantize(colors=colours).save(path, optimize=True)
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
    ax.set_xlabel(r"$t\ /\ d\sqrt{\rho/E^*}$")
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
    fit = sound.arrival_fit(heights, t10)
    x = np.linspace(0.0, max(heights) * 1.05, 10)
    ax.plot(x, x / fit["speed"] + fit["intercept"], "k--", lw=0.8,
            label=f"fit of the 10 % arrivals on L = {fit['L_min']:.0f}–{fit['L_max']:.0f}: "
                  f"1/slope = {fit['speed']:.3f}")
    ax.set_xlabel(r"source-detector distance $L\ /\ d$")
    ax.set_ylabel(r"arrival time $/\ d\sqrt{\rho/E^*}$")
    ax.set_title(title)
    ax.legend(frameon=False, fontsize=8)
    _save(fig, path)


def fig7_exponents(curves, path):
    """Fig. 7: effective exponents gamma_eff = -d log A / d log L and
    alpha_eff = d log W / d log L between successive sizes; curves: label ->
    (L, A, W) or (L, A, W, A_se, W_se), the means of A and W with their
    standard errors (error bars: sound.effective_exponents_se); the paper's
    values of Table III as grey lines"""
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9.5, 6.5), sharex=True)
    markers = "os^vDp<>h"
    for k, (label, curve) in enumerate(curves.items()):
        length, amplitude, width = curve[:3]
        a_se, w_se = curve[3:5] if len(curve) >= 5 else (np.zeros(len(length)), np.zeros(len(length)))
        x, gamma, gamma_se = sound.effective_exponents_se(length, amplitude, a_se)
        _, alpha, alpha_se = sound.effective_exponents_se(length, width, w_se)
        style = dict(color=f"C{k}", marker=markers[k % len(markers)], ms=4, lw=1, capsize=2, label=label)
        if k == 0 or "identical" in label:
            style["mfc"] = "none"
        top.errorbar(x, -gamma, yerr=gamma_se, **style)
        bottom.errorbar(x, alpha, yerr=alpha_se, **style)
    for value, style in ((2.0 / 3.0, ":"), (1.0, "--"), (1.5, "-.")):
        top.axhline(value, color="0.5", ls=style, lw=0.8)
    for value, style in ((1.0 / 3.0, ":"), (1.0, "--")):
        bottom.axhline(value, color="0.5", ls=style, lw=0.8)
    top.set_ylabel(r"$\gamma_{eff} = -d\,\log A / d\,\log L$")
    bottom.set_ylabel(r"$\alpha_{eff} = d\,\log W / d\,\log L$")
    bottom.set_xlabel("L (balls, rows or d)")
    top.set_xscale("log")
    top.legend(frameon=False, fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    bottom.set_title("W: first zero crossing − 10 % arrival", fontsize=8)
    fig.subplots_adjust(left=0.09, right=0.6, bottom=0.08, top=0.97, hspace=0.15)    # the legend to the right
    _save(fig, path, tight=False)


def fig8_speeds(pressure, c_tof, c_tof_err, c_l, c_t, path, lattice=None):
    """Fig. 8: sound speeds against pressure, with paper 003's Eqs. 18-19
    (Eq. 19's band: k_t/k_n = eta = 2 (1 - nu) / (2 - nu) for 0 <= nu <= 0.5)
    and the p^(1/6) law; lattice: label -> (pressures, c_tof) of perfect
    triangular lattices (frictionless: +, frictional: x)"""
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    p = np.asarray(pressure)
    every = list(p) + [q for ps, _ in (lattice or {}).values() for q in ps]
    low, high = min(every), max(every)
    ax.errorbar(p, c_tof, yerr=c_tof_err, fmt="o", label=r"$c_{tof}$ (2D disordered, this package)")
    ax.plot(p, c_l, "s", mfc="none", label=r"$c_\ell = \sqrt{C_{22}/\Phi_3^*}$")
    ax.plot(p, 2.0 * np.asarray(c_t), "v", mfc="none", label=r"$2 c_t$")
    for label, (ps, cs) in (lattice or {}).items():
        ax.plot(ps, cs, "+" if "frictionless" in label else "x", color="C3" if "frictionless" in label else "C2",
                ms=8, mew=1.5, ls="none", label=label)
    grid = np.logspace(np.log10(low) - 0.3, np.log10(high) + 0.3, 50)
    ax.plot(grid, [sound.triangular_lattice_speed(x) for x in grid], "k-", lw=0.8,
            label="triangular lattice, Eq. 18")
    ax.fill_between(grid, [sound.triangular_lattice_speed(x, eta=2.0 / 3.0) for x in grid],
                    [sound.triangular_lattice_speed(x, eta=1.0) for x in grid], color="0.8",
                    label=r"Eq. 19, $0 \leq \nu \leq 0.5$")
    ax.plot(grid, [sound.triangular_lattice_speed(x, eta=1.0) for x in grid], "k--", lw=0.8,
            label=r"Eq. 19 ($\nu$ = 0, $\eta$ = 1)")
    ax.plot(grid, 0.26 * (grid / 1e-4) ** (1.0 / 6.0), color="0.6", ls=":", label=r"$0.26\,(p/10^{-4})^{1/6}$")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"$p / E^*$")
    ax.set_ylabel(r"$c / \sqrt{E^*/\rho}$")
    ax.legend(frameon=False, fontsize=6.5)
    _save(fig, path)


def fig12_shapes(curves, path, title, limit=True):
    """Fig. 12: the coherent front of condition A in the chain's scaled
    variables, x = (c tau / l) / (c t / l)^(1/3) and y = F (c t / l)^(2/3) /
    (K l) (tau from the time (N + 1) l / c the front needs to reach the
    wall; K, m, l of the bulk chain; the paper's normalisation u'_1(0) = c:
    sound_chain.scaled_front), where Eq. 16 is the one
    curve y = -8 Ai'(-2 x) for large N (thick black: the N -> infinity
    limit of sound_chain.airy_front); curves: label -> (x, y, style), style
    "line" (chains) or "points" (lattices)"""
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    if limit:
        from scipy.special import airy
        x = np.linspace(-4.0, 3.0, 600)
        ax.plot(x, -8.0 * airy(-2.0 * x)[1], "k-", lw=3.0, alpha=0.8, label="Eq. 16 (N → ∞), factor from Eq. C4")
    for k, (label, (x, y, style)) in enumerate(curves.items()):
        if style == "points":
            ax.plot(x, y, "o", ms=3.5, color=f"C{3 + k % 4}", label=label)
        else:
            ax.plot(x, y, "-", lw=1.0, color=f"C{k}", label=label)
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlim(-4.0, 3.0)
    ax.set_xlabel(r"$(c\tau/\ell)\,/\,(ct/\ell)^{1/3}$")
    ax.set_ylabel(r"$F\,(ct/\ell)^{2/3} / K\ell$")
    ax.set_title(title, fontsize=9)
    ax.legend(frameon=False, fontsize=7)
    _save(fig, path)


def fig5_heights(signals, path, title):
    """Fig. 5: the coherent part of the signal at several source-detector
    distances; signals: label -> (t, F) (e.g. the ensemble means of each
    height), drawn up to a little past the first zero crossing of the
    tallest (the whole record when a signal does not cross zero after its
    peak)"""
    fig, ax = plt.subplots(figsize=(6.0, 4.0))
    end = 0.0
    for k, (label, (t, f)) in enumerate(signals.items()):
        peak = sound.coherent_peak(t, f)
        past = peak["t_zero"] + 1.5 * (peak["t_zero"] - peak["t10"])
        end = max(end, past if np.isfinite(past) else float(np.max(t)))
        ax.plot(t, f, color=f"C{k}", lw=1.3, label=label)
    ax.set_xlim(0.0, end)
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel(r"$t\ /\ d\sqrt{\rho/E^*}$")
    ax.set_ylabel(r"$F_{sig}$ (unit pulse)")
    ax.set_title(title, fontsize=9)
    ax.legend(frameon=False, fontsize=8)
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


# ---- figures of one packing's network and modes (sound_modes, in.figures)
#
# Figs. 1, 3 and 10 draw the packing itself; they share its drawing
# (_packing_panel) and their type: sized for print at the paper's widths (one
# column COLUMN, the page PAGE, inches), type of PRINT_TYPE points at that
# size, PRINT_DPI dots per inch.  The study's reduced units: lengths in grain
# diameters d, times in d sqrt(rho/E*), forces in E* d^2.

COLUMN, PAGE = 3.4, 7.0
PRINT_TYPE = 10
PRINT_DPI = 200
PRINT_STYLE = {key: PRINT_TYPE for key in ("font.size", "axes.titlesize", "axes.labelsize", "xtick.labelsize",
                                           "ytick.labelsize", "legend.fontsize", "legend.title_fontsize",
                                           "figure.titlesize")}
TIME_UNIT = r"$d\sqrt{\rho/E^*}$"
FREQUENCY_UNIT = r"$\sqrt{E^*/\rho}\,/\,d$"
GRAIN_DOT = 0.6          # the grey dot on a grain's centre, a fraction of its diameter
NETWORK_LINE = 1.0       # Fig. 1: the width (points) of a contact line at the mean force (stiffness)
ARROWS_LARGEST = 2.0     # Figs. 3, 10: the largest arrow is this long (d)


def _packing_figure(size, rows, columns, aspect, left=0.55, right=0.1, bottom=0.5, top=0.6, gaps=0.3, hspace=0.8):
    """a figure `size` inches wide (COLUMN or PAGE) of rows x columns panels
    of one height/width ratio (aspect: the packing's), laid out in inches
    (tight_layout leaves panels of fixed aspect small): the margins left,
    right, bottom and top, the gaps between columns (one or one per gap)
    and between rows (hspace) hold the labels and titles.  Returns the
    figure and the axes (rows x columns)"""
    gaps = np.broadcast_to(np.asarray(gaps, dtype=float), (columns - 1,))
    panel = (size - left - right - gaps.sum()) / columns
    tall = panel * aspect
    height = bottom + rows * tall + (rows - 1) * hspace + top
    fig = plt.figure(figsize=(size, height))
    starts = left + np.concatenate(([0.0], np.cumsum(gaps + panel)))
    axes = [[fig.add_axes([starts[c] / size, (bottom + (rows - 1 - r) * (tall + hspace)) / height, panel / size,
                           tall / height]) for c in range(columns)] for r in range(rows)]
    return fig, np.array(axes)


def _packing_panel(ax, x, y, radius, width, height, xlabel=True, ylabel=True):
    """one packing in the plane of the centres, as Figs. 1, 3 and 10 draw it:
    a grey dot (GRAIN_DOT of the diameter, to scale) on each grain's centre,
    the box 0 < x < width (periodic), 0 < y < height (the bottom wall, the
    source, and the top wall, the detector), axes in grain diameters;
    xlabel, ylabel: False on the inner panels of a grid (no labels, no
    tick labels)"""
    from matplotlib.collections import EllipseCollection
    size = GRAIN_DOT * 2.0 * np.asarray(radius, dtype=float)
    ax.add_collection(EllipseCollection(size, size, np.zeros(len(size)), units="xy",
                                        offsets=np.column_stack((x, y)), offset_transform=ax.transData,
                                        facecolors="0.75", linewidths=0, zorder=1))
    ax.set_xlim(0.0, width)
    ax.set_ylim(0.0, height)
    ax.set_aspect("equal")
    ax.set_xticks(np.arange(0.0, width + 1e-9, 10.0))
    ax.set_yticks(np.arange(0.0, height + 1e-9, 10.0))
    ax.tick_params(labelbottom=xlabel, labelleft=ylabel)
    if xlabel:
        ax.set_xlabel(r"$x\,/\,d$")
    if ylabel:
        ax.set_ylabel(r"$y\,/\,d$")


def _round_down(value):
    """the largest 1, 2 or 5 times a power of ten not above value (> 0)"""
    power = 10.0 ** math.floor(math.log10(value))
    return max(m * power for m in (1.0, 2.0, 5.0) if m * power <= value * (1.0 + 1e-12))


def _latex_number(value, digits=2):
    """value as a x 10^k in mathtext"""
    mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
    return rf"{mantissa}\times10^{{{int(exponent)}}}"


def fig1_network(grains, segments, forces, stiffnesses, width, height, path, title):
    """Fig. 1: (a) the normal forces of one packing as lines of width
    proportional to the force, (b) the same for the normal stiffness
    dF_n/dn, each with the key of its line widths (multiples of the mean,
    the mean in reduced units), (c) the histograms of the forces and
    stiffnesses of many packings, each over its mean (equal areas); grains:
    dict of x, y, radius; segments: rows x0, y0, x1, y1, f_n, k_n
    (sound_modes.network_segments); title: above the three panels"""
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D
    with plt.rc_context(PRINT_STYLE):
        fig, axes = _packing_figure(PAGE, 1, 3, height / width, bottom=1.25, top=0.65, gaps=(0.15, 0.8))
        axes = axes[0]
        below = 0.45 / (axes[0].get_position().height * fig.get_figheight())   # the key under the x label
        panels = ((axes[0], 4, "(a) normal forces", "f_n", "E^*d^2"),
                  (axes[1], 5, "(b) normal stiffnesses", "k_n", "E^*d"))
        for ax, column, label, symbol, unit in panels:
            _packing_panel(ax, grains["x"], grains["y"], grains["radius"], width, height, ylabel=ax is axes[0])
            values = segments[:, column]
            mean = values.mean()
            ax.add_collection(LineCollection(segments[:, :4].reshape(-1, 2, 2),
                                             linewidths=NETWORK_LINE * values / mean, colors="k", zorder=2))
            ax.set_title(label)
            multiples = (1, 2, 4)
            ax.legend([Line2D([], [], color="k", lw=NETWORK_LINE * m) for m in multiples], [f"{m}" for m in multiples],
                      title=rf"line width: ${symbol}/\langle {symbol}\rangle$" + "\n"
                            + rf"$\langle {symbol}\rangle = {_latex_number(mean)}\,{unit}$",
                      loc="upper center", bbox_to_anchor=(0.5, -below), ncol=3, frameon=False, handlelength=1.6,
                      columnspacing=1.2, borderaxespad=0.0)
        ax = axes[2]
        f = np.asarray(forces) / np.mean(forces)
        k = np.asarray(stiffnesses) / np.mean(stiffnesses)
        bins = np.linspace(0.0, max(f.max(), k.max()), 60)
        ax.hist(f, bins=bins, density=True, histtype="step", color="C0", label=r"$f_n / \langle f_n\rangle$")
        ax.hist(k, bins=bins, density=True, histtype="step", color="C3", label=r"$k_n / \langle k_n\rangle$")
        ax.set_xlabel("value / mean")
        ax.set_ylabel("probability density")
        ax.set_title("(c) histograms")
        ax.legend(frameon=False)
        fig.suptitle(title, y=1.0 - 0.12 / fig.get_figheight(), va="top")
        _save(fig, path, dpi=PRINT_DPI, colours=64, tight=False)


def fig2_directions(histogram, path, title):
    """Fig. 2: polar histograms of the contact directions, all, strong (force
    above the mean) and weak contacts (histogram: sound_modes.direction_histogram),
    each direction drawn at theta and theta + pi; the dashed circle is the
    isotropic density 1/pi"""
    edges = histogram["edges"]
    centres = 0.5 * (edges[1:] + edges[:-1])
    width = edges[1] - edges[0]
    fig, axes = plt.subplots(1, 3, figsize=(10.0, 3.8), subplot_kw={"projection": "polar"})
    top = max(histogram[name]["density"].max() for name in ("all", "strong", "weak")) * 1.1
    circle = np.linspace(0.0, 2.0 * np.pi, 200)
    for ax, name in zip(axes, ("all", "strong", "weak")):
        h = histogram[name]
        for shift in (0.0, np.pi):
            ax.bar(centres + shift, h["density"], width=width, color="C0", alpha=0.6, edgecolor="C0")
        ax.plot(circle, np.full(len(circle), 1.0 / np.pi), "k--", lw=0.8)
        ax.set_ylim(0.0, top)
        ax.set_yticklabels([])
        ax.set_title(f"{name} contacts ({h['count']})\n" + r"$F_2 = \langle n_y^2\rangle$" + f" = {h['F2']:.3f}",
                     fontsize=11)
    fig.suptitle(title, fontsize=11)
    _save(fig, path, dpi=110, colours=32)


def _arrows(ax, x, y, u, v, magnification):
    """the displacements (u, v) of the grains as arrows from their centres,
    magnified magnification times (lengths in d; an arrow shorter than its
    head shrinks with it, no dot for the grains at rest); the Quiver, for a
    key"""
    return ax.quiver(x, y, u, v, angles="xy", scale_units="xy", scale=1.0 / magnification, units="xy",
                     width=0.12, headwidth=3, headlength=3, headaxislength=2.7, minlength=0.0, zorder=3)


def fig3_snapshot(x, y, radius, ux, uy, width, height, time, path, title):
    """Fig. 3: the displacement of every grain at one time after the pulse
    (condition A, a unit pulse of the bottom wall), as arrows magnified so
    that the largest is ARROWS_LARGEST d long, with a key arrow of a round
    displacement (in d) and the time of the snapshot (in d sqrt(rho/E*))"""
    with plt.rc_context(PRINT_STYLE):
        fig, axes = _packing_figure(COLUMN, 1, 1, height / width, top=0.95)
        ax = axes[0, 0]
        _packing_panel(ax, x, y, radius, width, height)
        largest = np.max(np.hypot(ux, uy))
        magnification = ARROWS_LARGEST / largest
        arrows = _arrows(ax, x, y, ux, uy, magnification)
        key = _round_down(largest)
        ax.quiverkey(arrows, 0.03, 1.05, key, rf"$u$ = {key:g} $d$ (arrows: $u\times${magnification:.3g})",
                     labelpos="E", coordinates="axes")
        ax.set_title(f"{title}\n$t$ = {time:g} {TIME_UNIT} after a unit pulse", pad=22)
        _save(fig, path, dpi=PRINT_DPI, colours=16, tight=False)


def fig9_modes(omega2, contribution, marked, zero_modes, path, title):
    """Fig. 9: (a) omega_n^2 against the mode number n (zero modes of the
    rattlers first; inset: the lowest non-zero ones), (b) the contribution
    a_n b_n of each mode to the signal (Eq. 3); the modes of Fig. 10 circled"""
    n = np.arange(len(omega2))
    marked = np.asarray(marked, dtype=int)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10.0, 4.0))
    left.plot(n, omega2, ".", ms=2)
    left.plot(marked, omega2[marked], "o", mfc="none", color="C3", ms=8)
    left.set_xlabel("mode n")
    left.set_ylabel(r"$\omega_n^2$")
    left.set_title(f"(a) {title}: {zero_modes} zero modes", fontsize=9)
    inset = left.inset_axes([0.12, 0.45, 0.4, 0.45])
    low = slice(max(zero_modes - 5, 0), zero_modes + 30)
    inset.plot(n[low], omega2[low], ".", ms=3)
    inset.tick_params(labelsize=6)
    right.plot(n, contribution, "-", lw=0.6)
    right.plot(marked, contribution[marked], "o", mfc="none", color="C3", ms=8)
    right.axhline(0.0, color="k", lw=0.5)
    right.set_xlabel("mode n")
    right.set_ylabel(r"$a_n b_n$")
    right.set_title(r"(b) contribution to $F_{sig}$ (Eq. 3), condition A", fontsize=9)
    _save(fig, path)


def fig10_modes(shapes, width, height, path, title=None):
    """Fig. 10: selected eigenmodes as arrows on the grains, panels (a),
    (b), ...; shapes: list of (label, x, y, radius, ux, uy), each magnified
    so that its largest arrow is ARROWS_LARGEST d long (the shapes are
    mass-normalised: their scale is arbitrary); title: above the panels"""
    count = len(shapes)
    columns = 3 if count > 4 else 2
    rows = -(-count // columns)
    with plt.rc_context(PRINT_STYLE):
        fig, axes = _packing_figure(PAGE, rows, columns, height / width, top=1.15 if title else 0.75, gaps=0.15,
                                    hspace=0.75)
        for k, (ax, (label, x, y, radius, ux, uy)) in enumerate(zip(axes.ravel(), shapes)):
            _packing_panel(ax, x, y, radius, width, height, xlabel=k + columns >= count, ylabel=k % columns == 0)
            _arrows(ax, x, y, ux, uy, ARROWS_LARGEST / np.max(np.hypot(ux, uy)))
            ax.set_title(f"({chr(ord('a') + k)}) {label}")
        for ax in axes.ravel()[count:]:
            ax.axis("off")
        if title:
            fig.suptitle(title, y=1.0 - 0.1 / fig.get_figheight(), va="top")
        _save(fig, path, dpi=PRINT_DPI, colours=16, tight=False)


def fig11_damping(signals, path, title):
    """Fig. 11: F_sig(t) with contact damping, signals: {fraction of critical
    damping: (t, F)}"""
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for k, (zeta, (t, f)) in enumerate(sorted(signals.items())):
        ax.plot(t, f, color=f"C{k}", lw=0.9, label=f"{zeta:g} of critical")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel(r"$t\ /\ d\sqrt{\rho/E^*}$")
    ax.set_ylabel(r"$F_{sig}$ (unit pulse)")
    ax.set_title(title, fontsize=9)
    ax.legend(frameon=False, fontsize=8)
    _save(fig, path)
