"""The linear contact network of one 2D packing of examples/sound as paper
003 treats it (Sec. III, Eqs. 1-3; Appendix B): its eigenmodes, the
contribution a_n b_n of each mode to the signal F_sig (Fig. 9b), the modes
of Fig. 10, the force and stiffness networks and contact directions of
Figs. 1-2, and the apparent moduli of Appendix B (Tables IV and V).

The network is the one of acoustic_tools.network_moduli, built from the
contact network that fix acoustic/mindlin exposes (contacts.dump: i, j (0
for a wall), f_n, k_n) and the grains (grains.dump: id, x, y, radius, mass):
normal springs k_n and tangential springs eta k_n (eta = 1 for nu = 0) at
the contact points, grains translating in the plane and rotating about z,
the bottom (y = 0) and top (y = h) walls rigid.  It is the network of
compute vibration/pulse ... model full of examples/sound/in.measure: the
signal this module sums from the modes is compared with the deck's
pulse_A.dat (modal_signal, sound_collect.network_modes).

  network                 K, the masses, the source impulse and the detector
  modes                   eigenfrequencies, mass-normalised shapes, a_n b_n
  modal_signal            F_sig(t) = sum_n a_n b_n sin(omega_n t) (Eq. 3)
  participation_ratios    how many grains a mode moves
  selected_modes          the kinds of modes of Fig. 10
  network_segments        the contacts as segments, for Fig. 1
  contact_directions      the bulk contacts' angles and forces, for Fig. 2
  direction_histogram     their histogram (all, strong, weak)
  apparent_modulus_force  C~_alpha(n) of Eq. B2 (Table IV)
  apparent_modulus_displacement  C^_alpha(n) of Eq. B3 (Table V)
numpy and scipy only.
"""
import math

import numpy as np
import scipy.linalg
import scipy.sparse
import scipy.sparse.linalg

from . import network_moduli, sound


def _masses(grains):
    """the mass of each grain: the dump's mass column, else unit density"""
    if "mass" in grains:
        return np.asarray(grains["mass"], dtype=float)
    return 4.0 / 3.0 * math.pi * np.asarray(grains["radius"], dtype=float) ** 3


def network(grains, contacts, width, height, eta=1.0):
    """The linear network of a 2D packing (3 DOFs per grain: x, y, theta, in
    the order of grains["id"]):
      K         stiffness (sparse), M the diagonal masses (m, m, 0.4 m r^2)
      source    the impulse b = -K_FP s on the grains of a unit delta pulse
                of the bottom wall along y (condition A: u(0) = 0,
                M du/dt(0) = b)
      detector  d with F_top,y = d.u: the force of the grains on the top
                wall along y for displacements u (F_sig of Eq. 4)
    plus the compatibility matrix B, the springs and the contact geometry of
    network_moduli.compatibility."""
    B, springs, geometry = network_moduli.compatibility(grains, contacts, width, height, eta)
    K = (B.T @ scipy.sparse.diags(springs) @ B).tocsc()
    m = _masses(grains)
    r = np.asarray(grains["radius"], dtype=float)
    M = np.column_stack((m, m, 0.4 * m * r ** 2)).ravel()
    source = -(B.T @ (springs * network_moduli.wall_stretch(geometry, {0: (0.0, 1.0)})))
    # F_y on the top wall = -sum over its contacts of k s e_y (e = n or t)
    on_top = geometry["wall"] & (geometry["which_wall"] == 1)
    e_y = np.zeros(len(springs))
    e_y[0::2][on_top] = geometry["normal"][on_top, 1]
    e_y[1::2][on_top] = geometry["tangent"][on_top, 1]
    detector = -(B.T @ (springs * e_y))
    return {"K": K, "M": M, "source": np.asarray(source).ravel(), "detector": np.asarray(detector).ravel(),
            "B": B, "springs": springs, "geometry": geometry, "width": float(width), "height": float(height)}


def modes(net, zero=1e-8):
    """Every eigenmode of K v = omega^2 M v (dense): omega (ascending), the
    shapes as columns (v^T M v = 1), the zero modes (omega^2 below `zero`
    times the largest) and the contribution of each mode to the signal of
    a unit delta pulse of the bottom wall (condition A), paper 003 Eq. 3:
    F_sig(t) = sum_n a_n b_n sin(omega_n t), a_n b_n = (v_n.b)(d.v_n)/omega_n
    (0 for the zero modes)"""
    K = net["K"].toarray()
    scale = 1.0 / np.sqrt(net["M"])
    values, vectors = scipy.linalg.eigh(scale[:, None] * K * scale[None, :])
    shapes = scale[:, None] * vectors
    values = np.clip(values, 0.0, None)
    is_zero = values < zero * values.max()
    omega = np.sqrt(values)
    amplitude = shapes.T @ net["source"]
    coupling = shapes.T @ net["detector"]
    contribution = np.zeros(len(omega))
    contribution[~is_zero] = amplitude[~is_zero] * coupling[~is_zero] / omega[~is_zero]
    return {"omega": omega, "shapes": shapes, "zero": is_zero, "a": amplitude, "b": coupling,
            "contribution": contribution}


def modal_signal(omega, contribution, t):
    """F_sig(t) = sum_n a_n b_n sin(omega_n t) (Eq. 3) at the times t"""
    t = np.asarray(t, dtype=float)
    return np.sin(np.outer(t, omega)) @ contribution


def participation_ratios(shapes, masses):
    """PR = (sum_g w_g)^2 / (N sum_g w_g^2) of each mode (columns of
    shapes, 3 DOFs per grain), w_g the kinetic energy share of grain g: 1
    for a mode spread evenly over the N grains, 1/N on one grain (as
    compute vibration/modes defines it)"""
    w = (np.asarray(masses)[:, None] * shapes ** 2).reshape(-1, 3, shapes.shape[1]).sum(axis=1)
    return w.sum(axis=0) ** 2 / (w.shape[0] * (w ** 2).sum(axis=0))


def selected_modes(result, participation, strongest=3):
    """The kinds of modes of Fig. 10 (indices into the ascending modes):
    the first two non-zero modes, the `strongest` with the largest
    |a_n b_n| (in ascending order), and the most localised mode (smallest
    participation ratio) among the highest tenth of the frequencies"""
    nonzero = np.flatnonzero(~result["zero"])
    chosen = {"lowest": [int(k) for k in nonzero[:2]]}
    order = np.argsort(-np.abs(result["contribution"]))
    chosen["strongest"] = sorted(int(k) for k in order[:strongest])
    top = nonzero[int(0.9 * len(nonzero)):]
    chosen["localised"] = [int(top[np.argmin(participation[top])])]
    return chosen


# ---- Figs. 1 and 2: the contact network

def _centres(grains):
    return {int(i): k for k, i in enumerate(np.asarray(grains["id"]).astype(int))}


def network_segments(grains, contacts, width, height):
    """The loaded contacts as segments for a drawing of the force network
    (Fig. 1): rows (x0, y0, x1, y1, f_n, k_n), from grain i to the nearest
    image of grain j (a contact across the periodic side appears twice,
    once from each grain), or to its wall (y = 0 or y = height)"""
    row = _centres(grains)
    x, y = np.asarray(grains["x"], float), np.asarray(grains["y"], float)
    ci, cj = np.asarray(contacts[0]).astype(int), np.asarray(contacts[1]).astype(int)
    fn, kn = np.asarray(contacts[2], float), np.asarray(contacts[3], float)
    segments = []
    for a, b, f, k in zip(ci, cj, fn, kn):
        if f <= 0.0:
            continue
        i = row[a]
        if b == 0:
            segments.append((x[i], y[i], x[i], 0.0 if y[i] < 0.5 * height else height, f, k))
            continue
        j = row[b]
        dx = x[j] - x[i]
        shift = width * np.round(dx / width)
        segments.append((x[i], y[i], x[j] - shift, y[j], f, k))
        if shift != 0.0:
            segments.append((x[i] + shift, y[i], x[j], y[j], f, k))
    return np.array(segments).reshape(-1, 6)


def contact_directions(grains, contacts, width, height, boundary=3.0):
    """The angle (0 to pi, from the horizontal x axis) and the normal force of
    every loaded grain-grain contact with a grain in the bulk (centre more
    than `boundary` from both walls, as sound.static_properties counts
    them): (angles, forces)"""
    y = np.asarray(grains["y"], float)
    ids = np.asarray(grains["id"]).astype(int)
    bulk = set(ids[(y > boundary) & (y < height - boundary)])
    ci, cj = np.asarray(contacts[0]).astype(int), np.asarray(contacts[1]).astype(int)
    fn = np.asarray(contacts[2], float)
    chosen = (fn > 0.0) & (cj != 0) & np.array([a in bulk or b in bulk for a, b in zip(ci, cj)])
    row = _centres(grains)
    x = np.asarray(grains["x"], float)
    angles = []
    for a, b in zip(ci[chosen], cj[chosen]):
        dx = x[row[b]] - x[row[a]]
        dx -= width * np.round(dx / width)
        angles.append(math.atan2(y[row[b]] - y[row[a]], dx) % math.pi)
    return np.array(angles), fn[chosen]


def direction_histogram(samples, bins=18):
    """The histogram of contact directions of several packings (Fig. 2):
    samples = [(angles, forces)] of contact_directions; each packing's
    contacts are strong when their force exceeds that packing's mean.
    Returns the bin edges over [0, pi) and, for "all", "strong" and "weak",
    the probability density of the direction (integral over [0, pi) = 1)
    and the fabric <n_y^2> (paper 003 Eq. 6) of those contacts"""
    edges = np.linspace(0.0, math.pi, bins + 1)
    groups = {"all": [], "strong": [], "weak": []}
    for angles, forces in samples:
        mean = forces.mean()
        groups["all"].append(angles)
        groups["strong"].append(angles[forces > mean])
        groups["weak"].append(angles[forces <= mean])
    out = {"edges": edges}
    for name, parts in groups.items():
        angles = np.concatenate(parts) if parts else np.zeros(0)
        density, _ = np.histogram(angles, bins=edges, density=True)
        out[name] = {"density": density, "count": len(angles), "F2": float(np.mean(np.sin(angles) ** 2))}
    return out


# ---- Appendix B: apparent moduli on short length scales (Tables IV, V)

def _non_rattlers(grains, contacts):
    """True for the grains that carry force (sound.rattlers removed)"""
    ids = np.asarray(grains["id"]).astype(int)
    fn = np.asarray(contacts[2], float)
    loaded = fn > 0.0
    removed = sound.rattlers(ids, np.asarray(contacts[0])[loaded], np.asarray(contacts[1])[loaded])
    return np.array([i not in removed for i in ids])


def apparent_modulus_force(net, grains, contacts, n, direction, f0=1e-6):
    """C~_alpha(n) of paper 003's Eq. B2 (Table IV): every non-rattler grain i
    is pushed along `direction` (0: x, transverse, C33; 1: y, longitudinal,
    C22) by 4 pi R_i^3 / (3 Phi3*) f0 sin(n pi y_i / L2), the walls held;
    from the elastic energy W = F.u / 2 of the network,
    C = L1 L2^3 f0^2 / (4 n^2 pi^2 W).  Phi3* is that of the non-rattlers
    of the whole layer (the forces add up to f0 sin(...) per unit volume);
    linear, so f0 only sets the scale."""
    width, height = net["width"], net["height"]
    r = np.asarray(grains["radius"], float)
    y = np.asarray(grains["y"], float)
    active = _non_rattlers(grains, contacts)
    volume = 4.0 / 3.0 * math.pi * r ** 3
    phi3_star = volume[active].sum() / (width * height)
    force = np.zeros(net["K"].shape[0])
    force[3 * np.flatnonzero(active) + direction] = (volume[active] / phi3_star * f0
                                                     * np.sin(n * math.pi * y[active] / height))
    u = scipy.sparse.linalg.spsolve(network_moduli.regularised(net["K"]), force)
    energy = 0.5 * force @ u
    return width * height ** 3 * f0 ** 2 / (4.0 * n ** 2 * math.pi ** 2 * energy)


def line_displacement(y, n, height, u0=1.0):
    """The continuum displacement of Appendix B's imposed lines: on the
    lines y_k = k L2 / (n + 1), 0 when k is even, (-1)^l u0 when k = 2l + 1,
    linear in between (n odd)"""
    if n % 2 != 1:
        raise ValueError(f"Appendix B's lines need an odd n, not {n}")
    lines = np.arange(n + 2) * height / (n + 1)
    values = np.array([0.0 if k % 2 == 0 else (-1.0) ** (k // 2) * u0 for k in range(n + 2)])
    return np.interp(y, lines, values)


def apparent_modulus_displacement(net, grains, n, direction, u0=1e-6):
    """C^_alpha(n) of paper 003's Eq. B3 (Table V): the centres of the grains
    crossed by the lines y_k = k L2 / (n + 1) (|y_i - y_k| < R_i, k = 0 ...
    n + 1) take the displacement of the same point of the continuum
    (line_displacement along `direction`, 0 across it), their rotations and
    every other grain free, the walls held; from the elastic energy W of the
    network, C = 2 L2 W / ((n + 1)^2 L1 u0^2)"""
    width, height = net["width"], net["height"]
    r = np.asarray(grains["radius"], float)
    y = np.asarray(grains["y"], float)
    lines = np.arange(n + 2) * height / (n + 1)
    crossed = np.any(np.abs(y[:, None] - lines[None, :]) < r[:, None], axis=1)
    u = np.zeros(net["K"].shape[0])
    held = np.zeros(len(u), dtype=bool)
    for component in (0, 1):
        dofs = 3 * np.flatnonzero(crossed) + component
        held[dofs] = True
        if component == direction:
            u[dofs] = line_displacement(y[crossed], n, height, u0)
    K = net["K"].tocsr()
    free = ~held
    K_ff = network_moduli.regularised(K[free][:, free])
    u[free] = scipy.sparse.linalg.spsolve(K_ff, -(K[free][:, held] @ u[held]))
    energy = 0.5 * u @ (K @ u)
    return 2.0 * height * energy / ((n + 1) ** 2 * width * u0 ** 2)
