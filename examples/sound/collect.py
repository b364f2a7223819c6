"""Collect the runs of run_production.sh (out/p<p>_H<H>_s<seed>/) and of
in.chain (out/chain/) into paper 003's tables and figures:
  out/results.json, out/tables.md, figures/*.png
Usage: /usr/bin/python3 examples/sound/collect.py [OUT_DIR [FIGURE_DIR]]
(3D packings: collect.py out3d figures/3d)"""
import json
import math
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
import sound  # noqa: E402
import sound_figures  # noqa: E402


def samples(out):
    """(p, H, seed) -> directory of every finished sample"""
    found = {}
    for name in sorted(os.listdir(out)):
        match = re.fullmatch(r"p([0-9.e+-]+)_H([0-9]+)_s([0-9]+)", name)
        path = os.path.join(out, name)
        if match and os.path.exists(os.path.join(path, "moduli.txt")):
            found[(float(match.group(1)), int(match.group(2)), int(match.group(3)))] = path
    return found


def sample_results(path):
    summary = sound.read_summary(os.path.join(path, "summary.txt"))
    result = dict(summary)
    result.update(sound.read_summary(os.path.join(path, "moduli.txt")))
    for condition in ("A", "B"):
        t, f = sound.read_pulse(os.path.join(path, f"pulse_{condition}.dat"))
        peak = sound.coherent_peak(t, f)
        result.update({f"{key}_{condition}": value for key, value in peak.items()})
    grains = sound.read_dump(os.path.join(path, "grains.dump"))
    contacts = sound.read_dump(os.path.join(path, "contacts.dump"))
    result.update(sound.static_properties(grains, contacts, summary["W"], summary["h"], summary["p"],
                                          depth=summary.get("D") or None))
    return result


def mean_std(values):
    values = np.asarray(values, dtype=float)
    return float(values.mean()), float(values.std(ddof=1)) if len(values) > 1 else 0.0


def chain_results(directory):
    """amplitude and width of the coherent peak against N for conditions A, B"""
    out = {}
    for condition in ("A", "B"):
        sizes, amplitude, width = [], [], []
        for name in os.listdir(directory):
            match = re.fullmatch(rf"chain_{condition}_([0-9]+)\.dat", name)
            if not match:
                continue
            t, f = sound.read_pulse(os.path.join(directory, name))
            peak = sound.coherent_peak(t, f)
            sizes.append(int(match.group(1)))
            amplitude.append(peak["amplitude"])
            width.append(peak["t_peak"] - peak["t10"])
        order = np.argsort(sizes)
        out[condition] = {"N": list(np.array(sizes)[order].tolist()),
                          "amplitude": list(np.array(amplitude)[order].tolist()),
                          "rise": list(np.array(width)[order].tolist())}
    return out


def height_series(per_sample, pressure):
    """mean length, amplitude and width (condition A) of the coherent peak at
    each height of the samples at this pressure, with effective exponents"""
    heights = sorted({H for (q, H, _) in per_sample if q == pressure})
    if len(heights) < 2:
        return None
    at_height = [[r for (q, H, _), r in per_sample.items() if q == pressure and H == height] for height in heights]
    length = [float(np.mean([r["h"] for r in rows])) for rows in at_height]
    amplitude = [float(np.mean([r["amplitude_A"] for r in rows])) for rows in at_height]
    width = [float(np.mean([r["width_A"] for r in rows])) for rows in at_height]
    _, g = sound.effective_exponents(length, amplitude)
    _, a = sound.effective_exponents(length, width)
    return {"H": heights, "L": length, "amplitude": amplitude, "width": width,
            "samples": [len(rows) for rows in at_height], "gamma_eff": list(-g), "alpha_eff": list(a)}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "out")
    figures = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "figures")
    os.makedirs(figures, exist_ok=True)
    found = samples(out)
    per_sample = {key: sample_results(path) for key, path in found.items()}
    pressures = sorted({p for p, _, _ in per_sample})
    results = {"samples": {f"p{p:g}_H{H}_s{s}": r for (p, H, s), r in per_sample.items()},
               "pressures": {}}
    lines = []
    for p in pressures:
        seeds = sorted({s for (q, _, s) in per_sample if q == p})
        speeds = {"t10": [], "t_peak": [], "t_zero": []}
        gammas, alphas = [], []
        for s in seeds:
            short, tall = per_sample.get((p, 8, s)), per_sample.get((p, 25, s))
            if not (short and tall):
                continue
            for key in speeds:
                speeds[key].append(sound.time_of_flight_speed(short["h"], short[f"{key}_A"],
                                                               tall["h"], tall[f"{key}_A"]))
            span = math.log(tall["h"] / short["h"])
            gammas.append(-math.log(tall["amplitude_A"] / short["amplitude_A"]) / span)
            alphas.append(math.log(tall["width_A"] / short["width_A"]) / span)
        tall = [r for (q, H, _), r in per_sample.items() if q == p and H == 25]
        entry = {"samples": len(seeds), "tall_samples": len(tall)}
        for key, values in speeds.items():
            if values:
                entry[f"c_tof_{key}"] = mean_std(values)
        if gammas:
            entry["gamma"] = mean_std(gammas)
            entry["alpha"] = mean_std(alphas)
        for key in ("phi2", "phi3", "phi3_star", "z_star", "f0", "mean_force_over_p", "Z2", "Z3",
                    "sigma1_over_sigma2", "max_acceleration", "wall_seconds"):
            if tall and key in tall[0]:
                entry[key] = mean_std([r[key] for r in tall])
        # moduli: the samples whose response stayed linear (no rearrangement)
        linear = [r for r in tall if sound.linear_response(r)]
        entry["moduli_samples"] = len(linear)
        for key in ("C11", "C12", "C12_from_eps11", "C22", "C33", "strain"):
            if linear:
                entry[key] = mean_std([r[key] for r in linear])
        if "C22" in entry:
            c_l, c_t = sound.sound_speeds(entry["C22"][0], max(entry["C33"][0], 0.0), entry["phi3_star"][0])
            entry["c_l"], entry["c_t"] = c_l, c_t
            if "c_tof_t10" in entry:
                entry["c_tof_over_c_l"] = entry["c_tof_t10"][0] / c_l
        results["pressures"][f"{p:g}"] = entry

    # c_tof ~ p^x
    with_speed = [p for p in pressures if "c_tof_t10" in results["pressures"][f"{p:g}"]]
    if len(with_speed) >= 2:
        x, prefactor = sound.power_law_fit(with_speed, [results["pressures"][f"{p:g}"]["c_tof_t10"][0]
                                                          for p in with_speed])
        results["c_tof_exponent"] = x

    chain_dir = os.path.join(out, "chain")
    if os.path.isdir(chain_dir):
        chain = chain_results(chain_dir)
        results["chain"] = chain
        for condition in ("A", "B"):
            c = chain[condition]
            if len(c["N"]) >= 2:
                _, g = sound.effective_exponents(c["N"], c["amplitude"])
                _, a = sound.effective_exponents(c["N"], c["rise"])
                c["gamma_eff"] = list(-g)
                c["alpha_eff"] = list(a)

    series = height_series(per_sample, 1e-4)
    if series:
        results["disordered_1e-4"] = series

    with open(os.path.join(out, "results.json"), "w") as handle:
        json.dump(results, handle, indent=1, default=float)

    # tables
    def cell(entry, key, fmt="{:.3g}"):
        if key not in entry:
            return "-"
        value = entry[key]
        if isinstance(value, (list, tuple)):
            return (fmt + " ± " + fmt).format(*value)
        return fmt.format(value)

    lines.append("| p | samples | Φ2 | Φ3 | Φ3* | z* | f0 | ⟨N⟩/p | Z(2) | Z(3) |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|")
    for p in pressures:
        e = results["pressures"][f"{p:g}"]
        lines.append(f"| {p:g} | {e['tall_samples']} | " + " | ".join(
            cell(e, k) for k in ("phi2", "phi3", "phi3_star", "z_star", "f0", "mean_force_over_p", "Z2", "Z3")) + " |")
    lines.append("")
    lines.append("| p | σ1/σ2 | moduli samples | C11 | C12 | C12 (from ε11) | C22 | C33 | c_ℓ | c_t | c_tof (10 %) | c_tof (peak) | c_tof (zero) | c_tof/c_ℓ | γ (L 8-25) | α (L 8-25) |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for p in pressures:
        e = results["pressures"][f"{p:g}"]
        lines.append(f"| {p:g} | " + " | ".join(cell(e, k) for k in (
            "sigma1_over_sigma2", "moduli_samples", "C11", "C12", "C12_from_eps11", "C22", "C33", "c_l", "c_t", "c_tof_t10", "c_tof_t_peak",
            "c_tof_t_zero", "c_tof_over_c_l", "gamma", "alpha")) + " |")
    if "c_tof_exponent" in results:
        lines.append("")
        lines.append(f"c_tof ∝ p^x with x = {results['c_tof_exponent']:.4f} (paper: 1/6 = 0.1667)")
    if "chain" in results:
        for condition in ("A", "B"):
            c = results["chain"][condition]
            if "gamma_eff" in c:
                lines.append(f"chain {condition}: N {c['N']}, gamma_eff {np.round(c['gamma_eff'], 3).tolist()}, "
                             f"alpha_eff (rise time) {np.round(c['alpha_eff'], 3).tolist()}")
    if series:
        lines.append(f"2D p = 1e-4 (condition A): H {series['H']}, samples {series['samples']}, "
                     f"L {np.round(series['L'], 2).tolist()}, gamma_eff {np.round(series['gamma_eff'], 3).tolist()}, "
                     f"alpha_eff {np.round(series['alpha_eff'], 3).tolist()}")
    text = "\n".join(lines)
    with open(os.path.join(out, "tables.md"), "w") as handle:
        handle.write(text + "\n")
    print(text)

    # figures
    at = {key: r for key, r in per_sample.items() if key[0] == 1e-4}
    tall = [(key, r) for key, r in at.items() if key[1] == 25]
    if tall:
        signals = [sound.read_pulse(os.path.join(found[key], "pulse_A.dat")) for key, _ in tall]
        sound_figures.fig4_signals(signals, sound.ensemble(signals), os.path.join(figures, "fig4_signal_p1e-4.png"),
                                   "p = 1e-4, L ≈ 25, initial condition A")
        first = tall[0][0]
        modes = sound.read_vector_blocks(os.path.join(found[first], "modes.dat"))[-1][1][:, 0]
        sound_figures.fig9_spectrum(modes, os.path.join(figures, "fig9_spectrum_p1e-4.png"),
                                    "p = 1e-4, L ≈ 25 (rattlers: zero modes)")
    if at:
        keys = sorted(at)
        sound_figures.fig6_arrival_times([at[k]["h"] for k in keys], [at[k]["t10_A"] for k in keys],
                                         [at[k]["t_peak_A"] for k in keys], [at[k]["t_zero_A"] for k in keys],
                                         os.path.join(figures, "fig6_arrival_p1e-4.png"), "p = 1e-4")
    if with_speed:
        e = [results["pressures"][f"{p:g}"] for p in with_speed]
        sound_figures.fig8_speeds(with_speed, [x["c_tof_t10"][0] for x in e], [x["c_tof_t10"][1] for x in e],
                                  [x.get("c_l", np.nan) for x in e], [x.get("c_t", np.nan) for x in e],
                                  os.path.join(figures, "fig8_speeds.png"))
    curves = {}
    if "chain" in results:
        for condition in ("A", "B"):
            c = results["chain"][condition]
            if len(c["N"]) >= 2:
                curves[f"1D chain, {condition}"] = (c["N"], c["amplitude"], c["rise"])
    if "disordered_1e-4" in results:
        d = results["disordered_1e-4"]
        curves["2D disordered, p = 1e-4, A"] = (d["L"], d["amplitude"], d["width"])
    if curves:
        sound_figures.fig7_exponents(curves, os.path.join(figures, "fig7_exponents.png"))


if __name__ == "__main__":
    main()
