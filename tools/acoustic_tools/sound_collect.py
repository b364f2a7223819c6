"""Collect the jobs of examples/sound (acoustic_tools.sound_study, the
command line examples/sound/study.py) into paper 003's tables and figures.
Each job is a directory of OUT with its job.json (the settings: kind
"sample" or "chain", p, H, seed, W, D, piston_mass, piston_speed; N for the
chain) and, once finished, the result.json that in.sound (in.chain) writes
at its end; the settings come from job.json, the deck's values from
result.json, the signals and the contact network from the data files beside
them (pulse_A.dat, pulse_B.dat, modes.dat, grains.dump, contacts.dump;
chain_A_<N>.dat, chain_B_<N>.dat).

  samples, pistons, sample_results, usable_samples
                        the sample jobs and what each holds
  pressure_entry        the statistics of the samples at one pressure
  pressures_of, speed_pressures, overshoots
                        the pressures of the samples and those with a
                        speed, each packing's overshoot and stress ratio
  chain_results, height_series, checks_table, piston_checks
                        the 1D chain, the heights at one pressure, the
                        acceptance checks beside Table I, the pistons
  c33_candidates, c33_and_sliding, piston_samples, c33_and_piston
                        the measured candidate causes of C33 above
                        Table II's (z*, overshoot, sliding, strain, piston)
  collect_results       all of it: the dict of results.json
  tables                the markdown tables of tables.md
  figures               the figures (sound_figures)
  frictionless_results, frictionless_tables
                        the frictionless packings (job.json mu = 0),
                        kept apart from the frictional ones: their own
                        pressures, Tables I and II rows, speeds, Fig. 4(c)
  collect, draw          what study.py collect and study.py figures do
"""
import json
import math
import os

import numpy as np

from . import lammps_output, network_moduli, sound, sound_chain, sound_figures, sound_modes, study
from .stats import mean_sd


# paper 003, Table II: sigma1/sigma2, C11, C12, C22, C33
PAPER_TABLE_II = {
    1e-7: ("0.79 ± 0.06", "(9.9 ± 0.9)e-4", "(8.1 ± 0.4)e-4", "(13.9 ± 0.8)e-4", "(1.2 ± 0.4)e-4"),
    1e-6: ("0.79 ± 0.06", "(2.3 ± 0.2)e-3", "(1.7 ± 0.08)e-3", "(3.2 ± 0.2)e-3", "(0.35 ± 0.07)e-3"),
    1e-5: ("0.78 ± 0.06", "(5.4 ± 0.5)e-3", "(3.5 ± 0.2)e-3", "(7.4 ± 0.3)e-3", "(1.1 ± 0.2)e-3"),
    1e-4: ("0.71 ± 0.04", "(1.35 ± 0.09)e-2", "(6.8 ± 0.4)e-3", "(1.88 ± 0.08)e-2", "(4.0 ± 0.5)e-3"),
}
# Table II's C33, as numbers
PAPER_C33 = {1e-7: 1.2e-4, 1e-6: 0.35e-3, 1e-5: 1.1e-3, 1e-4: 4.0e-3}
# C22 and Phi3* of the two tables: the paper's c_l = sqrt(C22 / Phi3*)
PAPER_C22_PHI3STAR = {1e-7: (13.9e-4, 0.48), 1e-6: (3.2e-3, 0.49), 1e-5: (7.4e-3, 0.50), 1e-4: (1.88e-2, 0.52)}
# paper 003, Table IV: C~22(1)/C22, C~22(2)/C22, C~33(1)/C33, C~33(2)/C33
# (forces sin(n pi y / L2), Eq. B2), and Table V: C^22(1)/C22, C^22(3)/C22,
# C^33(1)/C33, C^33(3)/C33 (displacements imposed on lines, Eq. B3)
PAPER_TABLE_IV = {1e-7: ("0.85 ± 0.05", "0.74 ± 0.09", "0.81 ± 0.14", "1.01 ± 0.24"),
                  1e-6: ("0.88 ± 0.04", "0.80 ± 0.06", "0.90 ± 0.20", "0.96 ± 0.16"),
                  1e-5: ("0.91 ± 0.05", "0.86 ± 0.06", "0.85 ± 0.10", "0.89 ± 0.11"),
                  1e-4: ("0.93 ± 0.04", "0.88 ± 0.04", "0.85 ± 0.10", "0.90 ± 0.07")}
PAPER_TABLE_V = {1e-7: ("1.01 ± 0.02", "1.09 ± 0.03", "1.26 ± 0.16", "2.49 ± 0.69"),
                 1e-6: ("1.01 ± 0.01", "1.07 ± 0.07", "1.28 ± 0.20", "2.05 ± 0.45"),
                 1e-5: ("1.01 ± 0.02", "1.06 ± 0.03", "1.15 ± 0.11", "1.65 ± 0.30"),
                 1e-4: ("1.00 ± 0.01", "1.03 ± 0.02", "1.08 ± 0.05", "1.37 ± 0.14")}
# the columns of Tables IV (n = 1, 2, 3) and V (n = 1, 3): key -> (Eq., n, direction, modulus)
APPENDIX_B = {f"{modulus}_{kind}{n}_ratio": (kind, n, direction, modulus)
              for kind, orders in (("force", (1, 2, 3)), ("lines", (1, 3)))
              for modulus, direction in (("C22", 1), ("C33", 0)) for n in orders}


DEFAULT_PISTON = (1, 0.001)    # in.packing's piston_mass and piston_speed
DEFAULT_MU = 0.5               # in.packing's friction coefficient (job.json without mu: 0.5)
FRICTIONLESS = 0.0             # mu of the frictionless packings (paper 003 Fig. 4(c))
DEFAULT_MODULI_STRAIN = 0.05   # in.moduli's strain, a fraction of the overlap (job.json without it: 0.05)

# the values of a sample's result.json, in the order of results.json: what
# in.measure measured (with the deck's settings W, D, p_target, seed and
# piston_mass), what in.moduli measured, and the seconds the job took
SUMMARY_KEYS = ("W", "D", "h", "p", "p_target", "p_peak", "N", "seed", "max_acceleration", "piston_mass",
                "packing_steps", "wall_seconds")
MODULI_KEYS = ("sigma1_over_sigma2", "C11", "C22", "C12", "C12_from_eps11", "C33", "strain", "C11_half",
               "C22_half", "C12_half", "C33_half")


def piston_of(settings):
    """(mass, speed) of a sample's job.json"""
    return (settings["piston_mass"], settings["piston_speed"])


def mu_of(settings):
    """the friction coefficient of a sample's job.json (DEFAULT_MU when it
    does not say: the samples made before study.py run --mu)"""
    return float(settings.get("mu", DEFAULT_MU))


def moduli_strain_of(settings):
    """the strain of the moduli of a sample's job.json, a fraction of the
    overlap (DEFAULT_MODULI_STRAIN when it does not say)"""
    return float(settings.get("moduli_strain", DEFAULT_MODULI_STRAIN))


def network_model(mu):
    """the contact network of a packing of friction coefficient mu, as
    in.measure linearises it: "normal" (frictionless) for mu = 0, else "full"."""
    return "normal" if float(mu) == 0.0 else "full"


def sample_key(settings):
    """(p, H, seed) of a sample's job.json"""
    return (float(settings["p"]), int(settings["H"]), int(settings["seed"]))


def samples(out, piston=DEFAULT_PISTON, mu=DEFAULT_MU, moduli_strain=DEFAULT_MODULI_STRAIN):
    """(p, H, seed) -> (directory, result) of every finished sample made
    with the given piston (mass, speed), friction coefficient mu and strain
    of the moduli: the default ones (the paper's mu = 0.5) unless told; in
    the order of the directories' names"""
    found = {}
    for directory, settings, result in study.finished_jobs(out):
        if settings.get("kind") != "sample" or piston_of(settings) != tuple(piston):
            continue
        if mu_of(settings) != float(mu) or moduli_strain_of(settings) != float(moduli_strain):
            continue
        found[sample_key(settings)] = (directory, result)
    return found


def pistons(out):
    """the (mass, speed) of the pistons of the sample jobs (finished or not)"""
    found = set()
    for name in os.listdir(out):
        settings = study.read_job(os.path.join(out, name))
        if settings.get("kind") == "sample":
            found.add(piston_of(settings))
    return sorted(found)


def mean_standard_error(values):
    """mean and standard error of the mean"""
    values = np.asarray(values, dtype=float)
    if len(values) < 2:
        return float(values.mean()), 0.0
    return float(values.mean()), float(values.std(ddof=1) / math.sqrt(len(values)))


def checks_table(per_sample, pressures, height=25):
    """the acceptance checks of the packings (checks.txt of each) of the
    given height, per pressure: mean ± standard error, beside Table I, and
    how many of our standard errors separate the two"""
    rows = []
    for p in pressures:
        at = [r for (q, H, _), r in per_sample.items() if q == p and H == height and "z_star" in r]
        if not at:
            continue
        nearest, paper = sound.paper_row(p)
        for key in sound.CHECKS:
            values = [r[key] for r in at if key in r]
            if not values:
                continue
            mean, error = mean_standard_error(values)
            reference, spread = paper[key]
            distance = abs(mean - reference) / error if error > 0 else math.inf
            rows.append({"p": p, "key": key, "samples": len(values), "mean": mean, "standard_error": error,
                         "paper": reference, "paper_sd": spread, "standard_errors_off": distance})
    return rows


def _number(value):
    """a value of result.json as the float the analysis uses (None, a
    non-finite number of the deck, becomes nan)"""
    return math.nan if value is None else float(value)


def sample_results(path, result, model="full", mu=DEFAULT_MU):
    """Everything about one sample: its result.json (result) as in.sound
    wrote it (SUMMARY_KEYS, MODULI_KEYS), the coherent peak of both pulses,
    the statics of Table I, whether the packing came to rest, the stress
    ratio of its acceptance checks, the overshoot of its compression and (2D)
    the moduli of its contact network, and (when in.packing dumped the
    tangential forces, tangential.dump) the contacts at the Coulomb limit
    (contact_mobilisation; path: the job's directory; model: the network,
    "full", or "normal" for a frictionless packing, which has no Appendix B:
    its C33 is zero; mu: its friction coefficient)"""
    summary = {key: _number(result[key]) for key in SUMMARY_KEYS if key in result}
    out = dict(summary)
    out.update({key: _number(result[key]) for key in MODULI_KEYS if key in result})
    for condition in ("A", "B"):
        t, f = sound.read_pulse(os.path.join(path, f"pulse_{condition}.dat"))
        peak = sound.coherent_peak(t, f)
        out.update({f"{key}_{condition}": value for key, value in peak.items()})
    grains = lammps_output.read_dump(os.path.join(path, "grains.dump"))[-1]
    contacts = lammps_output.read_dump(os.path.join(path, "contacts.dump"))[-1]
    out.update(sound.static_properties(grains, contacts, summary["W"], summary["h"], summary["p"],
                                       depth=summary.get("D") or None))
    # the packing came to rest (every acceleration below the criterion)
    # within the deck's max_checks
    out["at_rest"] = bool(result["at_rest"])
    if "checks" in result:
        # the packing's own checks (bulk sigma1/sigma2 of the contact virial at rest)
        out["sigma_ratio"] = _number(result["checks"]["sigma_ratio"])
    if "p_peak" in summary:
        out["overshoot"] = summary["p_peak"] / summary["p"]
    if not summary.get("D"):
        # the same moduli from the linear response of the contact network (2D)
        network = network_moduli.network_moduli(grains, contacts, summary["W"], summary["h"], model=model)
        out.update({f"{key}_network": value for key, value in network.items()})
        if model == "full":
            out.update(appendix_b(grains, contacts, summary["W"], summary["h"], network))
    tangential = os.path.join(path, "tangential.dump")
    if model == "full" and os.path.exists(tangential):
        out.update(contact_mobilisation(lammps_output.read_dump(tangential)[-1], grains, contacts, summary, mu))
    return out


def contact_mobilisation(tangential, grains, contacts, summary, mu=DEFAULT_MU):
    """The grain-grain contacts at the Coulomb limit of one 2D packing
    (tangential: in.packing's tangential.dump, columns i, j, F_n, |F_t|):
    the fractions of sound.mobilisation, and the moduli of the contact
    network with the tangential springs of those contacts removed, as if
    every one of them slid (C22_slipping, C33_slipping: a bound on what
    sliding at those contacts can do to the moduli; the wall contacts keep
    their springs)"""
    found = sound.mobilisation(tangential[2], tangential[3], float(mu))
    sliding = {tuple(sorted((int(i), int(j)))) for i, j, limit in zip(tangential[0], tangential[1], found["at_limit"])
               if limit}
    out = {"mobilised": found["fraction_at_limit"], "mobilised_0.9": found["fraction_above_0.9"],
           "mobilisation_mean": found["mean"]}
    if not summary.get("D"):
        eta = np.array([0.0 if tuple(sorted((int(i), int(j)))) in sliding else 1.0
                        for i, j in zip(contacts[0], contacts[1])])
        slipping = network_moduli.network_moduli(grains, contacts, summary["W"], summary["h"], eta=eta)
        out.update({f"{key}_slipping": value for key, value in slipping.items()})
        out.update(c33_without_mobilised(found["m"], tangential, grains, contacts, summary))
    return out


# the mobilisations m = |F_t| / (mu F_n) above which c33_without_mobilised
# removes the tangential springs
MOBILISATION_THRESHOLDS = (0.8, 0.6)


def c33_without_mobilised(m, tangential, grains, contacts, summary, thresholds=MOBILISATION_THRESHOLDS):
    """How much of C33 hangs on the most mobilised contacts: for each
    threshold, the share of the grain-grain contacts with m >= threshold
    (m: sound.mobilisation's, in the order of tangential's rows) and the
    network's C33 with their tangential springs removed, as if they all
    slid; keys mobilised_<threshold>, C33_without_<threshold>"""
    by_pair = {tuple(sorted((int(i), int(j)))): value for i, j, value in zip(tangential[0], tangential[1], m)}
    grain_contact = contacts[1].astype(int) != 0
    mobilisation = np.array([by_pair.get(tuple(sorted((int(i), int(j)))), 0.0)
                             for i, j in zip(contacts[0], contacts[1])])
    out = {}
    for threshold in thresholds:
        removed = grain_contact & (mobilisation >= threshold)
        network = network_moduli.network_moduli(grains, contacts, summary["W"], summary["h"],
                                                 eta=np.where(removed, 0.0, 1.0))
        out[f"mobilised_{threshold:g}"] = float(removed.sum() / max(int(grain_contact.sum()), 1))
        out[f"C33_without_{threshold:g}"] = network["C33"]
    return out


def appendix_b(grains, contacts, width, height, network):
    """paper 003's Appendix B on one 2D packing: the apparent moduli C~22,
    C~33 of forces sin(n pi y / L2) (Eq. B2, n = 1, 2, 3) and C^22, C^33 of
    displacements imposed on lines (Eq. B3, n = 1, 3), over the global
    moduli of the same network (network: network_moduli.network_moduli);
    keys of APPENDIX_B"""
    net = sound_modes.network(grains, contacts, width, height)
    out = {}
    for key, (kind, n, direction, modulus) in APPENDIX_B.items():
        if kind == "force":
            value = sound_modes.apparent_modulus_force(net, grains, contacts, n, direction)
        else:
            value = sound_modes.apparent_modulus_displacement(net, grains, n, direction)
        out[key] = value / network[modulus]
    return out


def packing_modes(directory, result):
    """The eigenmodes of one 2D packing's network (sound_modes.modes), their
    participation ratios, the modes of Fig. 10 (sound_modes.selected_modes)
    and how far the signal summed from the modes (Eq. 3) lies from the
    deck's pulse_A.dat (largest difference over the largest |F_sig|)"""
    grains = lammps_output.read_dump(os.path.join(directory, "grains.dump"))[-1]
    contacts = lammps_output.read_dump(os.path.join(directory, "contacts.dump"))[-1]
    net = sound_modes.network(grains, contacts, float(result["W"]), float(result["h"]))
    found = sound_modes.modes(net)
    participation = sound_modes.participation_ratios(found["shapes"], net["M"])
    t, f = sound.read_pulse(os.path.join(directory, "pulse_A.dat"))
    deviation = float(np.max(np.abs(sound_modes.modal_signal(found["omega"], found["contribution"], t) - f))
                      / np.max(np.abs(f)))
    return {"grains": grains, "contacts": contacts, "network": net, "modes": found,
            "participation": participation, "selected": sound_modes.selected_modes(found, participation),
            "signal_deviation": deviation}


def width_of(peak):
    """The width of the coherent peak, the one definition of examples/sound
    (Fig. 7, Table III, the chains, the lattices and the packings alike):
    its first zero crossing minus its arrival at 10 % of its height (paper
    003 Fig. 6's inset: the first and last of its three marks)"""
    return peak["t_zero"] - peak["t10"]


def exponents_with_errors(sizes, amplitude, amplitude_se, width, width_se):
    """effective exponents gamma_eff = -d log A / d log L and alpha_eff =
    d log W / d log L between successive sizes, with the standard errors of
    independent means propagated (zero for a single realization)"""
    _, gamma, gamma_se = sound.effective_exponents_se(sizes, amplitude, amplitude_se)
    _, alpha, alpha_se = sound.effective_exponents_se(sizes, width, width_se)
    return {"gamma_eff": list(-gamma), "gamma_eff_se": list(gamma_se), "alpha_eff": list(alpha),
            "alpha_eff_se": list(alpha_se)}


def chain_wall_modulus(result):
    """the walls' Hertz modulus of a chain job from its result.json:
    1/sqrt(2) for identical springs (wall_spring_over_K 1), 2 for rigid
    walls (2, and the chains of in.chain's first version, which did not say)"""
    return 1.0 / math.sqrt(2.0) if abs(result.get("wall_spring_over_K", 2.0) - 1.0) < 1e-6 else 2.0


def chain_results(directory, result):
    """The coherent peak of a chain job (in.chain) against N for conditions A
    and B: mean amplitude and width (width_of) over its realizations with
    their standard errors, the effective exponents between successive N
    (exponents_with_errors), and the largest relative deviation of its
    signals from the same chains computed here (sound_chain: the Hertz
    springs and masses of chain_<N>.grains, modes of the tridiagonal
    chain): directory, result: the job's directory and result.json"""
    sizes = sorted(result["N"])
    realizations = int(result.get("realizations", 1)) if result.get("poly") else 1
    wall_modulus = chain_wall_modulus(result)
    out = {"poly": float(result.get("poly", 0.0)), "realizations": realizations,
           "wall_spring_over_K": result.get("wall_spring_over_K", 2.0)}
    deviation = 0.0
    for condition in ("A", "B"):
        columns = {"N": sizes, "amplitude": [], "amplitude_se": [], "width": [], "width_se": []}
        for n in sizes:
            amplitudes, widths = [], []
            for r in range(1, realizations + 1):
                tag = f"{n}_{r}" if result.get("poly") else f"{n}"
                t, f = sound.read_pulse(os.path.join(directory, f"chain_{condition}_{tag}.dat"))
                peak = sound.coherent_peak(t, f)
                amplitudes.append(peak["amplitude"])
                widths.append(width_of(peak))
                grains = os.path.join(directory, f"chain_{tag}.grains")
                if os.path.exists(grains):
                    _, diameters, _ = sound_chain.read_chain_grains(grains)
                    masses, springs = sound_chain.hertz_chain(diameters, result["p"], wall_modulus)
                    model = sound_chain.linear_chain_signal(masses, springs, t, condition)
                    deviation = max(deviation, float(np.max(np.abs(model - f)) / np.max(np.abs(f))))
            for key, values in (("amplitude", amplitudes), ("width", widths)):
                columns[key].append(float(np.mean(values)))
                columns[key + "_se"].append(float(np.std(values, ddof=1) / math.sqrt(len(values)))
                                            if len(values) > 1 else 0.0)
        if len(sizes) >= 2:
            columns.update(exponents_with_errors(sizes, columns["amplitude"], columns["amplitude_se"],
                                                 columns["width"], columns["width_se"]))
        out[condition] = columns
    out["model_deviation"] = deviation
    return out


def chain_jobs(out):
    """(directory, result) of every finished chain job of out, the chains of
    identical balls first, then by polydispersity"""
    found = [(directory, result) for directory, settings, result in study.finished_jobs(out)
             if settings.get("kind") == "chain"]
    return sorted(found, key=lambda job: (job[1].get("poly", 0.0), job[1].get("wall_spring_over_K", 2.0) != 1.0))


def chain_job(out):
    """(directory, result) of the finished chain of identical balls of out
    (identical wall springs when there is one), or None"""
    mono = [job for job in chain_jobs(out) if not job[1].get("poly")]
    return mono[0] if mono else None


LATTICE_MODELS = {"normal": ("frictionless", 0.0), "full": ("frictional", 1.0)}   # model -> (name, k_t / k_n)


def lattice_jobs(out):
    """(directory, result) of every finished lattice job (in.lattice) of out"""
    return [(directory, result) for directory, settings, result in study.finished_jobs(out)
            if settings.get("kind") == "lattice"]


def lattice_results(directory, result):
    """The coherent peak of every lattice of a lattice job (in.lattice), per
    ball of a row, for both models and conditions; the time-of-flight speeds
    from its two rows nearest to the packings' L = 8 and 25 (10 %, peak,
    zero crossing) beside Eqs. 18 (frictionless) and 19 (frictional,
    k_t = k_n), and the largest relative deviation of its signals from the
    chain of its rows (sound_chain.lattice_row_chain, times M)"""
    rows, heights, m_balls, a, p = result["rows"], result["h"], result["M"], result["a"], result["p"]
    order = np.argsort(rows)
    rows, heights = [rows[k] for k in order], [heights[k] for k in order]
    out = {"p": p, "M": m_balls, "a": a, "rows": rows, "h": heights, "models": {}}
    deviation = 0.0
    for model, (name, eta) in LATTICE_MODELS.items():
        entry = {"name": name, "eta": eta, "eq": sound_chain.lattice_speed(p, eta)}
        for condition in ("A", "B"):
            peaks = []
            for n in rows:
                t, f = sound.read_pulse(os.path.join(directory, f"lattice_{model}_{condition}_{n}.dat"))
                peaks.append(sound.coherent_peak(t, np.asarray(f) / m_balls))
                masses, springs = sound_chain.lattice_row_chain(n, p, eta, spacing=a)
                chain = m_balls * sound_chain.linear_chain_signal(masses, springs, t, condition)
                deviation = max(deviation, float(np.max(np.abs(chain - f)) / np.max(np.abs(f))))
            entry[condition] = {"N": rows, "L": heights, "amplitude": [q["amplitude"] for q in peaks],
                                "width": [width_of(q) for q in peaks], "t10": [q["t10"] for q in peaks],
                                "t_peak": [q["t_peak"] for q in peaks], "t_zero": [q["t_zero"] for q in peaks]}
            if len(rows) >= 2:
                entry[condition].update(exponents_with_errors(rows, entry[condition]["amplitude"], [0.0] * len(rows),
                                                              entry[condition]["width"], [0.0] * len(rows)))
        if len(rows) >= 2:
            short = int(np.argmin([abs(h - 8.0) for h in heights]))
            tall = int(np.argmin([abs(h - 25.0) for h in heights]))
            if short != tall:
                pk = entry["A"]
                entry["pair"] = [rows[short], rows[tall]]
                for key in ("t10", "t_peak", "t_zero"):
                    entry[f"c_tof_{key}"] = sound.time_of_flight_speed(heights[short], pk[key][short],
                                                                       heights[tall], pk[key][tall])
        out["models"][model] = entry
    out["chain_deviation"] = deviation
    return out


def front_curves(out, sizes=(32, 128, 512, 2048), rows=(32, 128)):
    """Fig. 12's curves (sound_chain.scaled_front) of condition A: the chain of
    identical balls of out (its sizes among `sizes`) and the frictionless
    triangular lattices at p = 1e-4 with these rows, per ball of a row, both
    as compute vibration/pulse measures them (a unit pulse of the source
    wall, the force on the detector wall) and scaled with their bulk chain's
    K, m and l: the lattice is compared with the chain of its rows that has
    identical springs at the walls, as in paper 003 Sec. V B"""
    curves = {}
    chain = chain_job(out)
    if chain:
        directory, result = chain
        for n in [n for n in sizes if n in result["N"]]:
            y, diameters, _ = sound_chain.read_chain_grains(os.path.join(directory, f"chain_{n}.grains"))
            masses, springs = sound_chain.hertz_chain(diameters, result["p"], chain_wall_modulus(result))
            t, f = sound.read_pulse(os.path.join(directory, f"chain_A_{n}.dat"))
            x, value = sound_chain.scaled_front(t, f, n, springs[1], masses[0], float(np.mean(np.diff(y))),
                                                springs[0], springs[-1])
            curves[f"1D chain, N = {n}"] = (x, value, "line")
    for directory, result in lattice_jobs(out):
        if abs(result["p"] / 1e-4 - 1.0) > 1e-9:
            continue
        for n in [n for n in rows if n in result["rows"]]:
            masses, springs = sound_chain.lattice_row_chain(n, result["p"], 0.0, spacing=result["a"])
            t, f = sound.read_pulse(os.path.join(directory, f"lattice_normal_A_{n}.dat"))
            # the lattice's signal as measured (a unit pulse of the wall, the force on the other
            # wall), per ball of a row, in the units of the chain of its rows with identical springs:
            # the walls' own springs (1.6 K here) are part of what is compared (paper Sec. V B)
            x, value = sound_chain.scaled_front(t, np.asarray(f) / result["M"], n, springs[1], masses[0],
                                                math.sqrt(3.0) / 2.0 * result["a"])
            keep = (x > -4.0) & (x < 3.0)
            step = max(1, int(keep.sum() // 80))
            curves[f"triangular lattice, {n} rows (frictionless)"] = (x[keep][::step], value[keep][::step], "points")
    return curves


def lattice_summary(out):
    """results.json's "lattice" (the speeds of every lattice job, by
    pressure and width) and "lattice_series" (the amplitude and width
    against the rows of the jobs with at least 3 lattices, for Fig. 7 and
    Table III)"""
    speeds, series = {}, {}
    for directory, result in lattice_jobs(out):
        entry = lattice_results(directory, result)
        speeds[os.path.basename(directory)] = entry
        if len(entry["rows"]) >= 3:
            for model, e in entry["models"].items():
                for condition in ("A", "B"):
                    series[f"{e['name']}, p = {entry['p']:g}, {condition}"] = dict(e[condition], condition=condition)
    return speeds, series


def height_series(per_sample, pressure):
    """mean length, amplitude and width (width_of, condition A) of the
    coherent peak at each height of the samples at this pressure, with their
    standard errors and the effective exponents between successive heights
    (exponents_with_errors)"""
    heights = sorted({H for (q, H, _) in per_sample if q == pressure})
    if len(heights) < 2:
        return None
    at_height = [[r for (q, H, _), r in per_sample.items() if q == pressure and H == height] for height in heights]
    series = {"H": heights, "samples": [len(rows) for rows in at_height],
              "L": [float(np.mean([r["h"] for r in rows])) for rows in at_height]}
    for key, column in (("amplitude", "amplitude_A"), ("width", "width_A")):
        values = [[r[column] for r in rows] for rows in at_height]
        series[key] = [float(np.mean(v)) for v in values]
        series[key + "_se"] = [float(np.std(v, ddof=1) / math.sqrt(len(v))) if len(v) > 1 else 0.0 for v in values]
    series.update(exponents_with_errors(series["L"], series["amplitude"], series["amplitude_se"], series["width"],
                                        series["width_se"]))
    return series


def usable_samples(out, mu=DEFAULT_MU):
    """(found, per_sample, off_target, not_at_rest): the directory of every
    finished sample with the default piston and friction coefficient mu
    (the paper's 0.5 unless told; (p, H, seed) -> path), the
    sample_results of those that belong to a pressure series, and the names
    of those left out: the packings whose servo did not bring the wall
    pressure within 5 % of the target, and those not at rest"""
    jobs = samples(out, mu=mu)
    found = {key: directory for key, (directory, _) in jobs.items()}
    model = network_model(mu)
    per_sample = {key: sample_results(directory, result, model, mu) for key, (directory, result) in jobs.items()}
    off_target = sorted(os.path.basename(found[key]) for key, r in per_sample.items()
                        if abs(r["p"] / key[0] - 1.0) > 0.05)
    not_at_rest = sorted(os.path.basename(found[key]) for key, r in per_sample.items() if not r["at_rest"])
    per_sample = {key: r for key, r in per_sample.items()
                  if os.path.basename(found[key]) not in off_target + not_at_rest}
    return found, per_sample, off_target, not_at_rest


def pressure_entry(per_sample, p):
    """The results of the samples at pressure p (mean, standard deviation):
    the time-of-flight speeds and the exponents gamma and alpha of the pairs
    of H = 8 and H = 25 packings of each seed, the statics of the H = 25
    packings, the moduli of those whose response stayed linear, the
    network's moduli, the sound speeds of the moduli"""
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
    entry = {"samples": len(speeds["t10"]), "tall_samples": len(tall)}
    for key, values in speeds.items():
        if values:
            entry[f"c_tof_{key}"] = mean_sd(values)[:2]
    if gammas:
        entry["gamma"] = mean_sd(gammas)[:2]
        entry["alpha"] = mean_sd(alphas)[:2]
    for key in ("phi2", "phi3", "phi3_star", "z_star", "f0", "mean_force_over_p", "Z2", "Z3", "F2",
                "F2_strong", "sigma_ratio", "sigma1_over_sigma2", "overshoot", "max_acceleration",
                "packing_steps", "wall_seconds"):
        if tall and key in tall[0]:
            entry[key] = mean_sd([r[key] for r in tall])[:2]
    # moduli: the samples whose response stayed linear (no rearrangement),
    # judged per loading: compression and stretch (C11, C12, C22), shear (C33)
    normal = [r for r in tall if sound.linear_response(r, keys=("C11", "C22"))]
    shear = [r for r in tall if sound.linear_response(r, keys=("C33",))]
    entry["moduli_samples"] = f"{len(normal)} / {len(shear)}"
    for key in ("C11", "C12", "C12_from_eps11", "C22", "strain"):
        if normal:
            entry[key] = mean_sd([r[key] for r in normal])[:2]
    if shear:
        entry["C33"] = mean_sd([r["C33"] for r in shear])[:2]
    # the network's moduli (every packing: the network is linear), and the
    # DEM's over the network's on the packings whose DEM response stayed linear
    if tall and "C22_network" in tall[0]:
        for key in ("C22", "C33"):
            entry[f"{key}_network"] = mean_sd([r[f"{key}_network"] for r in tall])[:2]
        if normal:
            entry["C22_dem_over_network"] = mean_sd([r["C22"] / r["C22_network"] for r in normal])[:2]
        if shear:
            entry["C33_dem_over_network"] = mean_sd([r["C33"] / r["C33_network"] for r in shear])[:2]
    for key in APPENDIX_B:
        if tall and key in tall[0]:
            entry[key] = mean_sd([r[key] for r in tall])[:2]
    c_l, c_t = sound.sound_speeds(entry.get("C22", (math.nan,))[0], entry.get("C33", (math.nan,))[0],
                                  entry.get("phi3_star", (math.nan,))[0])
    if "C22" in entry:
        entry["c_l"] = c_l
        if "c_tof_t10" in entry:
            entry["c_tof_over_c_l"] = entry["c_tof_t10"][0] / c_l
    if "C33" in entry:
        entry["c_t"] = c_t
    return entry


def piston_checks(out):
    """The checks of the H = 25 packings at p = 1e-4 for every piston (mass,
    dashpot speed) of the sample directories that has some, mean and
    standard error, when there is more than one piston: {"mass M, dashpot
    speed V": entry}"""
    checks = {}
    every_piston = pistons(out)
    for piston in every_piston if len(every_piston) > 1 else []:
        every = [sample_results(path, result) for key, (path, result) in samples(out, piston).items()
                 if key[0] == 1e-4 and key[1] == 25]
        if not every:
            continue    # a piston of other pressures only (c33_and_piston)
        at = [r for r in every if r["at_rest"]]
        entry = {"samples": f"{len(at)} of {len(every)} at rest"}
        if not at:
            checks[f"mass {piston[0]:g}, dashpot speed {piston[1]:g}"] = entry
            continue
        for key in sound.CHECKS + ("overshoot", "packing_steps"):
            if all(key in r for r in at):
                entry[key] = mean_standard_error([r[key] for r in at])
        checks[f"mass {piston[0]:g}, dashpot speed {piston[1]:g}"] = entry
    return checks


def overshoots(per_sample):
    """(p_peak / p, sigma1/sigma2, pressure) of every packing with an overshoot"""
    return [(r["overshoot"], r["sigma1_over_sigma2"], q) for (q, _, _), r in per_sample.items() if "overshoot" in r]


def c33_candidates(per_sample, pressures, height=25):
    """Two candidate causes of a C33 above Table II's, tested within our own
    ensembles: at each pressure, the least-squares line of C33 against z*
    over the H = 25 packings, read at the paper's z* (does the z* offset of
    Table I account for the excess?), and the line against log(p_peak / p)
    read at the smallest overshoot of the ensemble (would a gentler
    compression?); {p: {"samples", "C33", "paper", "z_star", "paper_z_star",
    "slope_z", "slope_z_se", "C33_at_paper_z", "r_overshoot",
    "C33_at_least_overshoot"}}"""
    out = {}
    for p in pressures:
        rows = [(r["z_star"], math.log(r["overshoot"]), r["C33"]) for (q, h, _), r in per_sample.items()
                if q == p and h == height and all(k in r for k in ("z_star", "overshoot", "C33"))]
        if len(rows) < 3 or p not in sound.PAPER_TABLE_I:
            continue
        z, log_overshoot, c33 = (np.asarray(v) for v in zip(*rows))
        (slope, intercept), cov = np.polyfit(z, c33, 1, cov=True)
        paper_z = sound.PAPER_TABLE_I[p]["z_star"][0]
        slope_o, intercept_o = np.polyfit(log_overshoot, c33, 1)
        out[p] = {"samples": len(rows), "C33": float(c33.mean()), "paper": PAPER_C33[p], "z_star": float(z.mean()),
                  "paper_z_star": paper_z, "slope_z": float(slope), "slope_z_se": float(math.sqrt(cov[0, 0])),
                  "C33_at_paper_z": float(slope * paper_z + intercept),
                  "r_overshoot": float(np.corrcoef(log_overshoot, c33)[0, 1]),
                  "least_overshoot": float(math.exp(log_overshoot.min())),
                  "C33_at_least_overshoot": float(slope_o * log_overshoot.min() + intercept_o)}
    return out


def moduli_strains(out):
    """the strains of the moduli other than the default among the finished
    samples of out (study.py run --moduli-strain), in order"""
    return sorted({moduli_strain_of(settings) for _, settings, _ in study.finished_jobs(out)
                   if settings.get("kind") == "sample" and moduli_strain_of(settings) != DEFAULT_MODULI_STRAIN})


def c33_and_sliding(out, per_sample, pressures, height=25):
    """C33 against sliding at the contacts, per pressure, on the H = 25
    packings: the contacts at the Coulomb limit and the network's C33 with
    their tangential springs removed (contact_mobilisation, on every packing
    with a tangential.dump), and the DEM's C33 measured at other strains on
    the same packings (the samples of study.py run --moduli-strain, paired
    seed by seed with the default ones: C33 at that strain over C33 at the
    default strain, mean and standard error); {p: {"packings",
    "mobilised", "mobilised_0.9", "mobilisation_mean", "C33_network",
    "C33_slipping", "C22_slipping_over_network", "mobilised_<t>",
    "C33_without_<t>" (c33_without_mobilised, t in MOBILISATION_THRESHOLDS), "paper",
    "strains": {strain: {"pairs", "ratio", "C33"}}}} (means and standard
    errors), the pressures without either left out"""
    strained = {e: samples(out, moduli_strain=e) for e in moduli_strains(out)}
    out_entry = {}
    for p in pressures:
        sliding = {s: r for (q, h, s), r in per_sample.items() if q == p and h == height and "mobilised" in r}
        for found in strained.values():
            for (q, h, s), (directory, result) in found.items():
                if q == p and h == height and s not in sliding and os.path.exists(
                        os.path.join(directory, "tangential.dump")):
                    grains = lammps_output.read_dump(os.path.join(directory, "grains.dump"))[-1]
                    contacts = lammps_output.read_dump(os.path.join(directory, "contacts.dump"))[-1]
                    summary = {key: _number(result[key]) for key in ("W", "h", "D") if key in result}
                    entry = contact_mobilisation(lammps_output.read_dump(os.path.join(directory, "tangential.dump"))[-1],
                                                 grains, contacts, summary)
                    network = network_moduli.network_moduli(grains, contacts, summary["W"], summary["h"])
                    entry.update({f"{key}_network": value for key, value in network.items()})
                    sliding[s] = entry
        entry = {"packings": len(sliding), "paper": PAPER_C33.get(p), "strains": {}}
        if sliding:
            rows = list(sliding.values())
            for key in ("mobilised", "mobilised_0.9", "mobilisation_mean", "C33_network", "C33_slipping") + tuple(
                    f"{name}_{t:g}" for t in MOBILISATION_THRESHOLDS for name in ("mobilised", "C33_without")):
                if all(key in r for r in rows):
                    entry[key] = mean_standard_error([r[key] for r in rows])
            entry["C22_slipping_over_network"] = mean_standard_error([r["C22_slipping"] / r["C22_network"]
                                                                      for r in rows])
        for e, found in strained.items():
            pairs = [(per_sample[(q, h, s)]["C33"], result["C33"]) for (q, h, s), (_, result) in found.items()
                     if q == p and h == height and (q, h, s) in per_sample]
            if pairs:
                entry["strains"][e] = {"pairs": len(pairs),
                                       "ratio": mean_standard_error([b / a for a, b in pairs]),
                                       "C33": mean_standard_error([b for _, b in pairs])}
        if sliding or entry["strains"]:
            out_entry[p] = entry
    return out_entry


def _se_cell(value, fmt="{:.3g}"):
    """mean ± standard error of a (mean, se) pair"""
    return f"{fmt.format(value[0])} ± {value[1]:.1g}"


def c33_sliding_table(sliding):
    """The Markdown lines of c33_and_sliding (pressure keys as text)"""
    strains = sorted({float(e) for c in sliding.values() for e in c["strains"]})
    lines = _table_head(["C33 and sliding at the contacts (H = 25 packings; mean ± standard error): the grain-grain contacts",
                         "at the Coulomb limit |F_t| = mu F_n (and above 0.9 mu F_n), the network's C33 with and without",
                         "their tangential springs, over Table II's; the same without the tangential springs of every",
                         "contact mobilised to m = |F_t|/(mu F_n) ≥ 0.8 or 0.6; the DEM's C33 measured at other strains on the same",
                         f"packings over C33 at the default strain ({DEFAULT_MODULI_STRAIN:g} of the overlap (3 p)^(2/3), "
                         "over h), and over Table II's"],
                        ["p", "packings", "at the limit", "above 0.9", "mean |F_t|/(mu F_n)", "C33 network / paper",
                         "C33 limit contacts slipping / paper", "C22 slipping / network"]
                        + [f"m ≥ {t:g}: share; C33 without their tangential springs / paper"
                           for t in MOBILISATION_THRESHOLDS]
                        + [f"C33(strain {e:g}) / C33 (pairs)" for e in strains]
                        + [f"C33(strain {e:g}) / paper" for e in strains])
    for p, c in sliding.items():
        paper = c["paper"]
        cells = [p, str(c["packings"])]
        if "mobilised" in c:
            cells += [_se_cell(c["mobilised"]), _se_cell(c["mobilised_0.9"]), _se_cell(c["mobilisation_mean"]),
                      f"{c['C33_network'][0] / paper:.2f}" if paper else "-",
                      f"{c['C33_slipping'][0] / paper:.2f}" if paper else "-",
                      _se_cell(c["C22_slipping_over_network"])]
        else:
            cells += ["-"] * 6
        for t in MOBILISATION_THRESHOLDS:
            share, without = c.get(f"mobilised_{t:g}"), c.get(f"C33_without_{t:g}")
            cells.append(f"{_se_cell(share)}; {without[0] / paper:.2f}" if share and without and paper else "-")
        for e in strains:
            found = c["strains"].get(e) or c["strains"].get(f"{e:g}") or c["strains"].get(str(e))
            cells.append(f"{_se_cell(found['ratio'])} ({found['pairs']})" if found else "-")
        for e in strains:
            found = c["strains"].get(e) or c["strains"].get(f"{e:g}") or c["strains"].get(str(e))
            cells.append(f"{found['C33'][0] / paper:.2f}" if found and paper else "-")
        lines.append("| " + " | ".join(cells) + " |")
    lines.append("")
    return lines


def piston_samples(out, height=25):
    """{(mass, speed): {(p, seed): sample_results}} of every finished sample
    of height H = height, at rest, made with another piston than the
    default one (study.py run --piston-mass / --piston-speed)"""
    found = {}
    for piston in pistons(out):
        if piston == DEFAULT_PISTON:
            continue
        rows = {}
        for (p, h, seed), (directory, result) in samples(out, piston).items():
            if h == height and result.get("at_rest"):
                rows[(p, seed)] = sample_results(directory, result)
        if rows:
            found[piston] = rows
    return found


PISTON_KEYS = ("phi2", "z_star", "sigma_ratio", "overshoot")


def c33_and_piston(per_sample, piston_results, pressures, height=25):
    """C33 against the piston, per pressure: the samples of each other piston
    (piston_samples) paired seed by seed with the default piston's
    (per_sample, H = height): Phi2, z*, sigma1/sigma2 and the overshoot of
    both, the network's C33 and the DEM's over the default piston's of the
    same seed, and the network's over Table II's (means and standard
    errors); {p: {piston name: {"pairs", key: (mean, se), "default": {key:
    (mean, se)}, "C33_network_ratio", "C33_ratio", "C33_network_over_paper"}}}"""
    entry = {}
    for p in pressures:
        by_piston = {}
        for (mass, speed), rows in piston_results.items():
            pairs = [(per_sample[(p, height, s)], r) for (q, s), r in sorted(rows.items())
                     if q == p and (p, height, s) in per_sample]
            if not pairs:
                continue
            c = {"pairs": len(pairs), "default": {}}
            for key in PISTON_KEYS:
                if all(key in a and key in b for a, b in pairs):
                    c[key] = mean_standard_error([b[key] for _, b in pairs])
                    c["default"][key] = mean_standard_error([a[key] for a, _ in pairs])
            for key in ("C33_network", "C33"):
                if all(key in a and key in b for a, b in pairs):
                    c[f"{key}_ratio"] = mean_standard_error([b[key] / a[key] for a, b in pairs])
            if "C33_network_ratio" in c and p in PAPER_C33:
                c["C33_network_over_paper"] = mean_standard_error([b["C33_network"] / PAPER_C33[p]
                                                                   for _, b in pairs])
            by_piston[f"mass {mass:g}, dashpot speed {speed:g}"] = c
        if by_piston:
            entry[p] = by_piston
    return entry


def c33_piston_table(by_pressure):
    """The Markdown lines of c33_and_piston (pressure keys as text)"""
    names = {"phi2": "Φ2", "z_star": "z*", "sigma_ratio": "σ1/σ2", "overshoot": "p_peak/p"}
    lines = _table_head(["C33 and the piston (H = 25 packings at rest, paired seed by seed with the default piston of",
                         f"mass {DEFAULT_PISTON[0]:g} and dashpot speed {DEFAULT_PISTON[1]:g}; mean ± standard error; "
                         "default piston's values in brackets)"],
                        ["p", "piston", "pairs"] + [names[k] for k in PISTON_KEYS]
                        + ["C33 network / default's", "C33 DEM / default's", "C33 network / paper"])
    for p, by_piston in by_pressure.items():
        for name, c in by_piston.items():
            cells = [p, name, str(c["pairs"])]
            for key in PISTON_KEYS:
                cells.append(f"{_se_cell(c[key])} ({c['default'][key][0]:.3g})" if key in c else "-")
            for key in ("C33_network_ratio", "C33_ratio", "C33_network_over_paper"):
                cells.append(_se_cell(c[key]) if key in c else "-")
            lines.append("| " + " | ".join(cells) + " |")
    lines.append("")
    return lines


def pressures_of(per_sample):
    """The pressures of the samples, in order"""
    return sorted({p for p, _, _ in per_sample})


def speed_pressures(results, pressures):
    """The pressures with a time-of-flight speed"""
    return [p for p in pressures if "c_tof_t10" in results["pressures"][f"{p:g}"]]


def collect_results(out, per_sample, off_target, not_at_rest):
    """The dict of results.json: each sample, the samples left out, the
    entry of each pressure (pressure_entry), the exponents of the speeds
    against the pressure, the 1D chain of out/chain, the correlation of the
    stress ratio with the overshoot, the heights at p = 1e-4, the checks
    beside Table I and those of the pistons (out: the jobs' directory)"""
    pressures = pressures_of(per_sample)
    results = {"samples": {f"p{p:g}_H{H}_s{s}": r for (p, H, s), r in per_sample.items()},
               "off_target": off_target, "not_at_rest": not_at_rest, "pressures": {}}
    for p in pressures:
        results["pressures"][f"{p:g}"] = pressure_entry(per_sample, p)

    # c_tof ~ p^x
    with_speed = speed_pressures(results, pressures)
    if len(with_speed) >= 2:
        x, _ = sound.power_law_fit(with_speed, [results["pressures"][f"{p:g}"]["c_tof_t10"][0]
                                                 for p in with_speed])
        results["c_tof_exponent"] = x
    for key in ("c_l", "c_t"):
        with_speed_key = [p for p in pressures if key in results["pressures"][f"{p:g}"]]
        if len(with_speed_key) >= 2:
            x, _ = sound.power_law_fit(with_speed_key, [results["pressures"][f"{p:g}"][key] for p in with_speed_key])
            results[f"{key}_exponent"] = x
            results[f"{key}_exponent_pressures"] = with_speed_key

    chain_found = chain_job(out)
    if chain_found:
        results["chain"] = chain_results(*chain_found)
    poly = [chain_results(*job) for job in chain_jobs(out) if job[1].get("poly")]
    if poly:
        results["chain_poly"] = {f"{c['poly']:g}": c for c in poly}

    lattice, lattice_series = lattice_summary(out)
    if lattice:
        results["lattice"] = lattice
        results["lattice_series"] = lattice_series

    # the stress ratio of every packing against the overshoot of its compression
    with_overshoot = overshoots(per_sample)
    if len(with_overshoot) >= 3:
        overshoot, ratio, _ = zip(*with_overshoot)
        results["log_overshoot_stress_ratio_correlation"] = float(np.corrcoef(np.log(overshoot), ratio)[0, 1])

    series = height_series(per_sample, 1e-4)
    if series:
        results["disordered_1e-4"] = series
    # Fig. 6's line: the 10 % arrivals of every sample at 1e-4, all heights
    arrivals = [(r["h"], r["t10_A"]) for key, r in per_sample.items() if key[0] == 1e-4 and "t10_A" in r]
    if len({h for h, _ in arrivals}) >= 2:
        results["arrival_fit_1e-4"] = sound.arrival_fit(*map(np.asarray, zip(*arrivals)))

    results["checks"] = checks_table(per_sample, pressures)
    results["c33_candidates"] = {f"{p:g}": c for p, c in c33_candidates(per_sample, pressures).items()}
    results["c33_sliding"] = {f"{p:g}": c for p, c in c33_and_sliding(out, per_sample, pressures).items()}
    # the same checks for every piston (mass, dashpot speed) at p = 1e-4, H = 25
    results["pistons"] = piston_checks(out)
    # C33 against the piston, every pressure, paired with the default piston
    results["c33_piston"] = {f"{p:g}": c for p, c in
                             c33_and_piston(per_sample, piston_samples(out), pressures).items()}
    frictionless = frictionless_results(usable_samples(out, FRICTIONLESS))
    if frictionless:
        results["frictionless"] = frictionless
    return results


def frictionless_results(usable):
    """results.json's "frictionless": the frictionless packings (mu = 0;
    usable: usable_samples(out, FRICTIONLESS)), apart from the frictional
    ones: each sample, those left out, the entry of each pressure
    (pressure_entry: statics of the H = 25 packings, moduli, network moduli
    of the frictionless network, c_tof from the H = 8 / 25 pairs) and c_tof
    against p; None without frictionless samples"""
    found, per_sample, off_target, not_at_rest = usable
    if not found:
        return None
    pressures = pressures_of(per_sample)
    results = {"mu": FRICTIONLESS, "samples": {f"p{p:g}_H{H}_s{s}": r for (p, H, s), r in per_sample.items()},
               "off_target": off_target, "not_at_rest": not_at_rest,
               "pressures": {f"{p:g}": pressure_entry(per_sample, p) for p in pressures}}
    with_speed = speed_pressures(results, pressures)
    if len(with_speed) >= 2:
        results["c_tof_exponent"], _ = sound.power_law_fit(
            with_speed, [results["pressures"][f"{p:g}"]["c_tof_t10"][0] for p in with_speed])
    return results


def _cell(entry, key, fmt="{:.3g}"):
    """entry[key] formatted: "mean ± s.d." of a pair, a string as it is, a
    dash when missing"""
    if key not in entry:
        return "-"
    value = entry[key]
    if isinstance(value, (list, tuple)):
        return (fmt + " ± " + fmt).format(*value)
    if isinstance(value, str):
        return value
    return fmt.format(value)


def _paper_cell(value):
    """a value of the paper's tables: "mean ± s.d.", or the mean alone"""
    mean, spread = value
    return f"{mean:g}" + (f" ± {spread:g}" if spread is not None else "")


def _table_head(titles, columns):
    """title lines, a blank line, the header and separator of a markdown table"""
    return titles + ["", "| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]


# paper 003, Table III: gamma and alpha (condition A unless B)
PAPER_TABLE_III = {"chain A": ("2/3", "1/3"), "chain B": ("1", "1/3"), "poly": ("≥ 2/3", "≥ 1/3"),
                   "lattice A": ("2/3", "1/3"), "lattice B": ("1", "1/3"), "2D": ("≈ 1.5", "≈ 1")}


def fitted_exponents(sizes, amplitude, width, smallest=64):
    """gamma and alpha of least-squares power laws A ~ L^-gamma, W ~ L^alpha
    over the sizes from `smallest` on (None with fewer than two)"""
    chosen = [k for k, n in enumerate(sizes) if n >= smallest]
    if len(chosen) < 2:
        return None
    gamma, _ = sound.power_law_fit([sizes[k] for k in chosen], [amplitude[k] for k in chosen])
    alpha, _ = sound.power_law_fit([sizes[k] for k in chosen], [width[k] for k in chosen])
    return -gamma, alpha


def lattice_table(results):
    """The time-of-flight speeds of the perfect triangular lattices beside
    Eqs. 18 (frictionless) and 19 (frictional, k_t = k_n, nu = 0)"""
    if not results.get("lattice"):
        return []
    lines = _table_head(["Perfect triangular lattices (in.lattice): c_tof from the rows nearest L = 8 and 25, by the "
                         "10 % arrival, the peak and the zero crossing, beside Eqs. 18-19; signals against the chain "
                         "of rows: largest relative deviation"],
                        ["job", "p", "M", "rows", "model", "c_tof (10 %)", "c_tof (peak)", "c_tof (zero)", "Eq. 18/19",
                         "c_tof (10 %) / Eq.", "vs row chain"])
    for name, entry in results["lattice"].items():
        for model, e in entry["models"].items():
            if "c_tof_t10" not in e:
                continue
            lines.append(f"| {name} | {entry['p']:g} | {entry['M']} | {e['pair'][0]}, {e['pair'][1]} | {e['name']} | "
                         f"{e['c_tof_t10']:.4f} | {e['c_tof_t_peak']:.4f} | {e['c_tof_t_zero']:.4f} | {e['eq']:.4f} | "
                         f"{e['c_tof_t10'] / e['eq']:.3f} | {entry['chain_deviation']:.1e} |")
    return lines + [""]


def table_iii(results):
    """Table III's rows beside the paper's: the exponents of the chains of
    identical and of polydisperse balls, of the triangular lattices and of
    the 2D packings at p = 1e-4 (effective exponents between the two largest
    sizes, ± their standard errors, and power laws fitted from N = 64 on);
    the width is width_of's throughout"""
    lines = _table_head(["Table III: γ (A ~ L^-γ) and α (W ~ L^α) of the coherent peak; width = first zero crossing "
                         "− 10 % arrival; effective exponents between the two largest sizes (± s.e. over the "
                         "realizations), and power laws fitted from N = 64 on"],
                        ["system", "condition", "paper γ", "paper α", "γ (two largest)", "α (two largest)",
                         "γ (fit)", "α (fit)", "sizes", "realizations"])

    chain = results.get("chain")

    def same_sizes(c):
        """the identical balls' exponents between the same two largest N"""
        if not chain or "gamma_eff" not in chain["A"]:
            return ""
        mono = chain["A"]
        pair = (c["N"][-2], c["N"][-1])
        for k in range(len(mono["N"]) - 1):
            if (mono["N"][k], mono["N"][k + 1]) == pair:
                return f" (identical balls, same N: {mono['gamma_eff'][k]:.3f}, {mono['alpha_eff'][k]:.3f})"
        return ""

    def row(name, paper_key, condition, c, unit="N", reference=""):
        if "gamma_eff" not in c:
            return
        fit = fitted_exponents(c["N"], c["amplitude"], c["width"])
        gamma, alpha = PAPER_TABLE_III[paper_key]
        lines.append(f"| {name} | {condition} | {gamma} | {alpha} | {c['gamma_eff'][-1]:.3f} ± "
                     f"{c['gamma_eff_se'][-1]:.3f} | {c['alpha_eff'][-1]:.3f} ± {c['alpha_eff_se'][-1]:.3f} | "
                     + (f"{fit[0]:.3f} | {fit[1]:.3f}" if fit else "- | -")
                     + f" | {unit} {c['N'][0]} … {c['N'][-1]}{reference} | {c.get('realizations', 1)} |")

    if chain:
        walls = "identical" if abs(chain["wall_spring_over_K"] - 1.0) < 1e-6 else "twice K"
        for condition in ("A", "B"):
            row(f"1D chain, identical balls (wall springs {walls})", f"chain {condition}", condition,
                dict(chain[condition], realizations=1))
    for w, c in results.get("chain_poly", {}).items():
        row(f"1D chain, diameters uniform in 1 ± {w}", "poly", "A", dict(c["A"], realizations=c["realizations"]),
            reference=same_sizes(c["A"]))
    for name, c in results.get("lattice_series", {}).items():
        row(f"triangular lattice, {name}", f"lattice {c['condition']}", c["condition"], c, unit="rows")
    e = results.get("pressures", {}).get("0.0001", {})
    if "gamma" in e:
        def spread(value):
            return f"{value[0]:.2f}" + (f" ± {value[1] / math.sqrt(e['samples']):.2f}" if e["samples"] > 1 else "")
        lines.append(f"| 2D disordered, p = 1e-4 | A | ≈ 1.5 | ≈ 1 | {spread(e['gamma'])} | {spread(e['alpha'])} "
                     f"| - | - | pairs H = 8, 25 of each seed | {e['samples']} pairs |")
    series = results.get("disordered_1e-4")
    if series:
        row("2D disordered, p = 1e-4, heights", "2D", "A", {"N": series["H"], **{k: series[k] for k in (
            "amplitude", "width", "gamma_eff", "gamma_eff_se", "alpha_eff", "alpha_eff_se")},
            "realizations": min(series["samples"])}, unit="H")
    return lines + [""]


def tables(results, pressures):
    """The text of tables.md: Table I beside the paper's, the acceptance
    checks, the pistons, Table II, the DEM over the network moduli, the
    speeds and the coherent peak, the packings left out, the exponents"""
    series = results.get("disordered_1e-4")
    lines = _table_head(["Table I (bulk of the H = 25 packings; paper: 30 samples per pressure)"],
                        ["p", "source", "samples", "Φ2", "Φ3", "Φ3*", "z*", "f0", "⟨N⟩/p", "Z(2)", "Z(3)", "F2",
                         "F2^S"])
    for p in pressures:
        e = results["pressures"][f"{p:g}"]
        if p in sound.PAPER_TABLE_I:
            lines.append(f"| {p:g} | paper 003 (2D) | 30 | " + " | ".join(
                _paper_cell(sound.PAPER_TABLE_I[p][k]) for k in
                ("phi2", "phi3", "phi3_star", "z_star", "f0", "mean_force_over_p", "Z2", "Z3", "F2",
                 "F2_strong")) + " |")
        lines.append(f"| {p:g} | ACOUSTIC | {e['tall_samples']} | " + " | ".join(
            _cell(e, k) for k in ("phi2", "phi3", "phi3_star", "z_star", "f0", "mean_force_over_p", "Z2", "Z3",
                                  "F2", "F2_strong")) + " |")
    lines.append("")
    lines += _table_head(["Acceptance checks of the H = 25 packings: ours mean ± standard error, the paper's mean",
                          "(± its standard deviation), and how many of our standard errors lie between them",
                          "(σ1/σ2: bulk contact virial of the packing at rest; paper: Table II)"],
                         ["p", "check", "samples", "ACOUSTIC", "paper 003", "|Δ| / s.e."])
    for row in results["checks"]:
        lines.append(f"| {row['p']:g} | {row['key']} | {row['samples']} | {row['mean']:.4g} ± "
                     f"{row['standard_error']:.2g} | {_paper_cell((row['paper'], row['paper_sd']))} | "
                     f"{row['standard_errors_off']:.1f} |")
    lines.append("")
    if results["pistons"]:
        columns = list(sound.CHECKS) + ["overshoot", "packing_steps"]
        lines += _table_head(["The piston (mass in units of the grains', dashpot speed: 0 = free): checks of the",
                              "H = 25 packings at p = 1e-4, mean ± standard error; "
                              "overshoot = p_peak / p at the checks"],
                             ["piston", "samples"] + columns)
        for name, entry in results["pistons"].items():
            lines.append(f"| {name} | {entry['samples']} | " + " | ".join(
                f"{entry[k][0]:.4g} ± {entry[k][1]:.2g}" if k in entry else "-" for k in columns) + " |")
        lines.append("")
    lines += _table_head(["Table II (H = 25 packings whose response stayed linear; mean ± standard deviation;",
                          "moduli samples: linear in compression and stretch / in shear)"],
                         ["p", "source", "σ1/σ2", "p_peak/p", "moduli samples", "C11", "C12", "C12 (from ε11)", "C22",
                          "C33"])
    for p in pressures:
        e = results["pressures"][f"{p:g}"]
        if p in PAPER_TABLE_II:
            ratio, c11, c12, c22, c33 = PAPER_TABLE_II[p]
            lines.append(f"| {p:g} | paper 003 (2D) | {ratio} | - | 30 | {c11} | {c12} | - | {c22} | {c33} |")
        lines.append(f"| {p:g} | ACOUSTIC | " + " | ".join(_cell(e, k) for k in (
            "sigma1_over_sigma2", "overshoot", "moduli_samples", "C11", "C12", "C12_from_eps11", "C22", "C33")) + " |")
        if "C22_network" in e:
            lines.append(f"| {p:g} | ACOUSTIC, network | - | - | {e['tall_samples']} | - | - | - | "
                         f"{_cell(e, 'C22_network')} | {_cell(e, 'C33_network')} |")
    lines.append("")
    lines += _table_head(["DEM moduli over network moduli, packing by packing (where the DEM response stayed linear)"],
                         ["p", "C22 (DEM / network)", "C33 (DEM / network)"])
    for p in pressures:
        e = results["pressures"][f"{p:g}"]
        lines.append(f"| {p:g} | {_cell(e, 'C22_dem_over_network')} | {_cell(e, 'C33_dem_over_network')} |")
    lines.append("")
    if results.get("c33_candidates"):
        lines += _table_head(["C33 against two candidate causes of its excess, within our H = 25 packings: the line",
                              "C33(z*) read at the paper's z*, and the line C33(log p_peak/p) read at the smallest "
                              "overshoot"],
                             ["p", "samples", "C33 (ours / paper)", "z* (ours / paper)", "dC33/dz*",
                              "C33 at the paper's z* / paper", "r(C33, log p_peak/p)",
                              "C33 at the least overshoot / paper"])
        for p, c in results["c33_candidates"].items():
            lines.append(f"| {p} | {c['samples']} | {c['C33']:.3g} / {c['paper']:.3g} ({c['C33'] / c['paper']:.2f}) | "
                         f"{c['z_star']:.3f} / {c['paper_z_star']:.2f} | {c['slope_z']:.2g} ± {c['slope_z_se']:.1g} | "
                         f"{c['C33_at_paper_z'] / c['paper']:.2f} | {c['r_overshoot']:+.2f} | "
                         f"{c['C33_at_least_overshoot'] / c['paper']:.2f} (p_peak/p = {c['least_overshoot']:.3g}) |")
        lines.append("")
    if results.get("c33_sliding"):
        lines += c33_sliding_table(results["c33_sliding"])
    if results.get("c33_piston"):
        lines += c33_piston_table(results["c33_piston"])
    for title, paper_table, keys in (
            ("Table IV (Appendix B, Eq. B2): apparent moduli of forces f0 sin(n π y / L2) on the non-rattlers, walls "
             "held, over the global moduli of the same contact network (H = 25 packings; mean ± s.d.)",
             PAPER_TABLE_IV, [("C22", "force", 1), ("C22", "force", 2), ("C22", "force", 3), ("C33", "force", 1),
                              ("C33", "force", 2), ("C33", "force", 3)]),
            ("Table V (Appendix B, Eq. B3): apparent moduli of displacements imposed on the grains crossed by n + 2 "
             "lines, over the global moduli of the same contact network (H = 25 packings; mean ± s.d.)",
             PAPER_TABLE_V, [("C22", "lines", 1), ("C22", "lines", 3), ("C33", "lines", 1), ("C33", "lines", 3)])):
        mark = "~" if keys[0][1] == "force" else "^"
        columns = [f"C{mark}{m[1:]}({n})/{m}" for m, _, n in keys]
        lines += _table_head([title], ["p", "source", "samples"] + columns)
        for p in pressures:
            e = results["pressures"][f"{p:g}"]
            if not any(f"{m}_{kind}{n}_ratio" in e for m, kind, n in keys):
                continue
            if p in paper_table:
                # the paper has n = 1, 2 (IV) or 1, 3 (V) only
                paper = dict(zip([k for k in keys if k[2] != 3] if keys[0][1] == "force" else keys, paper_table[p]))
                lines.append(f"| {p:g} | paper 003 | 30 | " + " | ".join(paper.get(k, "-") for k in keys) + " |")
            lines.append(f"| {p:g} | ACOUSTIC | {e['tall_samples']} | " + " | ".join(
                _cell(e, f"{m}_{kind}{n}_ratio") for m, kind, n in keys) + " |")
        lines.append("")
    lines += _table_head(["Speeds and the coherent peak (c_tof from the H = 8 and H = 25 packings of each seed)"],
                         ["p", "pairs", "c_tof (10 %)", "c_tof (peak)", "c_tof (zero)", "c_ℓ", "c_t", "c_tof/c_ℓ",
                          "paper c_ℓ (Table II)", "γ (L 8-25)", "α (L 8-25)"])
    for p in pressures:
        e = results["pressures"][f"{p:g}"]
        paper_c_l = "-"
        if p in PAPER_TABLE_II:
            paper_c_l = f"{math.sqrt(PAPER_C22_PHI3STAR[p][0] / PAPER_C22_PHI3STAR[p][1]):.3g}"
        lines.append(f"| {p:g} | {e['samples']} | " + " | ".join(_cell(e, k) for k in (
            "c_tof_t10", "c_tof_t_peak", "c_tof_t_zero", "c_l", "c_t", "c_tof_over_c_l")) +
            f" | {paper_c_l} | " + " | ".join(_cell(e, k) for k in ("gamma", "alpha")) + " |")
    lines.append("")
    lines += lattice_table(results)
    lines += table_iii(results)
    lines.append(f"packings left out (final pressure more than 5 % from the target): {results['off_target'] or 'none'}")
    lines.append(f"packings left out (not at rest within the deck's max_checks): {results['not_at_rest'] or 'none'}")
    if "log_overshoot_stress_ratio_correlation" in results:
        lines.append("")
        lines.append("correlation of sigma1/sigma2 with log(p_peak/p) over all packings: "
                     f"{results['log_overshoot_stress_ratio_correlation']:.3f}")
    if "arrival_fit_1e-4" in results:
        fit = results["arrival_fit_1e-4"]
        lines.append("")
        lines.append(f"Fig. 6 (p = 1e-4): the line through the 10 % arrivals of {fit['samples']} samples, "
                     f"L = {fit['L_min']:.1f} ... {fit['L_max']:.1f}: 1/slope = {fit['speed']:.4f}, "
                     f"intercept {fit['intercept']:.2f} (paper's fit: c_tof = 0.25)")
    if "c_tof_exponent" in results:
        lines.append("")
        lines.append(f"c_tof ∝ p^x with x = {results['c_tof_exponent']:.4f} (paper: 1/6 = 0.1667)")
        for key, paper in (("c_l", "0.18"), ("c_t", "0.23")):
            if f"{key}_exponent" in results:
                lines.append(f"{key} ∝ p^x with x = {results[key + '_exponent']:.3f} over p = "
                             f"{results[key + '_exponent_pressures']} (paper: {paper})")
    for name, chain in [("chain", results.get("chain"))] + [
            (f"chain poly {w}", c) for w, c in results.get("chain_poly", {}).items()]:
        if not chain:
            continue
        for condition in ("A", "B"):
            c = chain[condition]
            if "gamma_eff" in c:
                lines.append(f"{name} {condition}: N {c['N']}, gamma_eff {np.round(c['gamma_eff'], 3).tolist()}, "
                             f"alpha_eff (width) {np.round(c['alpha_eff'], 3).tolist()}")
    if series:
        lines.append(f"p = 1e-4, condition A, heights: H {series['H']}, samples {series['samples']}, "
                     f"L {np.round(series['L'], 2).tolist()}, gamma_eff {np.round(series['gamma_eff'], 3).tolist()}, "
                     f"alpha_eff {np.round(series['alpha_eff'], 3).tolist()}")
    if results.get("frictionless"):
        lines += [""] + frictionless_tables(results["frictionless"])
    return "\n".join(lines)


def frictionless_tables(frictionless):
    """The lines of tables.md on the frictionless packings (results.json's
    "frictionless"), after every table of the frictional ones: Table I's
    rows "ACOUSTIC, frictionless", Table II's (moduli of the DEM at mu = 0
    and of the frictionless network; C33 is zero: flat frictionless walls
    carry no shear), the speeds of the H = 8 / 25 pairs"""
    pressures = sorted(float(p) for p in frictionless["pressures"])
    lines = ["## Frictionless packings (mu = 0; paper 003 Fig. 4(c): measured on the frictionless network, "
             "model normal)", ""]
    lines += _table_head(["Table I, frictionless (bulk of the H = 25 packings; the paper gives no frictionless "
                          "table)"],
                         ["p", "source", "samples", "Φ2", "Φ3", "Φ3*", "z*", "f0", "⟨N⟩/p", "Z(2)", "Z(3)", "F2",
                          "F2^S", "σ1/σ2"])
    for p in pressures:
        e = frictionless["pressures"][f"{p:g}"]
        lines.append(f"| {p:g} | ACOUSTIC, frictionless | {e['tall_samples']} | " + " | ".join(
            _cell(e, k) for k in ("phi2", "phi3", "phi3_star", "z_star", "f0", "mean_force_over_p", "Z2", "Z3",
                                  "F2", "F2_strong", "sigma_ratio")) + " |")
    lines.append("")
    lines += _table_head(["Table II, frictionless (H = 25 packings whose compression and stretch stayed linear; "
                          "C33: zero, flat frictionless walls carry no shear)"],
                         ["p", "source", "σ1/σ2", "moduli samples", "C11", "C12", "C12 (from ε11)", "C22"])
    for p in pressures:
        e = frictionless["pressures"][f"{p:g}"]
        lines.append(f"| {p:g} | ACOUSTIC, frictionless | " + " | ".join(_cell(e, k) for k in (
            "sigma1_over_sigma2", "moduli_samples", "C11", "C12", "C12_from_eps11", "C22")) + " |")
        if "C22_network" in e:
            lines.append(f"| {p:g} | ACOUSTIC, frictionless network | - | {e['tall_samples']} | - | - | - | "
                         f"{_cell(e, 'C22_network')} |")
    lines.append("")
    lines += _table_head(["Speeds and the coherent peak, frictionless (c_tof from the H = 8 and H = 25 packings "
                          "of each seed)"],
                         ["p", "pairs", "c_tof (10 %)", "c_tof (peak)", "c_tof (zero)", "c_ℓ", "c_tof/c_ℓ",
                          "γ (L 8-25)", "α (L 8-25)"])
    for p in pressures:
        e = frictionless["pressures"][f"{p:g}"]
        lines.append(f"| {p:g} | {e['samples']} | " + " | ".join(_cell(e, k) for k in (
            "c_tof_t10", "c_tof_t_peak", "c_tof_t_zero", "c_l", "c_tof_over_c_l", "gamma", "alpha")) + " |")
    lines.append("")
    lines.append(f"frictionless packings left out (final pressure more than 5 % from the target): "
                 f"{frictionless['off_target'] or 'none'}")
    lines.append(f"frictionless packings left out (not at rest within the deck's max_checks): "
                 f"{frictionless['not_at_rest'] or 'none'}")
    if "c_tof_exponent" in frictionless:
        lines.append(f"frictionless: c_tof ∝ p^x with x = {frictionless['c_tof_exponent']:.4f}")
    return lines


def fig5_signals(per_sample, found):
    """Fig. 5's signals: (p, {label: (t, mean F_sig)}) of the heights at the
    highest pressure with at least two heights (the ensemble mean of each
    height's packings, condition A), or None"""
    for p in sorted({q for q, _, _ in per_sample}, reverse=True):
        heights = sorted({H for q, H, _ in per_sample if q == p})
        if len(heights) < 2:
            continue
        signals = {}
        for height in heights:
            keys = sorted(key for key in per_sample if key[0] == p and key[1] == height)
            t, mean, _ = sound.ensemble([sound.read_pulse(os.path.join(found[key], "pulse_A.dat")) for key in keys])
            length = np.mean([per_sample[key]["h"] for key in keys])
            signals[f"H = {height} (L = {length:.1f}), {len(keys)} packings"] = (t, mean)
        return p, signals
    return None


def lattice_points(results):
    """Fig. 8's lattice points: c_tof (10 %) of the lattice jobs of the
    packings' width, frictionless and frictional, against p"""
    points = {}
    for entry in results.get("lattice", {}).values():
        if entry["M"] < 8:
            continue
        for e in entry["models"].values():
            if "c_tof_t10" in e:
                ps, cs = points.setdefault(f"triangular lattice, {e['name']} (L 8, 25)", ([], []))
                ps.append(entry["p"])
                cs.append(e["c_tof_t10"])
    return points


def figures(results, per_sample, found, figdir, out=None):
    """Paper 003's Figs. 4, 5, 6, 7, 8, 9 and 12 and sigma1/sigma2 against
    the overshoot (sound_figures) into figdir, from the results of
    collect_results, the sample_results of the samples (per_sample), their
    directories (found) and (Fig. 12) the chain and lattice jobs of out"""
    at = {key: r for key, r in per_sample.items() if key[0] == 1e-4}
    tall = [(key, r) for key, r in at.items() if key[1] == 25]
    if tall:
        signals = [sound.read_pulse(os.path.join(found[key], "pulse_A.dat")) for key, _ in tall]
        sound_figures.fig4_signals(signals, sound.ensemble(signals), os.path.join(figdir, "fig4_signal_p1e-4.png"),
                                   "p = 1e-4, L ≈ 25, initial condition A")
        first = tall[0][0]
        modes = lammps_output.read_ave_time_vector(os.path.join(found[first], "modes.dat"))[-1][1][:, 0]
        sound_figures.fig9_spectrum(modes, os.path.join(figdir, "fig9_spectrum_p1e-4.png"),
                                    "p = 1e-4, L ≈ 25 (rattlers: zero modes)")
    if at:
        keys = sorted(at)
        sound_figures.fig6_arrival_times([at[k]["h"] for k in keys], [at[k]["t10_A"] for k in keys],
                                         [at[k]["t_peak_A"] for k in keys], [at[k]["t_zero_A"] for k in keys],
                                         os.path.join(figdir, "fig6_arrival_p1e-4.png"), "p = 1e-4")
    with_speed = speed_pressures(results, pressures_of(per_sample))
    if with_speed:
        e = [results["pressures"][f"{p:g}"] for p in with_speed]
        sound_figures.fig8_speeds(with_speed, [x["c_tof_t10"][0] for x in e], [x["c_tof_t10"][1] for x in e],
                                  [x.get("c_l", np.nan) for x in e], [x.get("c_t", np.nan) for x in e],
                                  os.path.join(figdir, "fig8_speeds.png"), lattice_points(results))
    curves = {}
    if "chain" in results:
        for condition in ("A", "B"):
            c = results["chain"][condition]
            if len(c["N"]) >= 2:
                curves[f"1D chain, identical balls, {condition}"] = (c["N"], c["amplitude"], c["width"])
    for w, chain in results.get("chain_poly", {}).items():
        c = chain["A"]
        if len(c["N"]) >= 2:
            curves[f"1D chain, d in 1 ± {w}, A ({chain['realizations']} chains)"] = (
                c["N"], c["amplitude"], c["width"], c["amplitude_se"], c["width_se"])
    for name, c in results.get("lattice_series", {}).items():
        if c["condition"] == "A" and len(c["N"]) >= 2:
            curves[f"triangular lattice, {name} (rows)"] = (c["N"], c["amplitude"], c["width"])
    if "disordered_1e-4" in results:
        d = results["disordered_1e-4"]
        curves["2D disordered packings, p = 1e-4, A"] = (d["L"], d["amplitude"], d["width"], d["amplitude_se"],
                                                         d["width_se"])
    front = front_curves(out) if out else {}
    if front:
        sound_figures.fig12_shapes(front, os.path.join(figdir, "fig12_shapes.png"),
                                   "condition A, p = 1e-4: chains with identical wall springs,\n"
                                   "lattices between rigid walls (per ball of a row)")
    heights = fig5_signals(per_sample, found)
    if heights:
        sound_figures.fig5_heights(heights[1], os.path.join(figdir, "fig5_heights.png"),
                                   f"p = {heights[0]:g}, condition A: ensemble mean of each height")
    with_overshoot = overshoots(per_sample)
    if with_overshoot:
        sound_figures.stress_ratio_against_overshoot(*zip(*with_overshoot),
                                                     os.path.join(figdir, "stress_ratio_overshoot.png"))
    if curves:
        sound_figures.fig7_exponents(curves, os.path.join(figdir, "fig7_exponents.png"))


def frictionless_figures(usable, figdir):
    """Fig. 4(c) and (d) (paper 003: "(c) 2D frictionless and (d) 3D
    frictionless systems exhibit similar behavior"): F_sig of the
    frictionless H = 25 packings at p = 1e-4 (usable: usable_samples(out,
    FRICTIONLESS)), each in grey, their ensemble mean and RMS deviation,
    into figdir/fig4c_signal_frictionless_p1e-4.png (2D) or
    fig4d_signal_frictionless_3d_p1e-4.png (3D packings, D > 0); the
    number of packings drawn (0: none, no figure)"""
    found, per_sample, _, _ = usable
    tall = sorted(key for key in per_sample if key[0] == 1e-4 and key[1] == 25)
    if not tall:
        return 0
    signals = [sound.read_pulse(os.path.join(found[key], "pulse_A.dat")) for key in tall]
    if per_sample[tall[0]].get("D"):
        name, title = "fig4d_signal_frictionless_3d_p1e-4.png", "3D frictionless spheres (μ = 0)"
    else:
        name, title = "fig4c_signal_frictionless_p1e-4.png", "2D frictionless (μ = 0)"
    sound_figures.fig4_signals(signals, sound.ensemble(signals), os.path.join(figdir, name),
                               f"{title}, p = 1e-4, L ≈ 25\ncondition A: {len(tall)} packings")
    return len(tall)


def figures_job(out):
    """(directory, settings, result) of the finished job of in.figures
    (kind "figures", study.py figures-run) in out, or None"""
    for directory, settings, result in study.finished_jobs(out):
        if settings.get("kind") == "figures":
            return directory, settings, result
    return None


def _dump_columns(path):
    """x, y, radius and the displacements x, y of a dump of in.figures"""
    snapshot = lammps_output.read_dump(path)[-1]
    return [np.asarray(snapshot[k], dtype=float) for k in range(1, 6)]


ORDINALS = ("", "second-", "third-", "fourth-", "fifth-")


def mode_kind(index, selected):
    """the kind of a mode of Fig. 10 (index into the ascending modes;
    selected: sound_modes.selected_modes): the lowest non-zero modes by
    their rank among the non-zero ones (lowest, second-lowest, ...), a mode
    of large |a_n b_n|, or the localised mode of high frequency"""
    names = {"strongest": "large $|a_n b_n|$", "localised": "localised, high $f$"}
    for kind, indices in selected.items():
        if index in indices:
            if kind == "lowest":
                return f"{ORDINALS[sorted(indices).index(index)]}lowest non-zero"
            return names[kind]
    raise ValueError(f"mode {index} is none of the selected modes {selected}")


def packing_figures(out, per_sample, found, figdir):
    """Figs. 1, 2, 9 (from the samples at p = 1e-4, H = 25: the first, or
    the one of the figures job, for the network and the modes; all of them
    for the histograms) and Figs. 3, 10, 11 (from the figures job of
    in.figures, when there is one) into figdir; what they show, for
    results.json"""
    tall = sorted(key for key in per_sample if key[0] == 1e-4 and key[1] == 25)
    if not tall:
        return {}
    job = figures_job(out)
    chosen = tall[0]
    if job:
        chosen = next((key for key in tall if os.path.basename(found[key]) == job[1]["sample"]), chosen)
    result = per_sample[chosen]
    width, height = result["W"], result["h"]
    shown = {"sample": os.path.basename(found[chosen]), "packings": len(tall)}

    # Figs. 1 and 2: the networks of the packings at 1e-4
    forces, stiffnesses, directions = [], [], []
    for key in tall:
        grains = lammps_output.read_dump(os.path.join(found[key], "grains.dump"))[-1]
        contacts = lammps_output.read_dump(os.path.join(found[key], "contacts.dump"))[-1]
        between_grains = (np.asarray(contacts[1]) != 0) & (np.asarray(contacts[2]) > 0)
        forces.append(np.asarray(contacts[2])[between_grains])
        stiffnesses.append(np.asarray(contacts[3])[between_grains])
        directions.append(sound_modes.contact_directions(grains, contacts, per_sample[key]["W"],
                                                         per_sample[key]["h"]))
    f, k = np.concatenate(forces), np.concatenate(stiffnesses)
    shown["force_cv"], shown["stiffness_cv"] = float(f.std() / f.mean()), float(k.std() / k.mean())
    data = packing_modes(found[chosen], {"W": width, "h": height})
    segments = sound_modes.network_segments(data["grains"], data["contacts"], width, height)
    sound_figures.fig1_network(data["grains"], segments, f, k, width, height,
                               os.path.join(figdir, "fig1_network_p1e-4.png"),
                               f"p = 1e-4: (a), (b) {shown['sample']}; (c) {len(tall)} packings, "
                               "grain-grain contacts")
    histogram = sound_modes.direction_histogram(directions)
    shown["F2"] = {name: histogram[name]["F2"] for name in ("all", "strong", "weak")}
    sound_figures.fig2_directions(histogram, os.path.join(figdir, "fig2_directions_p1e-4.png"),
                                  f"p = 1e-4, bulk contacts (3 d from the walls) of {len(tall)} packings")

    # Fig. 9: the spectrum and the modes' contributions of the chosen packing
    found_modes = data["modes"]
    if job:
        marked = [m - 1 for m in job[2]["modes"]]
        selected = job[2]["selected"]
    else:
        selected = data["selected"]
        marked = sorted(i for indices in selected.values() for i in indices)
    zero_modes = int(found_modes["zero"].sum())
    sound_figures.fig9_modes(found_modes["omega"] ** 2, found_modes["contribution"], marked, zero_modes,
                             os.path.join(figdir, "fig9_modes_p1e-4.png"), f"p = 1e-4, {shown['sample']}")
    contribution = np.abs(found_modes["contribution"])
    shown.update({"zero_modes": zero_modes, "modes": len(found_modes["omega"]),
                  "signal_deviation": data["signal_deviation"],
                  "modes_for_half_of_sum_abs_contribution": int(np.searchsorted(
                      np.cumsum(np.sort(contribution)[::-1]), 0.5 * contribution.sum()) + 1),
                  "marked": [{"n": int(i), "kind": mode_kind(i, selected),
                              "f": float(found_modes["omega"][i] / (2 * math.pi)),
                              "a_n_b_n": float(found_modes["contribution"][i]),
                              "participation": float(data["participation"][i])} for i in marked]})
    if not job:
        return shown

    # Figs. 3, 10, 11: the outputs of in.figures
    directory, settings, _ = job
    x, y, radius, ux, uy = _dump_columns(os.path.join(directory, "snapshot.dump"))
    sound_figures.fig3_snapshot(x, y, radius, ux, uy, width, height, settings["Tsnap"],
                                os.path.join(figdir, "fig3_snapshot_p1e-4.png"), f"p = 1e-4, {shown['sample']}")
    shown["snapshot_time"] = settings["Tsnap"]
    shapes = []
    for m in settings["modes"]:
        x, y, radius, ux, uy = _dump_columns(os.path.join(directory, f"mode_{m}.dump"))
        i = m - 1
        shapes.append((f"n = {i}\n{mode_kind(i, selected)}\n$f$ = {found_modes['omega'][i] / (2 * math.pi):.3g}, "
                       f"PR = {data['participation'][i]:.2g}", x, y, radius, ux, uy))
    sound_figures.fig10_modes(shapes, width, height, os.path.join(figdir, "fig10_modes_p1e-4.png"),
                              f"p = 1e-4, {shown['sample']}: n from 0 ({zero_modes} zero modes first), "
                              f"$f$ in {sound_figures.FREQUENCY_UNIT},\n"
                              f"PR the participation ratio; arrows: the translations, the largest "
                              f"{sound_figures.ARROWS_LARGEST:g} $d$ long")
    damped = {0.0: sound.read_pulse(os.path.join(found[chosen], "pulse_A.dat"))}
    for zeta in settings["damping"]:
        damped[float(zeta)] = sound.read_pulse(os.path.join(directory, f"pulse_damped_{zeta:g}.dat"))
    sound_figures.fig11_damping(damped, os.path.join(figdir, "fig11_damping_p1e-4.png"),
                                f"p = 1e-4, {shown['sample']}, condition A; dashpots on every contact")
    shown["damping"] = {}
    for zeta, (t, f) in sorted(damped.items()):
        peak = sound.coherent_peak(t, f)
        late = t > peak["t_zero"] + (peak["t_zero"] - peak["t10"])
        shown["damping"][f"{zeta:g}"] = {"amplitude": peak["amplitude"], "t10": peak["t10"],
                                         "rms_after_peak": float(np.sqrt(np.mean(f[late] ** 2)))}
    return shown


def collect(out):
    """What study.py collect does: results.json and tables.md into out, the
    tables on stdout"""
    found, per_sample, off_target, not_at_rest = usable_samples(out)
    results = collect_results(out, per_sample, off_target, not_at_rest)
    with open(os.path.join(out, "results.json"), "w") as handle:
        json.dump(results, handle, indent=1, default=float)
    text = tables(results, pressures_of(per_sample))
    with open(os.path.join(out, "tables.md"), "w") as handle:
        handle.write(text + "\n")
    print(text)


def draw(out, figdir):
    """What study.py figures does: the figures of the jobs of out into
    figdir (from the jobs themselves: collect need not have run)"""
    os.makedirs(figdir, exist_ok=True)
    found, per_sample, off_target, not_at_rest = usable_samples(out)
    results = collect_results(out, per_sample, off_target, not_at_rest)
    figures(results, per_sample, found, figdir, out)
    frictionless_figures(usable_samples(out, FRICTIONLESS), figdir)
    shown = packing_figures(out, per_sample, found, figdir)
    if shown:
        with open(os.path.join(out, "packing_figures.json"), "w") as handle:
            json.dump(shown, handle, indent=1, default=float)
        print(json.dumps(shown, indent=1, default=float))
