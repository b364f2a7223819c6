"""Collect the cavity runs of examples/cavity/study.py run (OUT/<set>/<name>/:
sets scan, paper, size, us; each with job.json (set, name, the deck's
variables, tag), the result.json that in.cavity writes at its end (the run's
parameters, wall_seconds) and the recordings TAG.wall.txt, TAG.contacts,
TAG.flow, TAG.us.txt) into the tables and figures of its RESULTS.md
(acoustic_tools.cavity_study is the command line).

  analyse, read_runs, block_error   the measurements of each run (cavity)
  scan_fit                          the Eq. 4 fit of the scan set
  print_tables                      the markdown tables on stdout
  figures                           the figures (cavity_figures)
  collect, draw                     what study.py collect and study.py figures do
"""
import json
import os

import numpy as np

from . import cavity, lammps_output, study
from . import cavity_figures as figs


def block_error(series, blocks=20):
    """Standard error of the mean of a correlated series from the scatter of
    the means of `blocks` consecutive blocks"""
    n = len(series) // blocks
    means = np.asarray(series[:n * blocks], float).reshape(blocks, n).mean(axis=1)
    return float(means.std(ddof=1) / np.sqrt(blocks))


def analyse(run, settings, p):
    """The measurements of one finished run in directory run (settings: its
    job.json, p: its result.json): (the row of summary.json: I_M, F/(PLd)
    and its block error, ell/L, Phi*, the correlation times, the Eq. 7 fits
    at the three scales, ..., the data of the figures: the wall force and
    its portions, the contact forces, the autocorrelations, the mean
    velocity field)."""
    tag = settings.get("tag", "cavity")
    wall = lammps_output.read_ave_time(os.path.join(run, f"{tag}.wall.txt"))
    F = wall["F"]
    portions = np.column_stack([wall[f"F_{i}"] for i in range(1, 11)])
    PLd = p["P"] * p["L"] * p["d"]
    dt_rec = p["nevery"] * p["dt"]
    period = p["d"] / p["U"]                      # passing period of the lid's roughness
    max_lag = min(len(F) // 4, int(round(20 * period / dt_rec)))
    C = cavity.autocorrelation(F, max_lag)
    C_portions = np.array([cavity.autocorrelation(portions[:, i], max_lag) for i in range(10)])
    dtc_portions, dtc_mean = cavity.portion_correlation_times(portions, dt_rec, max_lag)
    r = {"run": f"{settings['set']}/{settings['name']}", "I_M": p["I_M"], "NP": p["NP"],
         "NU": p["NU"], "Hd": p["Hd"], "freq": p["freq"], "grains": int(p["grains"]), "records": len(F),
         "recorded_HU": (p["nshear"] - p["nskip"]) * p["dt"] * p["U"] / p["H"],
         "recorded_s": (p["nshear"] - p["nskip"]) * p["dt"], "wall_s": p["wall_seconds"],
         "Fnorm": float(F.mean() / PLd), "Fnorm_sem": block_error(F) / PLd,
         "phi3d": float(cavity.volume_fraction_3d(wall["phi2d"].mean())), "h_over_H": float(wall["h"].mean() / p["H"]),
         "dtc_wall": float(cavity.correlation_time(C, dt_rec)), "dtc_portions": dtc_portions.tolist(),
         "dtc_mean": float(dtc_mean), "period": period, "dt_rec": dt_rec,
         "cv_wall": float(F.std() / F.mean())}
    skew = np.mean((F - F.mean()) ** 3) / F.std() ** 3
    r["skew_wall"] = float(skew)
    # vortex centre from the velocity field after tskip
    flow = os.path.join(run, f"{tag}.flow")
    if os.path.exists(flow):
        cols, counts = cavity.time_average_chunks(lammps_output.read_ave_chunk(flow), first_step=p["nskip"])
        inside = (counts > 0) & (cols["Coord1"] > 0) & (cols["Coord1"] < p["L"]) & (cols["Coord2"] > 0)
        vx = np.where(inside, cols["vx"], np.nan)
        vy = np.where(inside, cols["vy"], np.nan)
        try:
            xv, yv, ell = cavity.vortex_centre(cols["Coord1"], cols["Coord2"], vx, vy, p["L"])
            r["ell_over_L"], centre = float(ell), (xv, yv)
        except (ValueError, IndexError):
            r["ell_over_L"], centre = np.nan, None
        field = (cols["Coord1"], cols["Coord2"], vx, vy, p["L"], centre)
    # three scales of force: samples for the PDFs and Eq. 7 fits
    snaps = lammps_output.read_dump(os.path.join(run, f"{tag}.contacts"))
    f = np.concatenate([s["v_fwall"] for s in snaps if len(s)])
    f = f[f > 0]
    r["contacts_per_record"] = float(len(f) / max(1, len(snaps)))
    samples = {"particle": f, "wall": F, "meso": portions[:, 2:9]}
    for scale, v in samples.items():
        v = np.asarray(v, float)
        if v.ndim == 2:                       # portions: each by its own mean, the untouched ones left out
            v = v[:, v.mean(axis=0) > 0]
            scaled = (v / v.mean(axis=0)).ravel()
        else:
            scaled = v / v.mean()
        try:
            r[f"fit_{scale}"] = [float(x) for x in cavity.fit_trunc_lognormal(scaled)]
        except ValueError:
            r[f"fit_{scale}"] = [np.nan] * 3
    us = os.path.join(run, f"{tag}.us.txt")
    if os.path.exists(us):
        u = lammps_output.read_ave_time(us)
        r["mu_ratio"] = float(u["mu_ratio_mean"].mean())
        r["frac_below_half"] = float(u["frac_below_half"].mean())
    return r, {"F": F, "portions": portions, "f": f, "C": C, "C_portions": C_portions, "dt_rec": dt_rec,
               "field": field if os.path.exists(flow) else None}


def read_runs(top):
    """analyse of every finished run of top (its sets' directories
    top/<set>/, each holding one directory per run): {"<set>/<name>": (row,
    data)}, the set and the name from each run's job.json"""
    runs = {}
    for set_name in sorted(os.listdir(top)) if os.path.isdir(top) else []:
        for run, settings, result in study.finished_jobs(os.path.join(top, set_name)):
            if settings.get("kind") == "cavity":
                runs[f"{settings['set']}/{settings['name']}"] = analyse(run, settings, result)
    return runs


def g(x, digits=3):
    """x to `digits` significant digits, a dash when missing or not finite"""
    return "—" if x is None or not np.isfinite(x) else f"{x:.{digits}g}"


def print_tables(runs, fit):
    """The markdown table of every run, the Eq. 4 fit of the scan (fit:
    scan_fit's) and the table of the ultrasound set (us/<base>_f0 beside
    us/<base>_f70): the text (each line as print writes it)."""
    lines = []

    def print(*parts):
        lines.append(" ".join(str(part) for part in parts) + "\n")
    print("| run | H/d | N_P | N_U | I_M | grains | recorded (H/U; s) | F/(PLd) | ℓ/L | Φ* | ⟨Δt_c⟩ (d/U) | Δt_c wall (d/U) "
          "| CV, skewness of F | Eq. 7 wall μ, σ, f0 | wall time (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, (r, _) in sorted(runs.items(), key=lambda kv: (kv[0].split("/")[0], kv[1][0]["I_M"])):
        fw = r["fit_wall"]
        print(f"| {name} | {r['Hd']:g} | {r['NP']:g} | {r['NU']:g} | {r['I_M']:.3g} | {r['grains']} "
              f"| {r['recorded_HU']:.0f}; {r['recorded_s']:.3g} | {r['Fnorm']:.3f} ± {r['Fnorm_sem']:.3f} | {g(r.get('ell_over_L'), 2)} "
              f"| {r['phi3d']:.3f} | {g(r['dtc_mean'] / r['period'], 2)} | {g(r['dtc_wall'] / r['period'], 2)} "
              f"| {r['cv_wall']:.2f}, {r['skew_wall']:.2f} | {fw[0]:.2f}, {fw[1]:.2f}, {fw[2]:.2g} | {r['wall_s']:.0f} |")
    if fit is not None:
        (r1, r2, i0), (e1, e2, ei), chi2 = fit
        print(f"\nEq. 4 fit of the scan (weighted by the block errors, errors scaled by sqrt(chi2/dof) = "
              f"{np.sqrt(chi2):.2f}): r1 = {r1:.3f} ± {e1:.3f}, r2 = {r2:.3f} ± {e2:.3f}, "
              f"I0 = {i0:.4f} ± {ei:.4f} (paper 004: 0.53, 0.86, 0.02)")
    us = {n: r for n, (r, _) in runs.items() if n.startswith("us/")}
    if us:
        print("\n| I_M | F/(PLd) 0 / 70 kHz | ℓ/L 0 / 70 kHz | ⟨Δt_c⟩ (d/U) 0 / 70 kHz | CV of F 0 / 70 kHz "
              "| Eq. 7 wall (μ, σ, f0) 0 / 70 kHz | mean μ*/μ, fraction < 0.5 at 70 kHz |")
        print("|---|---|---|---|---|---|---|")
        for base in sorted({n.rsplit("_f", 1)[0] for n in us}, key=lambda b: us.get(b + "_f0", {}).get("I_M", 0)):
            a, b = us.get(base + "_f0"), us.get(base + "_f70")
            if not a or not b:
                continue
            fa, fb = a["fit_wall"], b["fit_wall"]
            print(f"| {a['I_M']:.3g} | {a['Fnorm']:.3f} ± {a['Fnorm_sem']:.3f} / {b['Fnorm']:.3f} ± {b['Fnorm_sem']:.3f} | {g(a.get('ell_over_L'), 2)} / "
                  f"{g(b.get('ell_over_L'), 2)} | {g(a['dtc_mean'] / a['period'], 2)} / {g(b['dtc_mean'] / b['period'], 2)} "
                  f"| {a['cv_wall']:.2f} / {b['cv_wall']:.2f} | {fa[0]:.2f}, {fa[1]:.2f}, {fa[2]:.2g} / "
                  f"{fb[0]:.2f}, {fb[1]:.2f}, {fb[2]:.2g} | {b.get('mu_ratio', np.nan):.3f}, "
                  f"{b.get('frac_below_half', np.nan):.3f} |")
    return "".join(lines)


def figures(runs, fit, figdir):
    """Paper 004's Figs. 2, 3, 9, 10, 12, 13, 14 and Phi*(I_M) of the scan
    set (cavity_figures) into figdir; fit: scan_fit's, drawn in Fig. 3."""
    os.makedirs(figdir, exist_ok=True)
    scan = {n: v for n, v in runs.items() if n.startswith("scan/")}
    if not scan:
        return
    order = sorted(scan, key=lambda n: scan[n][0]["I_M"])
    IM = np.array([scan[n][0]["I_M"] for n in order])
    figs.fig3_vortex_and_force(IM, [scan[n][0].get("ell_over_L", np.nan) for n in order],
                               [scan[n][0]["Fnorm"] for n in order], os.path.join(figdir, "fig3_force_vortex.png"),
                               fit=None if fit is None else fit[0], title="H/d = 10, L/H = 5")
    for n in (order[0], order[len(order) // 2], order[-1]):
        r, data = scan[n]
        if data["field"] is not None:
            xc, yc, vx, vy, L, centre = data["field"]
            figs.fig2_streamlines(xc, yc, vx, vy, L, os.path.join(figdir, f"fig2_streamlines_{os.path.basename(n)}.png"),
                                  centre=centre, title=f"$I_M$ = {r['I_M']:.2g}, $\\ell/L$ = {r['ell_over_L']:.2f}")
        figs.fig9_autocorrelation(data["dt_rec"] / r["period"], data["C_portions"],
                                  os.path.join(figdir, f"fig9_autocorrelation_{os.path.basename(n)}.png"),
                                  title=f"$I_M$ = {r['I_M']:.2g} (lag in d/U)")
    figs.fig10_correlation_times(IM, [np.array(scan[n][0]["dtc_portions"]) / scan[n][0]["period"] for n in order],
                                 os.path.join(figdir, "fig10_correlation_times.png"), title="(in units of d/U)")
    figs.fig12_particle_pdfs({scan[n][0]["I_M"]: scan[n][1]["f"] for n in order},
                             os.path.join(figdir, "fig12_particle_pdfs.png"))
    figs.fig13_wall_pdfs({scan[n][0]["I_M"]: scan[n][1]["F"] for n in order},
                         os.path.join(figdir, "fig13_wall_pdfs.png"))
    mid = order[len(order) // 2]
    figs.fig14_meso_pdfs(scan[mid][1]["portions"], {scan[n][0]["I_M"]: scan[n][1]["portions"] for n in order},
                         os.path.join(figdir, "fig14_meso_pdfs.png"), title=f"(a) at $I_M$ = {scan[mid][0]['I_M']:.2g}")
    figs.fig_volume_fraction(IM, [scan[n][0]["phi3d"] for n in order], os.path.join(figdir, "phi_IM.png"))


def scan_fit(runs):
    """The Eq. 4 fit of F/(PLd) against I_M over the scan set (four runs or
    more; None otherwise), weighted by the block errors: (parameters r1, r2,
    I0, their errors scaled by sqrt(chi2/dof) when above 1, chi2/dof)."""
    scan = [r for n, (r, _) in runs.items() if n.startswith("scan/")]
    if len(scan) >= 4:
        I = np.array([r["I_M"] for r in scan])
        Fn = np.array([r["Fnorm"] for r in scan])
        sem = np.array([r["Fnorm_sem"] for r in scan])
        params, errors = cavity.fit_mean_force(I, Fn, sigma=sem)
        # the packings scatter more than the block errors say: errors scaled by sqrt(chi2/dof)
        chi2 = float(np.sum(((Fn - cavity.mean_force_model(I, *params)) / sem) ** 2) / max(1, len(I) - 3))
        return params, tuple(e * max(1.0, np.sqrt(chi2)) for e in errors), chi2
    return None


def collect(top):
    """What study.py collect does: the tables on stdout and in top/tables.md,
    summary.json (every run's row, the Eq. 4 fit) into top."""
    runs = read_runs(top)
    fit = scan_fit(runs)
    text = print_tables(runs, fit)
    print(text, end="")
    with open(os.path.join(top, "tables.md"), "w") as handle:
        handle.write(text)
    with open(os.path.join(top, "summary.json"), "w") as f:
        json.dump({"runs": {n: r for n, (r, _) in runs.items()},
                   "eq4_fit": None if fit is None else [list(map(float, fit[0])), list(map(float, fit[1])), fit[2]]},
                  f, indent=1, default=float)


def draw(top, figdir):
    """What study.py figures does: the figures of the runs of top into figdir"""
    runs = read_runs(top)
    figures(runs, scan_fit(runs), figdir)
