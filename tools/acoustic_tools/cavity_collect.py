"""Collect the cavity runs of examples/cavity/study.py run (OUT/<set>/<name>/:
sets scan, paper, size, us; each with job.json (set, name, the deck's
variables, tag), the result.json that in.cavity writes at its end (the run's
parameters, wall_seconds) and the recordings TAG.wall.txt, TAG.contacts,
TAG.flow, TAG.us.txt) into the tables and figures of its RESULTS.md
(acoustic_tools.cavity_study is the command line).

  record, recorded_run              a run without its recordings (row.json)
  analyse, read_runs, block_error   the measurements of each run (cavity):
                                    F/(PLd), ell/L, <Delta t_c> in s and in
                                    d/U, the zero records per scale, Eq. 7
                                    with the zeros apart, the stationarity
                                    (first half against second half), the
                                    local mu(I) from TAG.stress
  scan_fit, eq5_fit, mu_I_fit       Eq. 4 over a scan, Eq. 5, Eq. 20
  by_im                             mean and standard error over the runs of
                                    one I_M (packings and (N_U, N_P) pairs)
  print_tables                      the markdown tables on stdout
  figures                           the figures (cavity_figures)
  collect, draw                     what study.py collect and study.py figures do

The H/d = 10 study (sets scan, paper, size, us) and paper 004's cavity of
issue 43 (sets h30, h30seeds: the scan and its packings; h30sens; h30us)
are collected side by side.
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
    r = {"run": f"{settings['set']}/{settings['name']}", "set": settings["set"], "I_M": p["I_M"], "NP": p["NP"],
         "seed": settings.get("seed", 1), "walls": p.get("walls", "smooth"), "LH": p.get("LH", 5),
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
    # the memory in seconds and in d/U (the passing period of the lid's roughness)
    r["dtc_mean_s"], r["dtc_mean_dU"] = r["dtc_mean"], r["dtc_mean"] / period
    r["dtc_wall_s"], r["dtc_wall_dU"] = r["dtc_wall"], r["dtc_wall"] / period
    # stationarity: the first half of every record against the second
    st = cavity.stationarity(F)
    stp = cavity.stationarity(portions)
    r["stationarity"] = {"F_z": st["z"], "F_rel": st["rel"], "F_cv1": st["cv1"], "F_cv2": st["cv2"],
                         "portions_max_abs_z": float(np.nanmax(np.abs(stp["z"][np.isfinite(stp["z"])]))
                                                     if np.isfinite(stp["z"]).any() else np.nan),
                         "portions_z": [float(z) for z in stp["z"]]}
    # vortex centre from the velocity field after tskip
    flow = os.path.join(run, f"{tag}.flow")
    if os.path.exists(flow):
        cols, counts = cavity.time_average_chunks(lammps_output.read_ave_chunk(flow), first_step=p["nskip"] + 1)
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
    nonempty = [s["v_fwall"] for s in snaps if len(s)]
    f_all = np.concatenate(nonempty) if nonempty else np.zeros(0)
    f = f_all[f_all > 0]
    r["contacts_per_record"] = float(len(f) / max(1, len(snaps)))
    # the meso scale of paper 004: portions of 3 d (its H/10 at H/d = 30):
    # the deck's 10 portions at H/d = 30, else round(H/3d) portions from the
    # contacts' heights; the central ones (3..9 of 10, cavity.central_portions)
    if int(round(p["Hd"])) == 30:
        meso = portions
    else:
        ybot = 0.5 * p["d"]
        _, meso = cavity.portion_force_series(snaps, ybot, ybot + wall["h"], n=max(1, int(round(p["Hd"] / 3))))
    central = list(range(2, 9)) if meso.shape[1] == 10 else cavity.central_portions(meso.shape[1])
    r["meso_portions"], r["meso_size_d"] = int(meso.shape[1]), float(p["Hd"] / meso.shape[1])
    # zero records per scale: records of the whole wall with F = 0, of a
    # central portion with F_i = 0, snapshots with no grain on the wall,
    # contacts with f = 0
    r["zeros"] = {"wall": cavity.zero_fraction(F), "meso": cavity.zero_fraction(meso[:, central]),
                  "particle_records": float(1 - len(nonempty) / max(1, len(snaps))),
                  "particle_contacts": cavity.zero_fraction(f_all)}
    # Eq. 7 at each scale fitted to what the histograms show: the records
    # scaled by the mean of all of them, the zeros a mass p0 at 0, Eq. 7 on
    # the positive ones (cavity.fit_eq7_with_zeros); the meso scale pools
    # the central portions, each scaled by its own mean
    meso_scaled = []
    for i in central:
        column = meso[:, i]
        if column.mean() > 0:
            meso_scaled.append(column / column.mean())
    samples = {"particle": f_all, "wall": F,
               "meso": np.concatenate(meso_scaled) if meso_scaled else np.zeros(0)}
    for scale, v in samples.items():
        fit = cavity.fit_eq7_with_zeros(v)
        r[f"eq7_{scale}"] = fit
        r[f"fit_{scale}"] = [fit["mu"], fit["sigma"], fit["f0"]]
    high = _modes(run)
    r["highest_mode"] = np.nan if high is None else high
    # where the drive falls in the network's spectrum (TAG.modes.hist, dense or kpm)
    r["modes_below_drive"], r["band_top"] = np.nan, np.nan
    hist = os.path.join(run, f"{tag}.modes.hist")
    if os.path.exists(hist) and p["freq"] > 0:
        try:
            r["modes_below_drive"], r["band_top"] = cavity.spectrum_position(*cavity.read_modes_histogram(hist), p["freq"])
        except ValueError:
            pass
    us = os.path.join(run, f"{tag}.us.txt")
    if os.path.exists(us):
        u = lammps_output.read_ave_time(us)
        r["mu_ratio"] = float(u["mu_ratio_mean"].mean())
        r["frac_below_half"] = float(u["frac_below_half"].mean())
    # the local rheology (Eqs. 16-20) from the stress and velocity fields
    rheology = None
    stress = os.path.join(run, f"{tag}.stress")
    if os.path.exists(stress):
        try:
            rheology = local_rheology(stress, p, wall["h"].mean())
            r["mu_I_points"] = int(np.isfinite(rheology["region"][1]).sum())
        except ValueError:
            rheology = None
    return r, {"F": F, "portions": portions, "meso": meso, "central": central, "f": f_all, "C": C,
               "C_portions": C_portions, "dt_rec": dt_rec, "period": period,
               "field": field if os.path.exists(flow) else None, "rheology": rheology}


def local_rheology(path, p, h):
    """The local mu(I) of one run from its TAG.stress (blocks after nskip,
    averaged: the fields of the time-averaged stress and velocity, smoothed
    by paper 004's kernel, App. A): {"x", "y", "I", "mu" (grids), "region":
    (I, mu) of paper 004 Fig. 19's region (the upper half of the packing, a
    band L/2 wide centred in x), "stress", "rate"}"""
    blocks = lammps_output.read_ave_chunk(path)
    cols = cavity.mean_blocks(blocks, first_step=p["nskip"])
    x, y, *fields = cavity.stress_and_velocity_fields(cols, p["d"] * p["d"], p["d"])
    # paper 004 App. A: a Gaussian kernel of standard deviation d/2 on the mesh of d
    sxx, syy, sxy, vx, vy = (cavity.smooth_field(f, 0.5) for f in fields)
    Dxx, Dyy, Dxy = cavity.strain_rate_2d(x, y, vx, vy)
    rho_p = 2500.0
    I, mu = cavity.local_rheology(sxx, syy, sxy, Dxx, Dyy, Dxy, p["d"], rho_p)
    X, Y = np.meshgrid(x, y)
    L = p["L"]
    region = (X > 0.25 * L) & (X < 0.75 * L) & (Y > 0.5 * h) & (Y < h - p["d"])
    return {"x": x, "y": y, "I": I, "mu": mu, "region": (I[region], mu[region]), "h": h, "L": L,
            "stress": (sxx, syy, sxy), "rate": (Dxx, Dyy, Dxy)}


ROW, REGION = "row.json", "region.json"      # what the record keeps of a run besides job.json, result.json


def record_run(run, settings, result, dest):
    """A finished run as the record keeps it, without its recordings (tens
    of MB at H/d = 30): dest/job.json, result.json, row.json (analyse's
    row: every number of the tables) and, with a stress field,
    region.json (the (I, mu) points of Fig. 19's region, for Eq. 20)."""
    row, data = analyse(run, settings, result)
    study.write_job(dest, settings)
    study.write_result(dest, result)
    with open(os.path.join(dest, ROW), "w") as handle:
        json.dump(row, handle, indent=1, default=float)
        handle.write("\n")
    if data.get("rheology"):
        I, mu = data["rheology"]["region"]
        with open(os.path.join(dest, REGION), "w") as handle:
            json.dump({"I": [float(v) for v in I], "mu": [float(v) for v in mu]}, handle)
            handle.write("\n")


def record(top, dest):
    """record_run of every finished run of top into dest/<set>/<name>/;
    returns the number of runs written"""
    written = 0
    for set_name in sorted(os.listdir(top)) if os.path.isdir(top) else []:
        for run, settings, result in study.finished_jobs(os.path.join(top, set_name)):
            if settings.get("kind") == "cavity" and os.path.exists(os.path.join(run, f"{settings.get('tag', 'cavity')}"
                                                                                        ".wall.txt")):
                record_run(run, settings, result, os.path.join(dest, set_name, os.path.basename(run)))
                written += 1
    return written


def recorded_run(run):
    """(row, data) of a recorded run (record_run): the row as analyse gave
    it; of the data only the rheology's region (no recordings: no figure
    but Eq. 20 draws from it)"""
    with open(os.path.join(run, ROW)) as handle:
        row = json.load(handle)
    data = {"rheology": None, "recorded": True}
    if os.path.exists(os.path.join(run, REGION)):
        with open(os.path.join(run, REGION)) as handle:
            region = json.load(handle)
        data["rheology"] = {"region": (np.array(region["I"], float), np.array(region["mu"], float))}
    return row, data


def read_runs(top):
    """analyse of every finished run of top (its sets' directories
    top/<set>/, each holding one directory per run), or its recorded row
    where the recordings are not there (a record: recorded_run): {"<set>/<name>":
    (row, data)}, the set and the name from each run's job.json"""
    runs = {}
    for set_name in sorted(os.listdir(top)) if os.path.isdir(top) else []:
        for run, settings, result in study.finished_jobs(os.path.join(top, set_name)):
            if settings.get("kind") != "cavity":
                continue
            raw = os.path.exists(os.path.join(run, f"{settings.get('tag', 'cavity')}.wall.txt"))
            if raw or not os.path.exists(os.path.join(run, ROW)):
                runs[f"{settings['set']}/{settings['name']}"] = analyse(run, settings, result)
            else:
                runs[f"{settings['set']}/{settings['name']}"] = recorded_run(run)
    return runs


def g(x, digits=3):
    """x to `digits` significant digits, a dash when missing or not finite"""
    return "—" if x is None or not np.isfinite(x) else f"{x:.{digits}g}"


# the sets of the H/d = 30 scan (paper 004's cavity): the scan and its packings
H30_SCAN = ("h30/", "h30seeds/")


def _select(runs, prefixes):
    return {n: v for n, v in runs.items() if n.startswith(tuple(prefixes))}


def _mean_sem(values):
    v = np.asarray([x for x in values if x is not None and np.isfinite(x)], float)
    if len(v) == 0:
        return np.nan, np.nan, 0
    return float(v.mean()), float(v.std(ddof=1) / np.sqrt(len(v))) if len(v) > 1 else np.nan, len(v)


def by_im(runs, prefixes=H30_SCAN, digits=2):
    """The runs of the sets prefixes grouped by I_M (to `digits` significant
    digits): {I_M: {quantity: (mean, standard error, runs)}} over packings
    and (N_U, N_P) pairs; quantities Fnorm, ell_over_L, dtc_mean_dU,
    dtc_mean_s, cv_wall, skew_wall, the Eq. 7 parameters of each scale (mu,
    sigma, f0 over the fits short of the Gaussian limit; loc, spread over all;
    "gaussian": how many reached it) and the zero fractions, plus "pairs"
    (the (N_U, N_P)) and "seeds"."""
    groups = {}
    for name, (r, _) in _select(runs, prefixes).items():
        groups.setdefault(float(f"{r['I_M']:.{digits}g}"), []).append(r)
    out = {}
    for im, rows in sorted(groups.items()):
        q = {}
        for key in ("Fnorm", "ell_over_L", "dtc_mean_dU", "dtc_mean_s", "cv_wall", "skew_wall"):
            q[key] = _mean_sem([row.get(key, np.nan) for row in rows])
        for scale in ("wall", "meso", "particle"):
            fits = [row[f"eq7_{scale}"] for row in rows]
            shapes = [cavity.eq7_location_spread(f["mu"], f["sigma"], f["f0"]) for f in fits]
            # mu, sigma, f0 over the fits short of the Gaussian limit, where they are determined
            for k in ("mu", "sigma", "f0"):
                q[f"eq7_{scale}_{k}"] = _mean_sem([f[k] for f, shape in zip(fits, shapes) if not shape[2]])
            q[f"eq7_{scale}_p0"] = _mean_sem([f["p0"] for f in fits])
            q[f"eq7_{scale}_loc"] = _mean_sem([shape[0] for shape in shapes])
            q[f"eq7_{scale}_spread"] = _mean_sem([shape[1] for shape in shapes])
            q[f"eq7_{scale}_gaussian"] = sum(shape[2] for shape in shapes)
        q["pairs"] = sorted({(row["NU"], row["NP"]) for row in rows})
        q["seeds"] = sorted({row.get("seed", 1) for row in rows})
        q["runs"] = len(rows)
        out[im] = q
    return out


US_QUANTITIES = ("Fnorm", "dtc_mean_dU", "cv_wall", "skew_wall")


def us_effects(runs, prefix="h30us/", quantities=US_QUANTITIES):
    """The effect of the drive in the ultrasound set: for each (N_U, f > 0),
    the differences x(f, seed) - x(0, seed) of each quantity over the
    packings (seeds) that ran both (the same deposit: paired), their mean
    and standard error: {(NU, freq): {quantity: (mean, sem, n)}}; also the
    spread sd(f) of the wall-scale Eq. 7 fit ("eq7_wall_spread": unlike
    sigma it stays determined at Eq. 7's Gaussian limit) and where the drive
    falls in the spectrum ("modes_below_drive", mean over the driven runs)"""
    table = {}
    for name, (r, _) in runs.items():
        if name.startswith(prefix):
            table[(r["NU"], r["freq"], r.get("seed", 1))] = r
    out = {}
    for (NU, freq, seed), r in sorted(table.items()):
        if freq == 0:
            continue
        base = table.get((NU, 0.0, seed)) or table.get((NU, 0, seed))
        entry = out.setdefault((NU, freq), {"_diffs": {}, "_below": []})
        entry["_below"].append(r.get("modes_below_drive", np.nan))
        if base is None:
            continue
        for q in quantities + ("eq7_wall_spread",):
            a = r["eq7_wall"]["spread"] if q == "eq7_wall_spread" else r.get(q, np.nan)
            b = base["eq7_wall"]["spread"] if q == "eq7_wall_spread" else base.get(q, np.nan)
            entry["_diffs"].setdefault(q, []).append(a - b)
    result = {}
    for key, entry in out.items():
        row = {q: _mean_sem(v) for q, v in entry["_diffs"].items()}
        row["modes_below_drive"] = _mean_sem(entry["_below"])
        row["I_M"] = next(r["I_M"] for (NU, f, _), r in table.items() if (NU, f) == key)
        result[key] = row
    return result


def e7(fit):
    """Eq. 7's parameters of a fit_eq7_with_zeros dict as the tables print
    them: "mu, sigma, f0", or at the Gaussian limit (f0 above 100 mean
    forces, cavity.eq7_location_spread) the location and spread, which stay
    determined there"""
    loc, spread, limit = cavity.eq7_location_spread(fit["mu"], fit["sigma"], fit["f0"])
    if limit:
        return f"Gaussian limit: location {loc:.2f}, spread {spread:.2f}"
    return f"{g(fit['mu'], 2)}, {g(fit['sigma'], 2)}, {g(fit['f0'], 2)}"


def _pm(value, digits=3):
    mean, sem, n = value
    if not np.isfinite(mean):
        return "—"
    return f"{mean:.{digits}g}" + (f" ± {sem:.2g}" if np.isfinite(sem) else "") + ("" if n > 1 else " (1 run)")


def print_tables(runs, fit, fit30=None, eq5=None, mu_fit=None):
    """The markdown tables: every run; the Eq. 4 fits (fit: the H/d = 10
    scan's, fit30: the H/d = 30 scan's, scan_fit's form); Eq. 5 (eq5_fit's);
    the H/d = 30 scan by I_M with errors over packings and pairs; its zero
    records, Eq. 7 with the zeros apart and stationarity per run; the
    sensitivity set; the ultrasound sets; Eq. 20 (mu_fit).  Returns the
    text (each line as print writes it)."""
    lines = []

    def print(*parts):
        lines.append(" ".join(str(part) for part in parts) + "\n")
    print("| run | H/d | N_P | N_U | I_M | grains | recorded (H/U; s) | F/(PLd) | ℓ/L | Φ* | ⟨Δt_c⟩ (d/U; ms) | Δt_c wall (d/U) "
          "| CV, skewness of F | Eq. 7 wall μ, σ, f0 | wall time (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, (r, _) in sorted(runs.items(), key=lambda kv: (kv[0].split("/")[0], kv[1][0]["I_M"], kv[0])):
        print(f"| {name} | {r['Hd']:g} | {r['NP']:g} | {r['NU']:g} | {r['I_M']:.3g} | {r['grains']} "
              f"| {r['recorded_HU']:.0f}; {r['recorded_s']:.3g} | {r['Fnorm']:.3f} ± {r['Fnorm_sem']:.3f} | {g(r.get('ell_over_L'), 2)} "
              f"| {r['phi3d']:.3f} | {g(r['dtc_mean_dU'], 2)}; {g(1e3 * r['dtc_mean_s'], 2)} | {g(r['dtc_wall_dU'], 2)} "
              f"| {r['cv_wall']:.2f}, {r['skew_wall']:.2f} | {e7(r['eq7_wall'])} | {r['wall_s']:.0f} |")
    for label, f in (("the H/d = 10 scan", fit), ("the H/d = 30 scan (sets h30, h30seeds)", fit30)):
        if f is not None:
            (r1, r2, i0), (e1, e2, ei), chi2 = f
            print(f"\nEq. 4 fit of {label} (weighted by the block errors, errors scaled by sqrt(chi2/dof) = "
                  f"{np.sqrt(chi2):.2f}): r1 = {r1:.3f} ± {e1:.3f}, r2 = {r2:.3f} ± {e2:.3f}, "
                  f"I0 = {i0:.4f} ± {ei:.4f} (paper 004: 0.53, 0.86, 0.02)")
    if eq5 is not None:
        (c1, c2), (e1, e2), r2, n = eq5
        print(f"\nEq. 5 fit of the H/d = 30 runs with I_M > 1e-2 ({n} runs): c1 = {c1:.3f} ± {e1:.3f}, "
              f"c2 = {c2:.3f} ± {e2:.3f}, R² = {r2:.2f} (paper 004 Fig. 4: 0.88, 0.5, R² = 0.96)")
    groups = by_im(runs)
    if groups:
        print("\nThe H/d = 30 scan by I_M (mean ± standard error over the packings and (N_U, N_P) pairs; Eq. 7's "
              "μ, σ, f0 over the fits short of its Gaussian limit (f0 above 100 mean forces, where the likelihood "
              "climbs on to f0 → ∞, σ → 0 and they are not determined one by one), its location and spread "
              "(mean and standard deviation of the untruncated law) over all):\n")
        print("| I_M | runs | (N_U, N_P) | seeds | F/(PLd) | ℓ/L | ⟨Δt_c⟩ (d/U) | ⟨Δt_c⟩ (ms) | CV of F | skewness "
              "| Eq. 7 wall μ | σ | f0 | location | spread | at the Gaussian limit | p0 wall | p0 meso |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for im, q in groups.items():
            ms = tuple(1e3 * x if i < 2 else x for i, x in enumerate(q["dtc_mean_s"]))
            print(f"| {im:g} | {q['runs']} | {', '.join(f'({a:g}, {b:.3g})' for a, b in q['pairs'])} "
                  f"| {', '.join(str(x) for x in q['seeds'])} | {_pm(q['Fnorm'])} | {_pm(q['ell_over_L'], 2)} "
                  f"| {_pm(q['dtc_mean_dU'], 2)} | {_pm(ms, 2)} | {_pm(q['cv_wall'], 2)} | {_pm(q['skew_wall'], 2)} "
                  f"| {_pm(q['eq7_wall_mu'], 2)} | {_pm(q['eq7_wall_sigma'], 2)} | {_pm(q['eq7_wall_f0'], 2)} "
                  f"| {_pm(q['eq7_wall_loc'], 2)} | {_pm(q['eq7_wall_spread'], 2)} | {q['eq7_wall_gaussian']} of {q['runs']} "
                  f"| {_pm(q['eq7_wall_p0'], 2)} | {_pm(q['eq7_meso_p0'], 2)} |")
    print("\nZero records, Eq. 7 with the zeros apart (μ, σ, f0 of the positive records scaled by the mean of all; "
          "p0 their fraction) and stationarity (z: the second half's mean minus the first's over its standard "
          "error, for F and the largest |z| of the 10 portions; rel: the relative change of F̄):\n")
    print("| run | meso portions (d) | p0 wall | p0 meso | records without contact | Eq. 7 particle μ, σ, f0 "
          "| Eq. 7 meso μ, σ, f0 | Eq. 7 wall μ, σ, f0 | z F | rel F | max abs z portions |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name, (r, _) in sorted(runs.items(), key=lambda kv: (kv[0].split("/")[0], kv[1][0]["I_M"], kv[0])):
        z, st = r["zeros"], r["stationarity"]
        print(f"| {name} | {r['meso_portions']} ({r['meso_size_d']:.2g}) | {z['wall']:.3f} | {z['meso']:.3f} "
              f"| {z['particle_records']:.3f} | {e7(r['eq7_particle'])} | {e7(r['eq7_meso'])} | {e7(r['eq7_wall'])} "
              f"| {st['F_z']:.1f} | {st['F_rel']:.3f} | {st['portions_max_abs_z']:.1f} |")
    sens = _select(runs, ("h30sens/",))
    if sens:
        print("\nSensitivity (h30sens) beside the h30 run of the same I_M and N_U:\n")
        print("| run | beside | F/(PLd) | ℓ/L | ⟨Δt_c⟩ (d/U) | CV of F | Eq. 7 wall μ, σ, f0 |")
        print("|---|---|---|---|---|---|---|")
        for name, (r, _) in sorted(sens.items()):
            base = next((n for n, (b, _) in runs.items() if n.startswith("h30/") and b["NU"] == r["NU"]
                         and abs(b["NP"] / r["NP"] - 1) < 1e-3), None)
            for label, row in ((name, r), (base, runs[base][0] if base else None)):
                if row is None:
                    continue
                print(f"| {label} | {'' if label != name else (base or '—')} | {row['Fnorm']:.3f} ± {row['Fnorm_sem']:.3f} "
                      f"| {g(row.get('ell_over_L'), 2)} | {g(row['dtc_mean_dU'], 2)} | {row['cv_wall']:.2f} "
                      f"| {e7(row['eq7_wall'])} |")
    us = {n: r for n, (r, _) in runs.items() if n.startswith("us/")}
    if us:
        print("\n| I_M | F/(PLd) 0 / 70 kHz | ℓ/L 0 / 70 kHz | ⟨Δt_c⟩ (d/U) 0 / 70 kHz | CV of F 0 / 70 kHz "
              "| Eq. 7 wall (μ, σ, f0) 0 / 70 kHz | mean μ*/μ, fraction < 0.5 at 70 kHz |")
        print("|---|---|---|---|---|---|---|")
        for base in sorted({n.rsplit("_f", 1)[0] for n in us}, key=lambda b: us.get(b + "_f0", {}).get("I_M", 0)):
            a, b = us.get(base + "_f0"), us.get(base + "_f70")
            if not a or not b:
                continue
            print(f"| {a['I_M']:.3g} | {a['Fnorm']:.3f} ± {a['Fnorm_sem']:.3f} / {b['Fnorm']:.3f} ± {b['Fnorm_sem']:.3f} | {g(a.get('ell_over_L'), 2)} / "
                  f"{g(b.get('ell_over_L'), 2)} | {g(a['dtc_mean_dU'], 2)} / {g(b['dtc_mean_dU'], 2)} "
                  f"| {a['cv_wall']:.2f} / {b['cv_wall']:.2f} | {e7(a['eq7_wall'])} / {e7(b['eq7_wall'])} "
                  f"| {b.get('mu_ratio', np.nan):.3f}, "
                  f"{b.get('frac_below_half', np.nan):.3f} |")
    us30 = _select(runs, ("h30us/",))
    if us30:
        print("\nUltrasound at N_P = 1, H/d = 30 (h30us; mean ± standard error over the packings; the drive "
              "against the network's highest mode at the end of each run):\n")
        print("| N_U | I_M | f (kHz) | runs | F/(PLd) | ⟨Δt_c⟩ (d/U) | CV of F | Eq. 7 wall spread | highest mode (kHz) "
              "| f / highest mode | modes below f | 99.9 % of the modes below (kHz) | mean μ*/μ |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        groups = {}
        for name, (r, _) in us30.items():
            groups.setdefault((r["NU"], r["freq"]), []).append(r)
        for (NU, freq), rows in sorted(groups.items()):
            high = _mean_sem([row.get("highest_mode", np.nan) / 1e3 for row in rows])
            ratio = _mean_sem([freq / row["highest_mode"] if row.get("highest_mode") else np.nan for row in rows])
            print(f"| {NU:g} | {rows[0]['I_M']:.3g} | {freq / 1e3:g} | {len(rows)} | {_pm(_mean_sem([x['Fnorm'] for x in rows]))} "
                  f"| {_pm(_mean_sem([x['dtc_mean_dU'] for x in rows]), 2)} | {_pm(_mean_sem([x['cv_wall'] for x in rows]), 2)} "
                  f"| {_pm(_mean_sem([x['eq7_wall']['spread'] for x in rows]), 2)} | {_pm(high, 3)} "
                  f"| {'—' if freq == 0 else _pm(ratio, 2)} | {_pm(_mean_sem([x['modes_below_drive'] for x in rows]), 3)} "
                  f"| {_pm(_mean_sem([x['band_top'] / 1e3 for x in rows]), 3)} "
                  f"| {_pm(_mean_sem([x.get('mu_ratio', np.nan) for x in rows]), 3)} |")
    effects = us_effects(runs)
    if effects:
        print("\nThe effect of the drive (h30us): the driven run minus the undriven one of the same packing, mean ± "
              "standard error over the packings:\n")
        print("| N_U | I_M | f (kHz) | modes below f | ΔF/(PLd) | Δ⟨Δt_c⟩ (d/U) | ΔCV of F | Δskewness | ΔEq. 7 wall spread |")
        print("|---|---|---|---|---|---|---|---|---|")
        for (NU, freq), q in sorted(effects.items()):
            print(f"| {NU:g} | {q['I_M']:.3g} | {freq / 1e3:g} | {_pm(q['modes_below_drive'], 3)} "
                  f"| {_pm(q.get('Fnorm', (np.nan, np.nan, 0)), 2)} | {_pm(q.get('dtc_mean_dU', (np.nan, np.nan, 0)), 2)} "
                  f"| {_pm(q.get('cv_wall', (np.nan, np.nan, 0)), 2)} | {_pm(q.get('skew_wall', (np.nan, np.nan, 0)), 2)} "
                  f"| {_pm(q.get('eq7_wall_spread', (np.nan, np.nan, 0)), 2)} |")
    if mu_fit is not None:
        print("\n" + eq20_line(mu_fit))
    return "".join(lines)


def eq20_line(mu_fit):
    """The line of the tables for mu_I_fit's ((mu1, mu2, I0), errors, bins), saying so
    when an error is larger than its value (too few bins, or I0 outside their range)"""
    (m1, m2, i0), (e1, e2, ei), n = mu_fit
    loose = not all(np.isfinite(e) and e < abs(v) for v, e in ((m1, e1), (m2, e2), (i0, ei)))
    return (f"Eq. 20 fit of the local μ(I) over the region of Fig. 19 of the runs with a stress field ({n} bins): "
            f"μ1 = {m1:.3f} ± {e1:.3f}, μ2 = {m2:.3f} ± {e2:.3f}, I0 = {i0:.3g} ± {ei:.2g} (paper 004: 0.12, 0.40, 0.13)"
            + ("; not constrained by these bins (an error larger than its value)" if loose else ""))


def figures(runs, fit, figdir, fit30=None, eq5=None, mu_fit=None):
    """Paper 004's figures into figdir: those of the H/d = 10 scan (Figs. 2,
    3, 8, 9, 10, 12, 13, 14, 20, Phi*) and, when there are runs of the
    H/d = 30 scan, the same with the suffix _H30 and Figs. 4, 5, 6, 11, 19"""
    os.makedirs(figdir, exist_ok=True)
    scan = {n: v for n, v in runs.items() if n.startswith("scan/")}
    if scan:
        _scan_figures(scan, fit, figdir, "", "H/d = 10, L/H = 5")
    h30 = _select(runs, H30_SCAN)
    if h30:
        _scan_figures(h30, fit30, figdir, "_H30", "H/d = 30, L/H = 5")
        _h30_figures(h30, figdir, eq5, mu_fit)
    _us_figures(runs, figdir)


def _one_per_im(runs):
    """one run per I_M (2 digits): seed 1 and the largest N_U"""
    best = {}
    for n, (r, d) in runs.items():
        im = float(f"{r['I_M']:.2g}")
        key = (r.get("seed", 1) == 1, r["NU"])
        if im not in best or key > best[im][0]:
            best[im] = (key, n)
    return [best[im][1] for im in sorted(best)]


def _scan_figures(scan, fit, figdir, suffix, title):
    order = sorted(scan, key=lambda n: scan[n][0]["I_M"])
    IM = np.array([scan[n][0]["I_M"] for n in order])
    figs.fig3_vortex_and_force(IM, [scan[n][0].get("ell_over_L", np.nan) for n in order],
                               [scan[n][0]["Fnorm"] for n in order], os.path.join(figdir, f"fig3_force_vortex{suffix}.png"),
                               fit=None if fit is None else fit[0], title=title)
    one = _one_per_im(scan)
    for n in (one[0], one[len(one) // 2], one[-1]):
        r, data = scan[n]
        if data["field"] is not None:
            xc, yc, vx, vy, L, centre = data["field"]
            figs.fig2_streamlines(xc, yc, vx, vy, L, os.path.join(figdir, f"fig2_streamlines_{os.path.basename(n)}.png"),
                                  centre=centre, title=f"$I_M$ = {r['I_M']:.2g}, $\\ell/L$ = {r['ell_over_L']:.2f}")
        figs.fig9_autocorrelation(data["dt_rec"] / r["period"], data["C_portions"],
                                  os.path.join(figdir, f"fig9_autocorrelation_{os.path.basename(n)}.png"),
                                  title=f"$I_M$ = {r['I_M']:.2g} (lag in d/U)")
    figs.fig10_correlation_times(IM, [np.array(scan[n][0]["dtc_portions"]) / scan[n][0]["period"] for n in order],
                                 os.path.join(figdir, f"fig10_correlation_times{suffix}.png"), title="(in units of d/U)")
    figs.fig12_particle_pdfs({scan[n][0]["I_M"]: scan[n][1]["f"] for n in one},
                             os.path.join(figdir, f"fig12_particle_pdfs{suffix}.png"),
                             fits={scan[n][0]["I_M"]: scan[n][0]["eq7_particle"] for n in one})
    figs.fig13_wall_pdfs({scan[n][0]["I_M"]: scan[n][1]["F"] for n in one}, os.path.join(figdir, f"fig13_wall_pdfs{suffix}.png"),
                         fits={scan[n][0]["I_M"]: scan[n][0]["eq7_wall"] for n in one})
    # Fig. 14 (a): the run nearest the paper's I_M = 1.2e-2
    near = min(one, key=lambda n: abs(np.log(scan[n][0]["I_M"] / 1.2e-2)))
    r = scan[near][0]
    figs.fig14_meso_pdfs(scan[near][1]["meso"], {scan[n][0]["I_M"]: scan[n][1]["meso"] for n in one},
                         os.path.join(figdir, f"fig14_meso_pdfs{suffix}.png"),
                         title=f"portions of {r['meso_size_d']:.2g} d; (a) at $I_M$ = {r['I_M']:.2g}")
    figs.fig_volume_fraction(IM, [scan[n][0]["phi3d"] for n in order], os.path.join(figdir, f"phi_IM{suffix}.png"))
    figs.fig20_loglinear({scan[n][0]["I_M"]: scan[n][1]["f"] for n in one}, {scan[n][0]["I_M"]: scan[n][1]["F"] for n in one},
                         os.path.join(figdir, f"fig20_loglinear{suffix}.png"),
                         fits_particle={scan[n][0]["I_M"]: scan[n][0]["eq7_particle"] for n in one},
                         fits_wall={scan[n][0]["I_M"]: scan[n][0]["eq7_wall"] for n in one})
    figs.fig8_autocorrelation({scan[n][0]["I_M"]: (scan[n][1]["dt_rec"], scan[n][1]["C"], scan[n][1]["period"]) for n in one},
                              os.path.join(figdir, f"fig8_autocorrelation{suffix}.png"), title=title)


def _us_figures(runs, figdir):
    effects = us_effects(runs)
    if effects:
        figs.fig_us_effects(effects, os.path.join(figdir, "fig_us_effects_H30.png"))


def _h30_figures(h30, figdir, eq5, mu_fit):
    rows = [r for r, _ in h30.values()]
    figs.fig_memory(rows, by_im(h30), os.path.join(figdir, "fig_memory_H30.png"),
                    title="force memory on the wall portions, H/d = 30")
    figs.fig4_force_vortex([r.get("ell_over_L", np.nan) for r in rows], [r["Fnorm"] for r in rows],
                           [r["I_M"] for r in rows], os.path.join(figdir, "fig4_force_vortex_H30.png"),
                           fit=None if eq5 is None else eq5[0], title="H/d = 30")
    groups = {}
    for n, (r, d) in h30.items():
        groups.setdefault(float(f"{r['I_M']:.2g}"), {}).setdefault((r["NU"], r["NP"]), []).append(d["f"])
    pairs = {im: {k: np.concatenate(v) for k, v in g.items()} for im, g in groups.items() if len(g) > 1}
    if pairs:
        figs.fig11_particle_pairs(pairs, os.path.join(figdir, "fig11_particle_pairs_H30.png"))
    points = {r["I_M"]: d["rheology"]["region"] for r, d in h30.values() if d.get("rheology")}
    if points:
        figs.fig19_mu_I(points, os.path.join(figdir, "fig19_mu_I_H30.png"), fit=None if mu_fit is None else mu_fit[0])
        for target, label in ((1.2e-2, "a"), (6.1e-2, "b")):
            cands = [(abs(np.log(r["I_M"] / target)), n) for n, (r, d) in h30.items() if d.get("rheology")]
            n = min(cands)[1]
            r, d = h30[n]
            rh = d["rheology"]
            figs.fig6_mu_map(rh["x"], rh["y"], rh["I"], rh["mu"], os.path.join(figdir, f"fig6{label}_mu_map_H30.png"),
                             rh["L"], rh["h"], title=f"({label}) $I_M$ = {r['I_M']:.2g}, $N_U$ = {r['NU']:g}, $N_P$ = {r['NP']:.3g}")
            if label == "b":
                figs.fig5_orientations(rh["x"], rh["y"], *rh["stress"], *rh["rate"],
                                       os.path.join(figdir, "fig5_orientations_H30.png"), rh["L"], rh["h"],
                                       title=f"$I_M$ = {r['I_M']:.2g}, $N_U$ = {r['NU']:g}, $N_P$ = {r['NP']:.3g}")


def scan_fit(runs, prefixes=("scan/",)):
    """The Eq. 4 fit of F/(PLd) against I_M over the runs of the sets
    prefixes (four runs or more; None otherwise), weighted by the block
    errors: (parameters r1, r2, I0, their errors scaled by sqrt(chi2/dof)
    when above 1, chi2/dof)."""
    scan = [r for n, (r, _) in runs.items() if n.startswith(tuple(prefixes))]
    if len(scan) >= 4:
        I = np.array([r["I_M"] for r in scan])
        Fn = np.array([r["Fnorm"] for r in scan])
        sem = np.array([r["Fnorm_sem"] for r in scan])
        params, errors = cavity.fit_mean_force(I, Fn, sigma=sem)
        # the packings scatter more than the block errors say: errors scaled by sqrt(chi2/dof)
        chi2 = float(np.sum(((Fn - cavity.mean_force_model(I, *params)) / sem) ** 2) / max(1, len(I) - 3))
        return params, tuple(e * max(1.0, np.sqrt(chi2)) for e in errors), chi2
    return None


def eq5_fit(runs, prefixes=H30_SCAN, above=1e-2):
    """Eq. 5 over the runs of prefixes with I_M > above (paper 004 Fig. 4):
    ((c1, c2), errors, R^2, runs), or None with fewer than 3"""
    rows = [r for n, (r, _) in runs.items() if n.startswith(tuple(prefixes)) and r["I_M"] > above
            and np.isfinite(r.get("ell_over_L", np.nan))]
    if len(rows) < 3:
        return None
    (c1, c2), err, r2 = cavity.fit_eq5([r["ell_over_L"] for r in rows], [r["Fnorm"] for r in rows])
    return (c1, c2), err, r2, len(rows)


def mu_I_fit(runs):
    """Eq. 20 over the region of Fig. 19 of every run with a stress field:
    ((mu1, mu2, I0), errors, bins), or None"""
    I = [d["rheology"]["region"][0] for _, d in runs.values() if d.get("rheology")]
    mu = [d["rheology"]["region"][1] for _, d in runs.values() if d.get("rheology")]
    if not I:
        return None
    I, mu = np.concatenate(I), np.concatenate(mu)
    keep = np.isfinite(I) & np.isfinite(mu) & (I > 0)
    try:
        params, errors = cavity.fit_mu_I(I[keep], mu[keep])
    except (ValueError, RuntimeError):
        return None
    return params, errors, int(keep.sum())


def _modes(run):
    """the network's highest mode (Hz) from the logs of a run's pieces, or None"""
    for name in sorted(os.listdir(run)):
        if name.startswith("log."):
            for line in open(os.path.join(run, name)):
                if line.startswith("cavity modes") and "highest mode" in line:
                    return float(line.split("highest mode")[1].split("Hz")[0])
    return None


def _fits(runs):
    return (scan_fit(runs), scan_fit(runs, H30_SCAN), eq5_fit(runs), mu_I_fit(runs))


def collect(top):
    """What study.py collect does: the tables on stdout and in top/tables.md,
    summary.json (every run's row, the fits) into top."""
    runs = read_runs(top)
    fit, fit30, eq5, mu_fit = _fits(runs)
    text = print_tables(runs, fit, fit30, eq5, mu_fit)
    print(text, end="")
    with open(os.path.join(top, "tables.md"), "w") as handle:
        handle.write(text)

    def listed(f):
        return None if f is None else [list(map(float, f[0])), list(map(float, f[1]))] + list(f[2:])
    with open(os.path.join(top, "summary.json"), "w") as f:
        json.dump({"runs": {n: r for n, (r, _) in runs.items()}, "eq4_fit": listed(fit), "eq4_fit_H30": listed(fit30),
                   "us_effects_H30": {f"nu{NU:g}_f{freq / 1e3:g}": q for (NU, freq), q in us_effects(runs).items()},
                   "eq5_fit_H30": listed(eq5), "eq20_fit": listed(mu_fit),
                   "by_im_H30": {f"{im:g}": {k: (list(v) if isinstance(v, tuple) else v) for k, v in q.items()}
                                 for im, q in by_im(runs).items()}},
                  f, indent=1, default=float)


def draw(top, figdir):
    """What study.py figures does: the figures of the runs of top into
    figdir (the fits over every run; the figures of the runs whose
    recordings are there, not of those known from the record alone)"""
    runs = read_runs(top)
    fit, fit30, eq5, mu_fit = _fits(runs)
    figures({n: v for n, v in runs.items() if not v[1].get("recorded")}, fit, figdir, fit30, eq5, mu_fit)
