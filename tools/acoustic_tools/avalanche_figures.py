"""PNG figures of paper 000 from avalanche runs (examples/avalanche), matplotlib only.

Each fig_* function takes the data it draws and the path of the PNG, writes
the PNG, says so on stdout and returns the figure (closed).  The command
line draws them from files:

    python3 -m acoustic_tools.avalanche_figures modes  [RUN.dump RUN.contacts] [--hist modes.hist] [--frame K] [--f0 70e3] -o fig3.png
        Fig. 3: density of states of the contact network, from compute vibration/modes
        (--hist, the file of in.modes) and/or rebuilt from a dump and its contacts dump
    python3 -m acoustic_tools.avalanche_figures sigma  RUN.series --theta 19.5 [RUN2.series --theta 15 ...] -o fig6.png
        Figs. 6 / 9: sigma_1, sigma_2 against the time since the tilt to theta
    python3 -m acoustic_tools.avalanche_figures thetam TABLE -o fig7.png [--coupling-of-70 TEXT]
        Fig. 7: theta_m against H/d; TABLE lines "H/d theta0 sd0 theta70 sd70"
        (ensemble means and standard deviations; optional 6th and 7th columns:
        paper 000's values, nan if unknown); --free TABLE2 adds the free-ends ensembles
    python3 -m acoustic_tools.avalanche_figures tcon   TABLE -o fig8.png [--coupling TEXT]
        Fig. 8: t_con against theta, one panel per H/d; TABLE lines "H<H>_<f>kHz theta t_con [thetam|run]"
        (one per run; thetam: the ramp's flow at theta_m, a star; paper000_...: paper 000's values)
    python3 -m acoustic_tools.avalanche_figures kappa  TABLE -o kappa_shift.png
        the 70 kHz shift against kappa_scale; TABLE lines "kappa H seed shift mu_factor
        onset_shift geometry"
    python3 -m acoustic_tools.avalanche_figures chains RUN.dump RUN.contacts [--frame K] -o fig10.png
        Fig. 10: force chains, width proportional to f_n, colour 1 - mu*/mu
    python3 -m acoustic_tools.avalanche_figures calibration calibration.json -o calibration.png
        the calibration scan of examples/avalanche/study.py calibrate: fraction of
        contacts with mu*/mu < 0.5 against U0/d, kappa_scale, C_mu and the
        damping ratio for both sources; sound speed and highest mode against kappa_scale
"""
import json
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
import matplotlib.ticker  # noqa: E402

from . import avalanche as av  # noqa: E402
from .lammps_output import read_ave_time_vector, read_dump  # noqa: E402


def _frames(dump, contacts, frame):
    """Frame `frame` of a dump and the contacts (named columns) at its timestep."""
    atoms = read_dump(dump)[frame]
    return atoms, av.contact_columns(av.contacts_at(contacts, atoms.timestep))


def _save(fig, path, dpi):
    """Write fig to path (PNG, tight bounding box), close it, say so; returns fig."""
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    plt.close(fig)
    print(f"wrote {path}")
    return fig


def sigma_runs(paths, thetas):
    """The runs of fig_sigma from series files of in.avalanche: (the last two
    parts of the path, the series, theta) for each path and angle."""
    return [("/".join(path.split("/")[-2:]), av.read_series(path), theta) for path, theta in zip(paths, thetas)]


def fig_modes(path, histogram=None, histogram_name="", network=None, f0=70e3, bins=60, dpi=110):
    """Fig. 3, density of states: the histogram of compute vibration/modes
    (rows centre (Hz), density (1/Hz) of the last block of in.modes' file,
    titled histogram_name) and/or the spectrum of the network rebuilt from
    network = (atoms, contacts), a dump frame and its contacts (named
    columns), in `bins` bins; the drive f0 (Hz) drawn as a line."""
    if histogram is None and network is None:
        raise ValueError("fig_modes: give a histogram and/or a network")
    fig, ax = plt.subplots(figsize=(5, 3.2))
    title = []
    if histogram is not None:
        centre, dens = histogram[:, 0] / 1e3, histogram[:, 1] * 1e3          # per kHz
        width = centre[1] - centre[0]
        ax.bar(centre, dens, width=width, color="tab:blue", alpha=0.7, label="compute vibration/modes")
        title.append(histogram_name)
    if network is not None:
        f = av.network_spectrum(*network) / 1e3
        nz = f[f > 1e-6 * f.max()]
        edges = np.linspace(0, max(nz.max(), f0 / 1e3) * 1.05, bins + 1)
        cnt, edges = np.histogram(nz, bins=edges)
        dens = cnt / (len(nz) * np.diff(edges))
        ax.step(edges[:-1], dens, where="post", color="k", lw=1, label="acoustic_tools.avalanche")
        title.append(f"{len(f)} modes ({len(f) - len(nz)} zero), {100 * np.mean(nz > f0 / 1e3):.1f} % "
                     f"above {f0 / 1e3:g} kHz, highest {nz.max():.1f} kHz")
    ax.axvline(f0 / 1e3, color="tab:orange", lw=2, label=f"drive {f0 / 1e3:g} kHz")
    ax.set_xlabel("eigenfrequency (kHz)")
    ax.set_ylabel("density of states (1/kHz)")
    ax.set_title("\n".join(title), fontsize=8)
    ax.legend(fontsize=7)
    return _save(fig, path, dpi)


def fig_sigma(path, runs, dpi=110):
    """Figs. 6 / 9: sigma_1 and sigma_2 against the time since the tilt to
    theta, one panel per run (name, series of avalanche.read_series, theta;
    sigma_runs reads them), the last stay at theta of each series."""
    ncols = int(np.ceil(np.sqrt(len(runs))))
    nrows = int(np.ceil(len(runs) / ncols))
    with plt.rc_context(READABLE):
        fig, axes = plt.subplots(nrows, ncols, figsize=(5.6 * ncols, 4.2 * nrows), squeeze=False)
        for ax in axes.flat[len(runs):]:
            ax.set_visible(False)
        for ax, (name, s, theta) in zip(axes.flat, runs):
            parts = [(t, idx) for th, t, idx in av.angle_samples(s) if abs(th - theta) < 1e-6]
            if not parts:
                raise ValueError(f"{name}: no samples at theta = {theta}")
            t, idx = parts[-1]
            ax.semilogy(t, s["sigma1"][idx], color="tab:blue", label=r"$\sigma_1$ (top)")
            ax.semilogy(t, s["sigma2"][idx], color="tab:red", label=r"$\sigma_2$ (bottom)")
            ax.axhline(av.EPS_SIGMA1, color="tab:blue", ls="--", lw=1)
            ax.axhline(av.EPS_SIGMA2, color="tab:red", ls="-", lw=1)
            ax.set_ylim(0.05, 100)
            ax.set_xlabel("time since the tilt (s)")
            ax.set_ylabel(r"$\sigma_l$")
            ax.set_title(f"{name}: $\\theta$ = {theta:g}°", fontsize=11)
            ax.legend(fontsize=11)
        fig.tight_layout()
    return _save(fig, path, dpi)


# paper 000's colours (its Figs. 7 and 8): blue without, orange with 70 kHz
COLOUR = {0: "tab:blue", 70: "tab:orange"}
MARKERS = ("o", "s", "^", "D")  # the angles of a ramp, in increasing order
READABLE = {"font.size": 13, "axes.labelsize": 14, "axes.titlesize": 14, "legend.fontsize": 11.5,
            "xtick.labelsize": 12, "ytick.labelsize": 12}


def fig_thetam(path, table, label="this code", free=None, free_label="free ends", couplings=(), dpi=110,
               coupling=None):
    """Fig. 7 from a table of ensembles: rows "H/d theta0 sd0 theta70 sd70
    [paper0 paper70]" (means and standard deviations over the packings, nan
    where missing; paper0/70: values paper 000 states in its text), named
    label, its 70 kHz points at the coupling `coupling` (a text, e.g.
    "kappa_scale 0.3"), blue at 0 kHz and orange at 70 kHz as in the
    paper.  free: a second geometry (named free_label) in the same format,
    drawn with open squares; couplings: (rows "H/d theta70 sd70", name) of
    theta_m at 70 kHz at other couplings, drawn with open diamonds.  Paper
    000's values at 6, 8.7 and 11.4 d are not stated in its text: the
    dashed lines are a straight line through its 20 deg (3 d) and 17 deg
    (14.4 d), and the same 2 deg lower, labelled as interpolated."""
    t = np.atleast_2d(np.asarray(table, float))
    at = f", {coupling}" if coupling else ""
    with plt.rc_context(READABLE):
        fig, ax = plt.subplots(figsize=(13.0, 9.0))
        sets = [(t, "o-", None, label)]
        if free is not None:
            sets.append((np.atleast_2d(np.asarray(free, float)), "s:", "none", free_label))
        for rows, fmt, fill, name in sets:
            for col, c, frequency in ((1, COLOUR[0], "0 kHz (no ultrasound)"), (3, COLOUR[70], f"70 kHz{at}")):
                ok = np.isfinite(rows[:, col])
                if ok.any():
                    ax.errorbar(rows[ok, col], rows[ok, 0], xerr=np.nan_to_num(rows[ok, col + 1]), fmt=fmt, color=c,
                                capsize=4, ms=8, lw=2,
                                label=f"{frequency}, {name} (mean ± s.d.)", **({"mfc": fill} if fill else {}))
        for k, (rows, name) in enumerate(couplings):
            c = np.atleast_2d(np.asarray(rows, float))
            ax.errorbar(c[:, 1], c[:, 0], xerr=np.nan_to_num(c[:, 2]), fmt="D", mfc="none", mew=2, ms=10,
                        color=("tab:red", "tab:green", "tab:purple")[k % 3], capsize=4,
                        label=f"70 kHz, {name} (mean ± s.d.)")
        h = np.linspace(3, 14.4, 2)
        line = 20 + (17 - 20) * (h - 3) / (14.4 - 3)
        ax.plot(line, h, "--", color=COLOUR[0], lw=1.2,
                label="paper 000, 0 kHz: interpolated, a straight line through its 20° (3 d) and 17° (14.4 d)")
        ax.plot(line - 2, h, "--", color=COLOUR[70], lw=1.2,
                label="paper 000, 70 kHz: the same line 2° lower (its text: \"about 2° lower\"), interpolated")
        if t.shape[1] >= 7:
            for col, frequency in ((5, 0), (6, 70)):
                ok = np.isfinite(t[:, col])
                nominal = [min((3, 6, 8.7, 11.4, 14.4), key=lambda n: abs(n - h)) for h in t[ok, 0]]
                values = ", ".join(f"{v:g}° at {h:g} d" for v, h in zip(t[ok, col], nominal))
                ax.plot(t[ok, col], t[ok, 0], "s", mfc="none", mew=2, color=COLOUR[frequency], ms=12,
                        label=f"paper 000, {frequency} kHz, stated in its text ({values})")
        ax.set_xlabel(r"avalanche angle $\theta_m$ (°)")
        ax.set_ylabel("layer thickness H/d (measured)")
        ax.set_title("Fig. 7: avalanche angle against layer thickness, without and with 70 kHz ultrasound")
        ax.grid(alpha=0.3)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=1, frameon=False)   # below: no point hidden
        fig.tight_layout()
        return _save(fig, path, dpi)


def kappa_means(kappas, shifts):
    """Rows (kappa, mean shift, standard error, number of ramps), one per
    distinct kappa in increasing order; the standard error is s.d./sqrt(n)
    with n - 1 degrees of freedom (0 for a single ramp)."""
    kappas, shifts = np.asarray(kappas, float), np.asarray(shifts, float)
    rows = []
    for x in np.unique(kappas):
        s = shifts[kappas == x]
        se = s.std(ddof=1) / np.sqrt(len(s)) if len(s) > 1 else 0.0
        rows.append((x, s.mean(), se, len(s)))
    return np.array(rows, float).reshape(-1, 4)


def fig_kappa(path, rows, dpi=110):
    """The 70 kHz shift against kappa_scale, from rows (kappa, H, shift,
    mu_factor, onset_shift, geometry) (one per 70 kHz ramp; onset_shift: the
    shift of the first spreading flow; geometry "periodic" or "free_ends"):
    every ramp (filled: theta_m, open: first spreading flow), the mean of
    theta_m's shift at each kappa for each H and geometry with its standard
    error (kappa_means), and paper 000's
    shift of about 2 deg as a band."""
    t = np.array([row[:5] for row in rows], float)
    geometry = np.array([row[5] for row in rows])
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    ax.axhspan(1.5, 2.5, color="0.85", label="paper 000: ≈ 2°")
    ax.axhline(0, color="0.5", lw=0.6)
    groups = sorted({(g, H) for g, H in zip(geometry, t[:, 1])}, key=lambda x: (x[1], x[0]))
    for k, (g, H) in enumerate(groups):
        group = t[(geometry == g) & (t[:, 1] == H)]
        ax.plot(group[:, 0], group[:, 2], "o", color=f"C{k}", alpha=0.6,
                label=f"H = {H:g} d, {g.replace('_', ' ')}, one ramp each")
        ax.plot(group[:, 0], group[:, 4], "o", mfc="none", color=f"C{k}", alpha=0.6,
                label="first spreading flow")
        means = kappa_means(group[:, 0], group[:, 2])
        ax.errorbar(means[:, 0], means[:, 1], yerr=means[:, 2], fmt="-", color=f"C{k}", capsize=4,
                    label="mean ± s.e. over the ramps")
    ax.set_xscale("log")
    ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xticks(np.unique(t[:, 0]))
    ax.set_xlabel("kappa_scale")
    ax.set_ylabel(r"$\theta_m$(0 kHz) $-$ $\theta_m$(70 kHz) (°)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    return _save(fig, path, dpi)


def _tcon_label(label):
    """(H/d, kHz) of a Fig. 8 row label "H<H>_<f>kHz..." or "paper000_H<H>_<f>kHz"."""
    import re
    m = re.search(r"H([0-9.]+)_([0-9.]+)kHz", label)
    if m is None:
        raise ValueError(f"fig_tcon: a label must hold H<H/d>_<f>kHz, got {label}")
    return float(m.group(1)), float(m.group(2))


def fig_tcon(path, rows, dpi=110, coupling=None):
    """Fig. 8 from rows (label, theta, t_con[, kind]), one per run, label
    "H<H/d>_<f>kHz[...]" (several packings give several points per label
    and angle): one panel per H/d, blue at 0 kHz and orange at 70 kHz as in
    paper 000, with its symbols: stars at theta_m (kind "thetam": the
    ramp's own flow), filled squares at the angles above it (kind "run",
    the default), the mean over packings at each angle as a line.  Labels
    starting with "paper" are values paper 000 states in its text, drawn
    as large open circles; coupling: the text of the 70 kHz runs'
    coupling (e.g. "kappa_scale 0.3"), said in the legend."""
    rows = [tuple(r) + (("run",) if len(r) == 3 else ()) for r in rows]
    heights = sorted({_tcon_label(r[0])[0] for r in rows})
    at = f", {coupling}" if coupling else ""
    with plt.rc_context(READABLE):
        # at least as wide as the two-column legend below the panels
        fig, axes = plt.subplots(1, len(heights), figsize=(max(5.2 * len(heights), 12.5), 8.0), sharey=True, squeeze=False)
        for ax, H in zip(axes[0], heights):
            for frequency in (0.0, 70.0):
                c = COLOUR[int(frequency)]
                mine = [r for r in rows if _tcon_label(r[0]) == (H, frequency) and not r[0].startswith("paper")]
                words = "0 kHz" if frequency == 0 else f"70 kHz{at}"
                for kind, marker, size, name in (("thetam", "*", 16, "at θ_m (stars)"),
                                                 ("run", "s", 8, "above θ_m (filled squares)")):
                    pts = np.array([[r[1], r[2]] for r in mine if r[3] == kind], float).reshape(-1, 2)
                    if len(pts):
                        ax.plot(pts[:, 0], pts[:, 1], marker, color=c, ms=size, alpha=0.85, mec="k", mew=0.5,
                                label=f"{words}, {name}")
                pts = np.array([[r[1], r[2]] for r in mine], float).reshape(-1, 2)
                if len(pts):
                    angles = np.unique(pts[:, 0])
                    ax.plot(angles, [pts[pts[:, 0] == th, 1].mean() for th in angles], "-", color=c, lw=1.5,
                            label=f"{'0 kHz' if frequency == 0 else '70 kHz'}, mean over packings")
                for r in rows:
                    if r[0].startswith("paper") and _tcon_label(r[0]) == (H, frequency):
                        ax.plot(r[1], r[2], "o", mfc="none", mec=c, mew=3, ms=18,
                                label=f"paper 000, {frequency:g} kHz: {r[2]:g} s at {r[1]:g}° (stated in its text)")
            ax.set_title(f"H = {H:g} d")
            ax.set_xlabel(r"slope angle $\theta$ (°)")
            ax.grid(alpha=0.3)
        axes[0][0].set_ylabel(r"time to a uniform flow $t_{con}$ (s)")
        legend = {}
        for ax in axes[0]:                    # one legend for the panels, below them: no point hidden
            for handle, text in zip(*ax.get_legend_handles_labels()):
                legend.setdefault(text, handle)
        fig.suptitle("Fig. 8: time from the tilt to a uniform flow, without (blue) and with (orange) 70 kHz")
        fig.tight_layout(rect=(0, 0.2, 1, 1))
        fig.legend(legend.values(), legend.keys(), loc="lower center", ncol=2, frameon=False,
                   bbox_to_anchor=(0.5, 0.0))
        return _save(fig, path, dpi)


def fig_chains(path, atoms, c, dpi=110):
    """Fig. 10: the force chains of a dump frame (atoms) from its contacts
    (c, named columns): line width proportional to f_n, colour 1 - mu*/mu,
    the grains as disks; x periodic (nearest image)."""
    x, y = atoms["x"], atoms["y"]
    lx = atoms.box[0, 1] - atoms.box[0, 0]
    segs, width, colour = [], [], []
    fmax = c["fn"].max() if len(c) else 1.0
    for p, q, fn, s in zip(av.rows_of(atoms, c["i"]), av.rows_of(atoms, c["j"]), c["fn"], c["mu_ratio"]):
        dx = x[q] - x[p]
        dx -= lx * np.round(dx / lx)            # nearest periodic image
        segs.append([(x[p], y[p]), (x[p] + dx, y[q])])
        width.append(0.3 + 3.0 * fn / fmax)
        colour.append(1.0 - s)
    d = 2 * np.mean(atoms["radius"])
    fig, ax = plt.subplots(figsize=(10, 10 * (np.ptp(y) + 2 * d) / (lx + 2 * d) + 1.2))
    from matplotlib.patches import Circle
    from matplotlib.collections import PatchCollection
    disks = PatchCollection([Circle((xx, yy), r) for xx, yy, r in zip(x, y, atoms["radius"])],
                            facecolor="0.92", edgecolor="0.75", linewidth=0.3)
    ax.add_collection(disks)
    lc = LineCollection(segs, linewidths=width, cmap="viridis", array=np.array(colour))
    lc.set_clim(0, 1)
    ax.add_collection(lc)
    ax.set_xlim(atoms.box[0, 0], atoms.box[0, 1])
    ax.set_ylim(y.min() - d, y.max() + d)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    cb = fig.colorbar(lc, ax=ax, orientation="horizontal", fraction=0.08, pad=0.02)
    cb.set_label(r"$1 - \mu^*/\mu$ (line width $\propto f_n$)")
    ax.set_title(f"timestep {atoms.timestep}: {len(c)} contacts, mean $\\mu^*/\\mu$ = "
                 f"{np.mean(c['mu_ratio']):.3f}", fontsize=9)
    return _save(fig, path, dpi)


def _ramp_count(count):
    """'4 packings' when every frequency has the same number of ramps,
    else '4 packings at 0 kHz, 2 at 70 kHz' or '4 packings at 0 kHz, none
    at 70 kHz' (count: frequency name -> ramps)."""
    numbers = list(count.values())
    if len(set(numbers)) == 1:
        return f"{numbers[0]} packing{'s' if numbers[0] != 1 else ''}"
    parts = [f"{n or 'none'} at {name}" for name, n in count.items()]
    return parts[0].replace(" at", " packings at", 1) + ", " + ", ".join(parts[1:])


def fig_percolation(path, rows, coupling="", dpi=110):
    """Paper 000's Fig. 11: how far the moving zones spread at each slope,
    with and without ultrasound: the largest fraction of the observed grains
    that move (|v| > vmob) at each tested angle of each ramp, one panel per
    H/d, one line per packing and frequency; rows (H, packing, f (kHz),
    angle, fraction, state) (avalanche_collect.percolation_rows), a star at
    the uniform flow (theta_m)."""
    heights = sorted({r[0] for r in rows})
    ncols = min(3, len(heights))
    nrows = -(-len(heights) // ncols)
    with plt.rc_context(READABLE):
        fig, axes = plt.subplots(nrows, ncols, figsize=(6.0 * ncols + 0.5, 4.8 * nrows), squeeze=False)
        panels = axes.ravel()
        for ax, H in zip(panels, heights):
            mine = [r for r in rows if r[0] == H]
            packings = sorted({r[1] for r in mine}, key=int)
            count = {}
            for f, marker, name in ((0.0, "o", "0 kHz"), (70.0, "s", "70 kHz")):
                drawn = 0
                for seed in packings:
                    line = sorted((r[3], r[4], r[5]) for r in mine if r[1] == seed and r[2] == f)
                    if not line:
                        continue
                    theta, frac, state = zip(*line)
                    ax.plot(theta, frac, marker=marker, ms=5, lw=1.2, color=COLOUR[int(f)], alpha=0.85,
                            label=name if drawn == 0 else None)
                    drawn += 1
                    for t, v, st in line:
                        if st == "uniform":
                            ax.plot(t, v, "*", ms=15, color=COLOUR[int(f)], mec="k", mew=0.6)
                count[name] = drawn
            ax.set_ylim(0, 1.02)
            ax.set_xlabel(r"slope angle $\theta$ (°)")
            ax.set_title(f"H = {H:g} d ({_ramp_count(count)})")
            ax.grid(alpha=0.3)
        for row in axes:
            row[0].set_ylabel("largest fraction of grains\nmoving at the angle")
        panels[0].plot([], [], "*", ms=13, color="0.5", mec="k", label=r"uniform flow ($\theta_m$)")
        spare = panels[len(heights):]
        for ax in spare:
            ax.axis("off")
        if len(spare):        # the legend in the empty panel of the grid, clear of the data
            spare[0].legend(*panels[0].get_legend_handles_labels(), loc="center", fontsize="large")
        else:
            panels[0].legend(loc="upper left")
        fig.suptitle("Moving zones against the slope, without and with 70 kHz" + (f": {coupling}" if coupling else ""))
        fig.tight_layout()
    return _save(fig, path, dpi)


def fig_fields(path, runs, dpi=100):
    """Paper 000's Figs. 6 and 9: for each run (title, the fields of one
    angle: avalanche_fields.angle_fields) a column of the grains' speed over
    the observation window at the kept times since the tilt (0 to 1.2 s;
    cells of the window, log colour scale shared by all runs) above
    sigma_1 and sigma_2 against time with the uniform-flow criteria."""
    from .avalanche_fields import as_array
    from matplotlib.colors import LogNorm
    n = max(len(f["snapshots"]) for _, f in runs)
    speeds = np.concatenate([as_array(snap["speed"]).ravel() for _, f in runs for snap in f["snapshots"]])
    speeds = speeds[np.isfinite(speeds) & (speeds > 0)]
    norm = LogNorm(vmin=max(np.percentile(speeds, 1), 1e-6) if len(speeds) else 1e-5,
                   vmax=max(speeds.max(), 1e-5) if len(speeds) else 1e-2)
    with plt.rc_context(READABLE):
        fig, axes = plt.subplots(n + 1, len(runs), figsize=(6.2 * len(runs), 0.95 * n + 4.2), squeeze=False,
                                 gridspec_kw={"height_ratios": [1] * n + [4.0]})
        image = None
        for col, (title, f) in enumerate(runs):
            x0, x1 = f["window_d"]
            for row in range(n):
                ax = axes[row][col]
                ax.set_xticks([])
                ax.set_yticks([])
                if row >= len(f["snapshots"]):
                    ax.axis("off")
                    continue
                snap = f["snapshots"][row]
                field = as_array(snap["speed"])
                image = ax.imshow(np.where(field > 0, field, np.nan), origin="lower", aspect="auto", norm=norm,
                                  cmap="viridis", extent=(x0, x1, 0, field.shape[0] * f["cell_d"][1]))
                ax.set_ylabel(f"{snap['t']:.1f} s", rotation=0, ha="right", va="center", fontsize=11)
            axes[0][col].set_title(title, fontsize=12)
            ax = axes[n][col]
            t = np.array(f["sigma_t"])
            ax.semilogy(t, as_array(f["sigma1"]), color="tab:blue", label=r"$\sigma_1$ (top half)")
            ax.semilogy(t, as_array(f["sigma2"]), color="tab:red", label=r"$\sigma_2$ (bottom half)")
            ax.axhline(av.EPS_SIGMA1, color="tab:blue", ls="--", lw=1)
            ax.axhline(av.EPS_SIGMA2, color="tab:red", ls="--", lw=1)
            ax.set_xlim(0, 1.3)
            ax.set_ylim(0.05, 100)
            ax.set_xlabel("time since the tilt (s)")
            ax.legend(loc="upper right", fontsize=10)
        axes[n][0].set_ylabel(r"$\sigma_l$ (dashed: criteria)")
        if image is not None:
            bar = fig.colorbar(image, ax=axes[:n, :].ravel().tolist(), orientation="vertical", fraction=0.02,
                               pad=0.01)
            bar.set_label("grain speed (m/s), cells of the observation window")
    return _save(fig, path, dpi)


def fig_front(path, runs, times=(0.2, 0.4), dpi=100):
    """Paper 000's Fig. 14 (c, d) as profiles: the grains' mean speed in
    columns along the whole layer (back at the left, front at the right),
    divided by its mean over the layer, at the kept times nearest `times`
    (s since the tilt to theta_m), one panel each; runs: (label, frequency
    (kHz), the fields of that angle).  A flow led by its ends has still
    columns between them; a uniform one is flat."""
    from .avalanche_fields import as_array
    with plt.rc_context(READABLE):
        fig, axes = plt.subplots(len(times), 1, figsize=(16, 4.6 * len(times)), squeeze=False, sharex=True)
        for ax, t in zip(axes[:, 0], times):
            for label, f_khz, f in runs:
                snap = min(f["snapshots"], key=lambda s: abs(s["t"] - t))
                x = np.array(snap["column_x"])
                speed = as_array(snap["columns"])
                ratio = speed / np.nanmean(speed)
                ax.plot(x - x.min(), ratio, "-o", ms=3.5, color=COLOUR.get(int(f_khz), "0.4"),
                        label=f"{label},\nt = {snap['t']:.2f} s: {100 * np.mean(ratio > 0.1):.0f} % of the "
                              "columns above 0.1")
            ax.axhline(1.0, color="0.6", lw=0.8)
            ax.axhline(0.1, color="0.6", lw=0.8, ls=":")
            ax.set_yscale("log")
            ax.set_ylabel("mean speed / layer mean")
            ax.set_title(f"{t:g} s after the tilt to $\\theta_m$", fontsize=13)
            # beside the panel: inside, a profile with a deep dip ran under it
            ax.legend(fontsize=10.5, loc="center left", bbox_to_anchor=(1.01, 0.5), frameon=False)
            ax.grid(alpha=0.3)
        axes[-1][0].set_xlabel("distance from the back of the layer (d), 10 d columns; the front is at the right")
        fig.tight_layout()
    return _save(fig, path, dpi)


def fig_spread(path, runs, dpi=100):
    """How a flow covers the observation window, layer against layer: the
    fraction of the window's grains faster than v_mob (top row; more than
    50 % for 10 ms is one condition of the uniform flow) and sigma_1 of
    Eq. 3.1 (bottom row; below 0.3 the other) against the time since the
    tilt, at the last followed angles up to theta_m, one column per
    frequency; runs: (layer length (d), frequency (kHz), the fields of the
    ramp (avalanche_fields)), drawn solid for the longest layer and dashed
    for the others, darker the steeper the angle (markers in MARKERS'
    order); sigma_1 shown between 0.2 and 100."""
    longest = max(layer for layer, _, _ in runs)
    frequencies = sorted({f_khz for _, f_khz, _ in runs})
    with plt.rc_context(READABLE):
        fig, axes = plt.subplots(2, len(frequencies), figsize=(7.2 * len(frequencies), 11.0), squeeze=False,
                                 sharex=True)
        for col, f_khz in enumerate(frequencies):
            for layer, _, fields in sorted((r for r in runs if r[1] == f_khz), key=lambda r: -r[0]):
                angles = sorted(fields["angles"], key=lambda a: a["theta"])
                window = np.diff(angles[0]["window_d"])[0] if angles else 0.0
                for k, a in enumerate(angles):
                    t = a["sigma_t"]
                    shade = 0.25 + 0.75 * (k + 1) / len(angles)
                    style = dict(color=COLOUR.get(int(f_khz), "0.4"), alpha=shade, marker=MARKERS[k % len(MARKERS)],
                                 markevery=max(1, len(t) // 8), ms=6,
                                 ls="-" if layer == longest else "--", lw=2.2 if layer == longest else 1.6)
                    theta_m = " (θ_m)" if fields["theta_m"] is not None and \
                        abs(a["theta"] - fields["theta_m"]) < 1e-6 else ""
                    axes[0][col].plot(t, a["mobile"], label=f"{layer:g} d layer, {window:.0f} d window, "
                                      f"{a['theta']:g}°{theta_m}", **style)
                    axes[1][col].plot(t, a["sigma1"], **style)
            axes[0][col].axhline(0.5, color="0.5", lw=0.8, ls=":")
            axes[1][col].axhline(0.3, color="0.5", lw=0.8, ls=":")
            axes[0][col].set_title(f"{f_khz:g} kHz")
            axes[0][col].set_ylim(0.0, 1.02)
            axes[1][col].set_yscale("log")
            axes[1][col].set_ylim(0.2, 100.0)  # sigma_1 of a layer at rest spikes far above: not the question
            axes[1][col].legend(*axes[0][col].get_legend_handles_labels(), fontsize=10.5, ncol=2,
                                loc="upper center", bbox_to_anchor=(0.5, -0.16), frameon=False)
            axes[1][col].set_xlabel("time since the tilt (s)")
            axes[0][col].grid(alpha=0.3)
            axes[1][col].grid(alpha=0.3)
        axes[0][0].set_ylabel("fraction of the window's grains\nfaster than $v_{mob}$ (uniform: > 0.5)")
        axes[1][0].set_ylabel("$\\sigma_1$ of Eq. 3.1 (uniform: < 0.3)")
        fig.tight_layout()
    return _save(fig, path, dpi)


def _segments(grains, contacts):
    """The contacts between two grains of a snapshot (avalanche_snapshots)
    as line segments, with their f_n and mu*/mu (wall contacts dropped)."""
    index = {int(t): k for k, t in enumerate(grains["id"])}
    keep = [k for k, (i, j) in enumerate(zip(contacts["i"], contacts["j"])) if int(i) in index and int(j) in index]
    x, y = grains["x"], grains["y"]
    segments = [[(x[index[int(contacts["i"][k])]], y[index[int(contacts["i"][k])]]),
                 (x[index[int(contacts["j"][k])]], y[index[int(contacts["j"][k])]])] for k in keep]
    return segments, contacts["fn"][keep], contacts["mu_ratio"][keep]


def _disks(ax, grains, d):
    """The grains of a snapshot as light disks, lengths in d."""
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Circle
    ax.add_collection(PatchCollection([Circle((x / d, y / d), r / d) for x, y, r in
                                       zip(grains["x"], grains["y"], grains["radius"])],
                                      facecolor="0.93", edgecolor="0.78", linewidth=0.3))


def snapshot_panels(axes, snap, arrow_floor=1e-3):
    """The three panels of one snapshot (paper 000's Fig. 10 a-c): the force
    chains on a linear scale (line width proportional to f_n), the
    vibration-induced displacements q = (U0 q)/U0 as arrows (their
    direction; colour |q|/U0 on a log scale from arrow_floor), the force chains on a logarithmic
    scale coloured by the friction reduction 1 - mu*/mu (0: unchanged, blue;
    1: friction gone, red).  Lengths in d from the window's left end.
    Returns the two colour mappables (|q|, 1 - mu*/mu)."""
    g, d = snap["grains"], snap["d"]
    x0 = snap["window"][0]
    shifted = dict(g, x=g["x"] - x0)
    segments, fn, ratio = _segments(shifted, snap["contacts"])
    segments = [[(a / d, b / d) for a, b in seg] for seg in segments]
    fmax = fn.max() if len(fn) else 1.0
    y0 = (g["y"] - g["radius"]).min() / d
    for ax in axes:
        _disks(ax, shifted, d)
        ax.set_xlim(0, (snap["window"][1] - x0) / d)
        ax.set_ylim(y0 - 0.5, (g["y"] + g["radius"]).max() / d + 0.5)
        ax.set_aspect("equal")
        ax.set_ylabel("y / d")
    axes[0].add_collection(LineCollection(segments, linewidths=0.2 + 3.5 * fn / fmax, colors="k"))
    q = np.hypot(g["qx"], g["qy"]) / snap["U0"]
    moving = (g["type"] == 1) & (q > 0)
    # arrows of one length (0.8 d: the direction), coloured by |q|/U0 on a
    # log scale: the response falls by decades away from the driven grains
    from matplotlib.colors import LogNorm
    unit = 0.8 / np.maximum(q[moving], 1e-300)
    arrows = axes[1].quiver(shifted["x"][moving] / d, g["y"][moving] / d, g["qx"][moving] / snap["U0"] * unit,
                            g["qy"][moving] / snap["U0"] * unit, q[moving], cmap="viridis", angles="xy",
                            scale_units="xy", scale=1.0, width=0.0025, pivot="middle",
                            norm=LogNorm(vmin=arrow_floor, vmax=max(1.0, q[moving].max() if moving.any() else 1.0)))
    fpos = fn[fn > 0]
    lo = np.log10(fpos.min()) if len(fpos) else 0.0
    hi = np.log10(fmax) if len(fpos) else 1.0
    widths = 0.3 + 2.5 * (np.log10(np.maximum(fn, 10 ** lo)) - lo) / max(hi - lo, 1e-12)
    chains = LineCollection(segments, linewidths=widths, cmap="coolwarm", array=1.0 - ratio)
    chains.set_clim(0, 1)
    axes[2].add_collection(chains)
    return arrows, chains


def fig_snapshots(path, snaps, titles, dpi=110):
    """Paper 000's Figs. 10, 12, 13: one row per snapshot (its title in
    titles), three panels per row (snapshot_panels); one colour bar for |q|
    per row and one for 1 - mu*/mu."""
    rows = len(snaps)
    g0, d0 = snaps[0]["grains"], snaps[0]["d"]
    aspect = ((g0["y"] + g0["radius"]).max() - (g0["y"] - g0["radius"]).min() + d0) / (
        snaps[0]["window"][1] - snaps[0]["window"][0])
    with plt.rc_context(READABLE):
        fig = plt.figure(figsize=(21, rows * (7 * aspect + 2.2)), layout="constrained")
        for sub, snap, title in zip(np.atleast_1d(fig.subfigures(rows, 1)), snaps, titles):
            axes = sub.subplots(1, 3)
            arrows, chains = snapshot_panels(axes, snap)
            sub.suptitle(title, fontsize=14)
            axes[0].set_title("force chains (line width $\\propto f_n$)", fontsize=12)
            axes[1].set_title("vibration-induced displacement $q/U_0$ (arrows: direction only)", fontsize=12)
            axes[2].set_title(r"force chains (log $f_n$), colour $(\mu_p - \mu^*)/\mu_p$", fontsize=12)
            sub.colorbar(arrows, ax=axes[1], orientation="horizontal", fraction=0.08, pad=0.04,
                         label=r"$|q|/U_0$ (log scale)")
            sub.colorbar(chains, ax=axes[2], orientation="horizontal", fraction=0.08, pad=0.04,
                         label=r"friction reduction $1 - \mu^*/\mu$")
            for ax in axes:
                ax.set_xlabel("x / d (a window at the layer's middle)")
    return _save(fig, path, dpi)


def fig_calibration(path, results, dpi=110):
    """The calibration scan (the results of
    avalanche_calibration.calibration_scan, `examples/avalanche/study.py calibrate`'s
    JSON file): the fraction of contacts with mu*/mu < 0.5 against each
    scanned parameter for both sources, the sound speed and the highest mode
    against kappa_scale."""
    labels = {"U0": "$U_0/d$", "kappa": "kappa_scale", "cmu": r"$C_\mu$", "zeta": r"damping ratio $\zeta$"}
    fig, axes = plt.subplots(2, 3, figsize=(12, 7))
    for ax, name in zip(axes.flat, ("U0", "kappa", "cmu", "zeta")):
        for source, style in (("bottom", "o-"), ("base", "s--")):
            rows = results["scans"].get(f"{source}:{name}", [])
            ax.plot([r["value"] for r in rows], [r["fraction_below_half"] for r in rows], style,
                    label={"bottom": "grains on the base, normal (paper 000)", "base": "rough base"}[source])
        ax.axvline(results["reference"][name], color="0.6", lw=0.8)
        if name in ("U0", "kappa"):
            ax.set_xscale("log")
        ax.set_xlabel(labels[name])
        ax.set_ylabel(r"fraction of contacts with $\mu^*/\mu < 0.5$")
        ax.set_ylim(0.0, 1.0)
    axes.flat[0].legend(fontsize=8)
    rows = results["spectrum_and_speed"]
    kappa = [r["kappa"] for r in rows]
    ax = axes.flat[4]
    ax.loglog(kappa, [r["speed"] for r in rows], "o-", label="time-of-flight speed (m/s)")
    ax.axhline(10.0, color="C3", lw=0.8, label="paper 000: c = 10 m/s")
    ax.set_xlabel("kappa_scale")
    ax.legend(fontsize=8)
    ax = axes.flat[5]
    ax.loglog(kappa, [r["highest_mode"] / 1e3 for r in rows], "o-", label="highest mode (kHz)")
    ax.axhline(results["freq"] / 1e3, color="C3", lw=0.8, label="drive")
    ax.axhline(75.0, color="0.5", ls=":", lw=0.8, label="paper 000 Fig. 3: 75 kHz")
    ax.set_xlabel("kappa_scale")
    ax.legend(fontsize=8)
    fig.tight_layout()
    return _save(fig, path, dpi)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)
    m = sub.add_parser("modes")
    m.add_argument("dump", nargs="?")
    m.add_argument("contacts", nargs="?")
    m.add_argument("--hist", help="histogram file of compute vibration/modes (fix ave/time mode vector)")
    m.add_argument("--frame", type=int, default=0)
    m.add_argument("--f0", type=float, default=70e3)
    m.add_argument("--bins", type=int, default=60)
    s = sub.add_parser("sigma")
    s.add_argument("series", nargs="+")
    s.add_argument("--theta", type=float, action="append", required=True)
    t = sub.add_parser("thetam")
    t.add_argument("table")
    t.add_argument("--label", default="this code")
    t.add_argument("--free", help="a second table (free ends), drawn with open squares")
    t.add_argument("--free-label", default="free ends")
    t.add_argument("--coupling", nargs=2, action="append", metavar=("TABLE", "LABEL"),
                   help="theta_m at 70 kHz at another coupling (lines H/d theta70 sd70), open diamonds")
    t.add_argument("--coupling-of-70", help="the coupling of the table's 70 kHz points, said in the legend")
    c = sub.add_parser("tcon")
    c.add_argument("table")
    c.add_argument("--coupling", help="the coupling of the 70 kHz runs, said in the legend")
    kap = sub.add_parser("kappa")
    kap.add_argument("table")
    ch = sub.add_parser("chains")
    ch.add_argument("dump")
    ch.add_argument("contacts")
    ch.add_argument("--frame", type=int, default=-1)
    cal = sub.add_parser("calibration")
    cal.add_argument("results")
    for q in (m, s, t, c, kap, ch, cal):
        q.add_argument("-o", "--output", required=True)
        q.add_argument("--dpi", type=int, default=110)
    a = p.parse_args(argv)
    if a.cmd == "modes":
        if not a.hist and not (a.dump and a.contacts):
            sys.exit("modes: give --hist FILE and/or DUMP CONTACTS")
        fig_modes(a.output, read_ave_time_vector(a.hist)[-1][1] if a.hist else None,       # last block
                  os.path.basename(a.hist) if a.hist else "",
                  _frames(a.dump, a.contacts, a.frame) if a.dump and a.contacts else None, a.f0, a.bins, a.dpi)
    elif a.cmd == "sigma":
        if len(a.theta) != len(a.series):
            sys.exit("give one --theta per series file")
        try:
            fig_sigma(a.output, sigma_runs(a.series, a.theta), a.dpi)
        except ValueError as e:
            sys.exit(str(e))
    elif a.cmd == "thetam":
        fig_thetam(a.output, np.loadtxt(a.table), a.label, np.loadtxt(a.free) if a.free else None, a.free_label,
                   [(np.loadtxt(table), name) for table, name in a.coupling or []], a.dpi, a.coupling_of_70)
    elif a.cmd == "tcon":
        rows = [line.split() for line in open(a.table) if line.strip() and not line.startswith("#")]
        fig_tcon(a.output, [(r[0], float(r[1]), float(r[2])) + tuple(r[3:4]) for r in rows], a.dpi, a.coupling)
    elif a.cmd == "kappa":
        rows = [line.split() for line in open(a.table) if line.strip() and not line.startswith("#")]
        fig_kappa(a.output, [tuple(float(r[k]) for k in (0, 1, 3, 4, 5)) + (r[6],) for r in rows], a.dpi)
    elif a.cmd == "chains":
        fig_chains(a.output, *_frames(a.dump, a.contacts, a.frame), a.dpi)
    else:
        with open(a.results) as handle:
            fig_calibration(a.output, json.load(handle), a.dpi)
    return 0


if __name__ == "__main__":
    sys.exit(main())
