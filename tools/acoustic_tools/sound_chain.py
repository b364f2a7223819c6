"""Paper 003's one-dimensional references for the coherent pulse: the chain
of balls between two walls (Sec. V A, Appendix C, Table III) and the perfect
triangular lattice mapped onto a chain of rows (Sec. V B, Eqs. 18-19).

  chain_modes, chain_signal   Eqs. C2 and C4-C6: the chain of N identical
                              masses with identical springs K (walls too)
  scaled_front                Fig. 12's variables of a front
  airy_front                  Eq. 16 (and its condition-B partner): the
                              front of that chain for large N, with the
                              factor the sum gives
  linear_chain_signal         any chain of masses and springs (polydisperse
                              balls, other wall springs), by its eigenmodes,
                              with compute vibration/pulse's normalisation
  hertz_chain, read_chain_grains
                              masses and springs of a chain of Hertz balls
                              (E* = 1, nu = 0) at a force f, from in.chain's
                              chain_<N>.grains
  lattice_row_chain, lattice_speed
                              the rows of a triangular lattice as a chain:
                              its springs, masses and long-wavelength speed
  lattice_walls_ratio         K_wall / K_bulk of that chain

Normalisations.  The paper's (Eqs. C4-C6, C5): condition A u'_1(0) = c,
condition B u_1(0) = l.  compute vibration/pulse's (a unit displacement of
the source wall for an instant): A u'_1(0) = k_0 / m_1, B u_1(0) = 1; F_sig =
k_N u_N with k_0, k_N the springs to the source and to the detector.
numpy and scipy only.
"""
import math

import numpy as np
from scipy.linalg import eigh_tridiagonal
from scipy.special import airy


def chain_modes(n, stiffness=1.0, mass=1.0, spacing=1.0):
    """Eq. C2: wavenumbers k_n = n pi / ((N + 1) l) and frequencies
    omega_n = 2 sqrt(K/m) sin(k_n l / 2), n = 1 .. N"""
    k = np.arange(1, n + 1) * math.pi / ((n + 1) * spacing)
    return k, 2.0 * math.sqrt(stiffness / mass) * np.sin(0.5 * k * spacing)


def chain_signal(n, t, condition="A", stiffness=1.0, mass=1.0, spacing=1.0):
    """Eqs. C4-C6: F(t) = K u_N(t) of the chain of N identical balls with
    identical springs to the walls, after condition A (u'_1(0) = c =
    l sqrt(K/m), Eq. C3) or B (u_1(0) = l), amplitudes of Eq. C5"""
    k, omega = chain_modes(n, stiffness, mass, spacing)
    t = np.asarray(t, dtype=float)
    if condition == "A":
        a = 2.0 * spacing / (n + 1) * np.cos(0.5 * k * spacing)
        time = np.sin(np.outer(t, omega))
    elif condition == "B":
        a = 2.0 * spacing / (n + 1) * np.sin(k * spacing)
        time = np.cos(np.outer(t, omega))
    else:
        raise ValueError(f"condition A or B, not {condition}")
    return stiffness * time @ (a * np.sin(k * n * spacing))


def airy_front(n, tau, condition="A", stiffness=1.0, mass=1.0, spacing=1.0):
    """The long-time front of chain_signal, Eq. 16 (condition A) and the
    paper's expression for condition B below it, with the factors that the
    sum C4 gives (the paper leaves them undetermined and writes -4 K l):
    F(t1 + tau) = -8 K l (c t / l)^(-2/3) Ai'(w) (A) and
    16 K l (c t / l)^(-1) Ai''(w) (B), w = -2 (c tau / l) / (c t / l)^(1/3),
    with tau from t1 = (N + 1) l / c, when the front reaches the wall (the
    paper's t0 = N l / c: one ball's transit earlier, a subleading shift);
    paper's normalisation; Ai''(w) = w Ai(w).  Derivation: the alternating
    sign sin(k_n N l) = (-1)^(n+1) sin(k_n l) turns Eq. C4 near the front
    into (2/pi) integral of sin(k l) cos(k l / 2) sin(omega t - k (N + 1) l),
    and omega = c k - c l^2 k^3 / 24 (Eq. 11) makes it an Airy integral"""
    c = spacing * math.sqrt(stiffness / mass)
    s = np.asarray(tau, dtype=float) * c / spacing
    ct = n + 1.0 + s
    w = -2.0 * s / ct ** (1.0 / 3.0)
    ai, aip, _, _ = airy(w)
    if condition == "A":
        return -8.0 * stiffness * spacing * ct ** (-2.0 / 3.0) * aip
    if condition == "B":
        return 16.0 * stiffness * spacing * w * ai / ct
    raise ValueError(f"condition A or B, not {condition}")


def linear_chain_signal(masses, springs, t, condition="A"):
    """F_sig(t) = k_N u_N(t) of a chain of N masses and N + 1 springs
    (springs[0] to the source wall, springs[N] to the detector wall), by its
    eigenmodes, in compute vibration/pulse's normalisation: condition A
    u'_1(0) = k_0 / m_1, condition B u_1(0) = 1, everything else at rest"""
    m = np.asarray(masses, dtype=float)
    k = np.asarray(springs, dtype=float)
    if len(k) != len(m) + 1:
        raise ValueError("a chain of N masses has N + 1 springs")
    # M^(-1/2) K M^(-1/2), tridiagonal
    diagonal = (k[:-1] + k[1:]) / m
    off = -k[1:-1] / np.sqrt(m[:-1] * m[1:])
    omega2, vectors = eigh_tridiagonal(diagonal, off)
    omega = np.sqrt(np.maximum(omega2, 0.0))
    # u = M^(-1/2) V q; the mode amplitudes of the first ball's start
    first, last = vectors[0] / math.sqrt(m[0]), vectors[-1] / math.sqrt(m[-1])
    t = np.asarray(t, dtype=float)
    if condition == "A":
        # q_j(0) = 0, q'_j(0) = V_1j sqrt(m_1) v_1, v_1 = k_0 / m_1
        rate = first * m[0] * k[0] / m[0]
        u = np.sin(np.outer(t, omega)) @ (last * rate / omega)
    elif condition == "B":
        u = np.cos(np.outer(t, omega)) @ (last * first * m[0])
    else:
        raise ValueError(f"condition A or B, not {condition}")
    return k[-1] * u


def hertz_chain(diameters, force, wall_modulus=1.0 / math.sqrt(2.0), density=1.0):
    """(masses, springs) of a chain of Hertz balls (E* = 1, nu = 0; pair E_mix
    1/2, R* = a b / (a + b)) between two flat walls of Hertz modulus
    wall_modulus (E_mix wall_modulus / 2, R* = a; 1/sqrt(2): a ball on a
    wall as on its mirror image, in.chain's `walls identical`; 2: rigid
    planes of E_mix 1, `walls rigid`), every contact at the force f:
    k = dF/d delta = 2 E_mix sqrt(R* delta) at the Hertz overlap delta"""
    d = np.asarray(diameters, dtype=float)
    radius = 0.5 * d
    masses = density * math.pi / 6.0 * d ** 3

    def spring(e_mix, r_star):
        delta = (3.0 * force / (4.0 * e_mix * np.sqrt(r_star))) ** (2.0 / 3.0)
        return 2.0 * e_mix * np.sqrt(r_star * delta)

    pair = spring(0.5, radius[:-1] * radius[1:] / (radius[:-1] + radius[1:]))
    walls = spring(0.5 * wall_modulus, radius[[0, -1]])
    return masses, np.concatenate([[walls[0]], pair, [walls[1]]])


def read_chain_grains(path):
    """(y, diameter, mass) of in.chain's chain_<N>[_<r>].grains, in the
    order of the balls along the chain"""
    with open(path) as handle:
        lines = handle.read().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
    rows = np.array([[float(x) for x in line.split()] for line in lines[start:] if line.strip()])
    rows = rows[np.argsort(rows[:, 1])]
    return rows[:, 1], rows[:, 2], rows[:, 3]


def scaled_front(t, signal, n, stiffness, mass, spacing, source_spring=None, detector_spring=None):
    """Fig. 12's variables of a chain signal in compute vibration/pulse's
    normalisation (condition A: u'_1(0) = source_spring / m, F = detector_spring
    u_N): x = (c tau / l) / (c t / l)^(1/3), tau = t - (N + 1) l / c, and
    y = F_paper (c t / l)^(2/3) / (K l), F_paper = K u_N c / u'_1(0) the force
    of Eq. C6 in the paper's normalisation u'_1(0) = c; K the bulk spring,
    c = l sqrt(K / m); the walls' springs default to K"""
    source_spring = stiffness if source_spring is None else source_spring
    detector_spring = stiffness if detector_spring is None else detector_spring
    c = spacing * math.sqrt(stiffness / mass)
    t = np.asarray(t, dtype=float)
    u = np.asarray(signal, dtype=float) / detector_spring
    f_paper = stiffness * u * c / (source_spring / mass)
    ct = np.maximum(c * t / spacing, 1e-12)
    return (ct - (n + 1)) / ct ** (1.0 / 3.0), f_paper * ct ** (2.0 / 3.0) / (stiffness * spacing)


# ---------------------------------------------------------------------------
# the perfect triangular lattice (paper 003 Sec. V B)

def lattice_contact_force(pressure, spacing=1.0):
    """the force on every contact of a triangular lattice with rows parallel
    to the walls, spacing a along the rows, under the vertical stress p of a
    layer one diameter thick: two contacts at 60 degrees carry p a, f = p a / sqrt(3)"""
    return pressure * spacing / math.sqrt(3.0)


def lattice_row_chain(rows, pressure, eta=0.0, wall_modulus=2.0, spacing=1.0):
    """(masses, springs) of the chain of the rows of a perfect triangular
    lattice of unit balls (E* = 1, nu = 0; rows parallel to the walls),
    `rows` rows between two flat walls of Hertz modulus wall_modulus (2: the
    rigid planes of the packings), per grain of a row (paper 003 Sec. V B:
    a row moves as one ball): bulk spring 2 (k_n sin^2 60 + k_t cos^2 60) =
    (3/2) k_n (1 + eta/3), k_t = eta k_n; wall spring the normal k of the
    one wall contact, which carries p a; mass pi/6; a = spacing, the
    balls' distance along a row (in.lattice's a = 1 - delta; 1 in Eqs. 18-19)"""
    a = spacing
    f = lattice_contact_force(pressure, a)
    kn = 0.5 * (3.0 * f) ** (1.0 / 3.0)         # unit balls: E_mix 1/2, R* 1/4
    e_wall = 0.5 * wall_modulus
    delta = (3.0 * pressure * a / (4.0 * e_wall * math.sqrt(0.5))) ** (2.0 / 3.0)
    k_wall = 2.0 * e_wall * math.sqrt(0.5 * delta)
    bulk = 1.5 * kn * (1.0 + eta / 3.0)
    springs = np.array([k_wall] + [bulk] * (rows - 1) + [k_wall])
    return np.full(rows, math.pi / 6.0), springs


def lattice_speed(pressure, eta=0.0, spacing=1.0):
    """long-wavelength speed of the row chain, l sqrt(K_bulk / m) with the
    row spacing l = sqrt(3) a / 2: paper 003 Eq. 18 (eta = 0) and 19 for a = 1"""
    masses, springs = lattice_row_chain(2, pressure, eta, spacing=spacing)
    return math.sqrt(3.0) / 2.0 * spacing * math.sqrt(springs[1] / masses[0])


def lattice_walls_ratio(pressure, wall_modulus=2.0):
    """K_wall / K_bulk of the row chain (frictionless bulk spring): 4 / 3^(5/6)
    = 1.60 for rigid planes; the paper's "K_wall/K_bulk = 3^(5/6)/4 = 0.62" is
    its inverse"""
    _, springs = lattice_row_chain(2, pressure, 0.0, wall_modulus)
    return springs[0] / springs[1]
