#!/usr/bin/python3
"""Collect the production runs (out/prod, run_production.sh) into tables and figures.

    /usr/bin/python3 examples/avalanche/collect.py [PROD_DIR] [FIG_DIR]

Prints a markdown table of theta_m(H/d) and t_con for 0 and 70 kHz beside paper
000's values, and writes figures/fig3_modes_H*.png, fig6_9_sigma_H*.png,
fig7_thetam.png, fig8_tcon.png, fig10_chains_H*.png (small PNGs).
"""
import glob
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
import numpy as np  # noqa: E402

import avalanche as av  # noqa: E402
import avalanche_figures as figs  # noqa: E402

# paper 000, section 3.2 text: H = 3 d: 20 deg without, 14.5 deg with 70 kHz;
# H = 14.4 d: theta_m = 17 deg without vibration (Fig. 6); the other values are
# only drawn in Fig. 7 ("about 2 deg lower with 70 kHz").
PAPER = {3.0: (20.0, 14.5), 14.4: (17.0, np.nan)}

RESULT = re.compile(r"theta_m = ([0-9.]+|none) deg\s+t_con = ([-0-9.]+) s")


def result(log):
    if not os.path.exists(log):
        return np.nan, np.nan
    for line in open(log):
        m = RESULT.search(line)
        if m:
            tm = float(m.group(1)) if m.group(1) != "none" else np.nan
            return tm, float(m.group(2)) if np.isfinite(tm) else np.nan
    return np.nan, np.nan


def deposit(log):
    for line in open(log):
        if line.startswith("deposit:"):
            n = re.search(r"(\d+) grains on (\d+) base", line)
            h = re.search(r"H = ([0-9.]+) d", line)
            return int(n.group(1)), int(n.group(2)), float(h.group(1))
    return 0, 0, np.nan


def loop_time(log):
    return sum(float(l.split()[3]) for l in open(log) if l.startswith("Loop time of"))


def main(prod=os.path.join(here, "out", "prod"), figdir=os.path.join(here, "figures")):
    os.makedirs(figdir, exist_ok=True)
    rows, tcon_rows = [], []
    for d in sorted(glob.glob(os.path.join(prod, "H*")), key=lambda p: float(p.split("/H")[-1])):
        H = float(d.split("/H")[-1])
        if not os.path.exists(os.path.join(d, "log.deposit")):
            continue
        n, nb, hm = deposit(os.path.join(d, "log.deposit"))
        r0, r70 = result(os.path.join(d, "log.f0")), result(os.path.join(d, "log.f70"))
        t0 = loop_time(os.path.join(d, "log.f0")) if os.path.exists(os.path.join(d, "log.f0")) else np.nan
        t70 = loop_time(os.path.join(d, "log.f70")) if os.path.exists(os.path.join(d, "log.f70")) else np.nan
        rows.append((H, hm, n, nb, r0, r70, t0, t70))
        for tag, label in (("f0", "0 kHz"), ("f70", "70 kHz")):
            if np.isfinite(result(os.path.join(d, f"log.{tag}"))[0]):
                tm, tc = result(os.path.join(d, f"log.{tag}"))
                tcon_rows.append((f"H{H:g}_{label.replace(' ', '')}", tm, tc))
            for log in sorted(glob.glob(os.path.join(d, f"log.tcon_{tag}_*"))):
                tm, tc = result(log)
                if np.isfinite(tm):
                    tcon_rows.append((f"H{H:g}_{label.replace(' ', '')}", tm, tc))
        # per-H figures: spectrum and chains of the 70 kHz run at its last frame, sigma curves
        dump, cont = os.path.join(d, "f70.dump"), os.path.join(d, "f70.contacts")
        if os.path.exists(dump) and os.path.exists(cont):
            hist = os.path.join(d, f"modes_H{H:g}.hist")     # compute vibration/modes (in.modes), if run
            figs.main(["modes", dump, cont, "--frame", "0", "-o", os.path.join(figdir, f"fig3_modes_H{H:g}.png"),
                       "--dpi", "80"] + (["--hist", hist] if os.path.exists(hist) else []))
            # the last frame below theta_m: the static layer under ultrasound (Fig. 10)
            frames = av.read_dump(dump)
            below = [i for i, fr in enumerate(frames) if fr["v_th"][0] < (r70[0] if np.isfinite(r70[0]) else 90) - 1e-6]
            k = below[-1] if below else len(frames) - 1
            figs.main(["chains", dump, cont, "--frame", str(k), "-o", os.path.join(figdir, f"fig10_chains_H{H:g}.png"), "--dpi", "80"])
        sers = [(os.path.join(d, f"{tag}.series"), r[0]) for tag, r in (("f0", r0), ("f70", r70)) if np.isfinite(r[0])]
        if sers:
            args = ["sigma"] + [s for s, _ in sers]
            for _, th in sers:
                args += ["--theta", f"{th:g}"]
            figs.main(args + ["-o", os.path.join(figdir, f"fig6_9_sigma_H{H:g}.png"), "--dpi", "80"])
    table7 = os.path.join(prod, "thetam.txt")
    with open(table7, "w") as f:
        for H, hm, n, nb, r0, r70, *_ in rows:
            p = PAPER.get(H, (np.nan, np.nan))
            f.write(f"{H:g} {r0[0]:g} {r70[0]:g} {p[0]:g} {p[1]:g}\n")
    figs.main(["thetam", table7, "-o", os.path.join(figdir, "fig7_thetam.png"), "--dpi", "80"])
    if tcon_rows:
        table8 = os.path.join(prod, "tcon.txt")
        with open(table8, "w") as f:
            for label, tm, tc in tcon_rows:
                f.write(f"{label} {tm:g} {tc:g}\n")
        figs.main(["tcon", table8, "-o", os.path.join(figdir, "fig8_tcon.png"), "--dpi", "80"])
    print("| H/d (target) | H/d (measured) | grains + base | θ_m 0 kHz | θ_m 70 kHz | shift | t_con 0 / 70 kHz at θ_m | paper 000 θ_m 0 / 70 kHz | DEM time (s) 0 / 70 kHz |")
    print("|---|---|---|---|---|---|---|---|---|")
    for H, hm, n, nb, r0, r70, t0, t70 in rows:
        p = PAPER.get(H)
        ptxt = (f"{p[0]:g} / {p[1]:g}" if p and np.isfinite(p[1]) else f"{p[0]:g} / —" if p else "Fig. 7 only") \
            + " (≈ 2° lower with 70 kHz)"
        print(f"| {H:g} | {hm:.2f} | {n} + {nb} | {r0[0]:g}° | {r70[0]:g}° | {r0[0] - r70[0]:g}° | "
              f"{r0[1]:.3f} s / {r70[1]:.3f} s | {ptxt} | {t0:.0f} / {t70:.0f} |")
    for label, tm, tc in tcon_rows:
        print(f"t_con {label} theta {tm:g}: {tc:.3f} s")


if __name__ == "__main__":
    main(*sys.argv[1:])
