"""Analysis of pulse-propagation runs in confined granular packings (paper 003).

Reads the outputs of compute vibration/pulse (through fix ave/time ... mode
vector file), of dumps of grains and contacts, and turns them into paper
003's quantities: arrival times of the coherent peak (10 % of the first
peak, the peak, the first zero crossing), the time-of-flight speed from two
source-detector distances, amplitude A(L) ~ L^-gamma and width W(L) ~
L^alpha with their effective exponents, ensemble mean and RMS of the
signal, the static characterisation of Table I and the sound speeds of the
moduli of Table II.  numpy only; usable on any run with the same outputs.
"""
import math

import numpy as np

from .lammps_output import read_ave_time_vector


# ---------------------------------------------------------------------------
# files

def read_pulse(path):
    """(t, F_sig) of the last block written by compute vibration/pulse."""
    rows = read_ave_time_vector(path)[-1][1]
    return rows[:, 0], rows[:, 1]


# ---------------------------------------------------------------------------
# the coherent peak

def coherent_peak(t, signal, floor=0.01):
    """Arrival times and shape of the coherent peak of a pulse signal: the
    first local maximum of F above `floor` times max |F| (the front; paper 003
    Fig. 6 inset).  Returns a dict with
      amplitude  the value of that maximum (parabolic interpolation)
      t_peak     its time
      t10        first crossing of 10 % of the amplitude before it (linear)
      t_zero     first zero crossing after it (linear)
      width      t_zero - t10
    """
    t = np.asarray(t, dtype=float)
    f = np.asarray(signal, dtype=float)
    threshold = floor * np.abs(f).max()
    top = None
    for k in range(1, len(f) - 1):
        if f[k] >= threshold and f[k] >= f[k - 1] and f[k] > f[k + 1]:
            top = k
            break
    if top is None:
        raise ValueError("no coherent peak: the signal has no maximum above "
                         f"{floor} of its largest value (is the duration long enough?)")
    a, b, c = f[top - 1], f[top], f[top + 1]
    denominator = a - 2.0 * b + c
    shift = 0.5 * (a - c) / denominator if denominator != 0.0 else 0.0
    h = t[top + 1] - t[top]
    t_peak = t[top] + shift * h
    amplitude = b - 0.25 * (a - c) * shift
    level = 0.1 * amplitude
    k = top
    while k > 0 and f[k] > level:
        k -= 1
    t10 = t[k] + (level - f[k]) * (t[k + 1] - t[k]) / (f[k + 1] - f[k])
    k = top
    while k + 1 < len(f) and f[k + 1] > 0.0:
        k += 1
    if k + 1 >= len(f):
        t_zero = float("nan")
    else:
        t_zero = t[k] + f[k] * (t[k + 1] - t[k]) / (f[k] - f[k + 1])
    return {"amplitude": amplitude, "t_peak": t_peak, "t10": t10, "t_zero": t_zero,
            "width": t_zero - t10}


def time_of_flight_speed(distance1, time1, distance2, time2):
    """c_tof = (L2 - L1) / (t2 - t1): paper 003's definition with the arrival
    times at 10 % of the peak for L = 8 and 25"""
    return (distance2 - distance1) / (time2 - time1)


def arrival_fit(distance, t10):
    """Paper 003 Fig. 6's slope: the least-squares line t10 = L / c + t0
    through the 10 % arrivals of every sample, {"speed": c, "intercept": t0,
    "L_min", "L_max": the range of L it is fitted on, "samples"}"""
    slope, intercept = np.polyfit(distance, t10, 1)
    return {"speed": 1.0 / slope, "intercept": intercept, "L_min": float(np.min(distance)),
            "L_max": float(np.max(distance)), "samples": len(distance)}


def power_law_fit(x, y):
    """least-squares fit y = a x^b in log-log: (b, a)"""
    slope, intercept = np.polyfit(np.log(x), np.log(y), 1)
    return slope, math.exp(intercept)


def effective_exponents(x, y):
    """local slopes d log y / d log x between successive points: (x_mid, slopes),
    x_mid the geometric means"""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    slopes = np.diff(np.log(y)) / np.diff(np.log(x))
    return np.sqrt(x[1:] * x[:-1]), slopes


def effective_exponents_se(x, y, y_se):
    """effective_exponents with the standard errors of the slopes, y being
    independent means with standard errors y_se: (x_mid, slopes, errors)"""
    x_mid, slopes = effective_exponents(x, y)
    relative = np.asarray(y_se, dtype=float) / np.asarray(y, dtype=float)
    return x_mid, slopes, np.hypot(relative[1:], relative[:-1]) / np.diff(np.log(np.asarray(x, dtype=float)))


def ensemble(signals):
    """mean and root-mean-square deviation of several signals (t, F) on the
    time grid of the first one, up to the shortest duration: (t, mean, rms)"""
    t0 = np.asarray(signals[0][0], dtype=float)
    end = min(float(np.asarray(t)[-1]) for t, _ in signals)
    grid = t0[t0 <= end]
    stack = np.array([np.interp(grid, t, f) for t, f in signals])
    mean = stack.mean(axis=0)
    rms = np.sqrt(((stack - mean) ** 2).mean(axis=0))
    return grid, mean, rms


# ---------------------------------------------------------------------------
# statics (paper 003 Table I) and moduli (Table II)

# paper 003, Table I (mean, one standard deviation of the packings or None
# where the paper gives none), and the stress ratio of its Table II
PAPER_TABLE_I = {
    1e-7: {"phi2": (0.818, 0.005), "phi3": (0.561, 0.005), "phi3_star": (0.48, 0.01),
           "z_star": (3.18, 0.03), "f0": (0.15, 0.02), "mean_force_over_p": (1.31, None),
           "Z2": (1.49, None), "Z3": (2.81, None), "F2": (0.527, None), "F2_strong": (0.557, None),
           "sigma_ratio": (0.79, 0.06)},
    1e-6: {"phi2": (0.814, 0.004), "phi3": (0.558, 0.005), "phi3_star": (0.49, 0.01),
           "z_star": (3.23, 0.04), "f0": (0.14, 0.02), "mean_force_over_p": (1.27, None),
           "Z2": (1.50, None), "Z3": (2.83, None), "F2": (0.524, None), "F2_strong": (0.560, None),
           "sigma_ratio": (0.79, 0.06)},
    1e-5: {"phi2": (0.809, 0.004), "phi3": (0.554, 0.005), "phi3_star": (0.50, 0.01),
           "z_star": (3.31, 0.03), "f0": (0.11, 0.02), "mean_force_over_p": (1.22, None),
           "Z2": (1.49, None), "Z3": (2.77, None), "F2": (0.523, None), "F2_strong": (0.558, None),
           "sigma_ratio": (0.78, 0.06)},
    1e-4: {"phi2": (0.815, 0.005), "phi3": (0.558, 0.005), "phi3_star": (0.52, 0.01),
           "z_star": (3.48, 0.03), "f0": (0.074, 0.015), "mean_force_over_p": (1.06, None),
           "Z2": (1.51, None), "Z3": (2.90, None), "F2": (0.524, None), "F2_strong": (0.578, None),
           "sigma_ratio": (0.71, 0.04)},
}

# the acceptance checks of a packing, in the order of the paper's Table I
CHECKS = ("phi2", "z_star", "f0", "mean_force_over_p", "Z2", "Z3", "F2", "F2_strong",
          "sigma_ratio")


def paper_row(pressure):
    """Table I's row at the paper's pressure nearest to `pressure` (in log)"""
    nearest = min(PAPER_TABLE_I, key=lambda q: abs(math.log(q / pressure)))
    return nearest, PAPER_TABLE_I[nearest]


def rattlers(ids, contacts_i, contacts_j, minimum=2):
    """IDs of the rattlers: grains left with fewer than `minimum` contacts when
    such grains are removed one after the other (wall contacts, j = 0, count)"""
    ids = [int(i) for i in ids]
    neighbours = {i: [] for i in ids}
    for a, b in zip(contacts_i, contacts_j):
        a, b = int(a), int(b)
        if a in neighbours:
            neighbours[a].append(b)
        if b != 0 and b in neighbours:
            neighbours[b].append(a)
    removed = set()
    changed = True
    while changed:
        changed = False
        for i in ids:
            if i in removed:
                continue
            alive = [j for j in neighbours[i] if j == 0 or j not in removed]
            if len(alive) < minimum:
                removed.add(i)
                changed = True
    return removed


def static_properties(grains, contacts, width, height, pressure, boundary=3.0, depth=None):
    """Paper 003's Table I for one packing: solid fractions Phi2, Phi3 and
    Phi3* (without rattlers; a 2D layer counts as one diameter thick, a 3D
    packing of the given depth has no Phi2), coordination z* of the non-rattlers, fraction
    of rattlers f0, mean normal force <N>/p and the reduced moments
    Z(2) = <N^2>/<N>^2, Z(3) = <N^3>/<N>^3, the fabric F2 = <n_y^2> of all
    and F2_strong of the strong contacts (N > <N>) -- measured in the bulk, between
    `boundary` and height - `boundary` (grain centres; contacts with at least
    one such grain).  grains: dict or lammps_output.Snapshot with id, y,
    radius; contacts: the columns of fix acoustic/mindlin's local array by
    position (a Snapshot of its dump local: 0 = i, 1 = j (0: a wall), 2 = f_n)."""
    ids = grains["id"].astype(int)
    y = grains["y"]
    radius = grains["radius"]
    ci, cj, fn = contacts[0].astype(int), contacts[1].astype(int), contacts[2]
    loaded = fn > 0.0
    ci, cj, fn = ci[loaded], cj[loaded], fn[loaded]
    bulk = (y > boundary) & (y < height - boundary)
    bulk_ids = set(ids[bulk])
    area = width * (height - 2.0 * boundary)
    volume = area * (depth if depth else 1.0)
    out = {}
    if not depth:
        out["phi2"] = float(np.sum(math.pi * radius[bulk] ** 2) / area)
    out["phi3"] = float(np.sum(4.0 / 3.0 * math.pi * radius[bulk] ** 3) / volume)
    removed = rattlers(ids, ci, cj)
    active = bulk & np.array([i not in removed for i in ids])
    out["phi3_star"] = float(np.sum(4.0 / 3.0 * math.pi * radius[active] ** 3) / volume)
    out["f0"] = float(1.0 - active.sum() / bulk.sum())
    count = {i: 0 for i in ids}
    for a, b in zip(ci, cj):
        if a in removed or (b != 0 and b in removed):
            continue
        count[a] += 1
        if b != 0:
            count[b] += 1
    active_ids = ids[active]
    out["z_star"] = float(np.mean([count[i] for i in active_ids]))
    in_bulk = np.array([(a in bulk_ids) or (b in bulk_ids) for a, b in zip(ci, cj)])
    forces = fn[in_bulk]
    mean = forces.mean()
    out["mean_force_over_p"] = float(mean / pressure)
    out["Z2"] = float(np.mean(forces ** 2) / mean ** 2)
    out["Z3"] = float(np.mean(forces ** 3) / mean ** 3)
    # fabric (paper 003 Eq. 6): <n_y^2> over the bulk contacts, and over the
    # strong ones (normal force above the mean)
    ny = vertical_normals(grains, ci[in_bulk], cj[in_bulk], width, depth)
    out["F2"] = float(np.mean(ny ** 2))
    out["F2_strong"] = float(np.mean(ny[forces > mean] ** 2))
    return out


def vertical_normals(grains, contacts_i, contacts_j, width, depth=None):
    """n_y of the unit normal of each contact (i, j atom IDs; j = 0: a wall,
    whose normal is vertical), the nearest image along the periodic x of
    the given width (and z of the given depth, 3D)"""
    row = {int(i): k for k, i in enumerate(grains["id"].astype(int))}
    position = np.column_stack([grains["x"], grains["y"], grains["z"]])
    ny = np.ones(len(contacts_i))
    for m, (a, b) in enumerate(zip(contacts_i, contacts_j)):
        if b == 0:
            continue
        d = position[row[int(b)]] - position[row[int(a)]]
        d[0] -= width * np.round(d[0] / width)
        if depth:
            d[2] -= depth * np.round(d[2] / depth)
        ny[m] = d[1] / np.linalg.norm(d)
    return ny


COULOMB_LIMIT = 0.999   # |F_t| / (mu F_n) at or above it: a contact at the Coulomb limit


def mobilisation(normal_force, tangential_force, mu, limit=COULOMB_LIMIT):
    """How far the contacts are from sliding: the mobilisation m = |F_t| /
    (mu F_n) of every contact that carries a normal force; the fraction at
    the Coulomb limit (m >= limit: LAMMPS's Mindlin model scales F_t back
    onto mu F_n, so a sliding contact has m = 1 to rounding), the fraction
    with m >= 0.9, the mean of m, at_limit, the mask of the contacts at
    the limit, and m itself, in the order given"""
    normal_force = np.asarray(normal_force, dtype=float)
    tangential_force = np.asarray(tangential_force, dtype=float)
    if mu <= 0.0:
        raise ValueError("mobilisation needs a friction coefficient mu > 0")
    loaded = normal_force > 0.0
    m = np.zeros(len(normal_force))
    m[loaded] = tangential_force[loaded] / (mu * normal_force[loaded])
    at_limit = loaded & (m >= limit)
    count = max(int(loaded.sum()), 1)
    return {"fraction_at_limit": float(at_limit.sum() / count), "fraction_above_0.9": float((m[loaded] >= 0.9).sum() / count),
            "mean": float(m[loaded].mean()) if loaded.any() else 0.0, "at_limit": at_limit, "m": m}


def linear_response(moduli, tolerance=0.25, keys=("C11", "C22", "C33")):
    """True when the moduli measured over the first half of each imposed
    strain (C.._half) agree with those of the whole strain within
    `tolerance` and are positive: the packing responded linearly, without a
    rearrangement during the measurement (examples/sound/in.moduli)"""
    for key in keys:
        whole, half = moduli.get(key), moduli.get(key + "_half")
        if whole is None or half is None or not whole > 0.0 or not half > 0.0:
            return False
        if abs(half / whole - 1.0) > tolerance:
            return False
    return True


def sound_speeds(c22, c33, phi3_star):
    """c_l = sqrt(C22 / Phi3*), c_t = sqrt(C33 / Phi3*): the density is the 3D
    solid fraction of the non-rattlers (unit grain density)"""
    return math.sqrt(c22 / phi3_star), math.sqrt(c33 / phi3_star)


def triangular_lattice_speed(pressure, eta=None):
    """paper 003 Eqs. 18 (eta None: frictionless) and 19 (friction, k_t = eta k_n),
    in units of sqrt(E*/rho), pressure in units of E*"""
    c = 3.0 ** (19.0 / 12.0) / (2.0 ** 1.5 * math.sqrt(math.pi)) * pressure ** (1.0 / 6.0)
    return c if eta is None else c * math.sqrt(1.0 + eta / 3.0)
