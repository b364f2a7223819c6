"""acoustic_tools.sound_chain against closed forms and independent
computations: Eq. C2's frequencies, Eqs. C4-C6 against the eigenmodes of the
chain and against a direct integration, Eq. 16's front, the Hertz springs,
Eqs. 18-19 from the chain of rows of the triangular lattice"""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.special import airy

from acoustic_tools import sound, sound_chain


def test_chain_frequencies_are_eq_c2():
    n, k, m = 12, 3.0, 0.7
    matrix = (np.diag(np.full(n, 2.0 * k)) - np.diag(np.full(n - 1, k), 1) - np.diag(np.full(n - 1, k), -1)) / m
    _, omega = sound_chain.chain_modes(n, k, m)
    assert np.sqrt(np.linalg.eigvalsh(matrix)) == pytest.approx(np.sort(omega), rel=1e-12)
    # the long-wavelength speed of Eq. C3
    wavenumber, omega = sound_chain.chain_modes(2000, k, m, spacing=0.9)
    assert omega[0] / wavenumber[0] == pytest.approx(0.9 * math.sqrt(k / m), rel=1e-6)


def test_closed_form_is_the_eigenmode_sum_of_the_chain():
    n, k, m = 40, 2.0, 0.5
    c = math.sqrt(k / m)
    t = np.linspace(0.0, 60.0, 601)
    # the paper's A (u'_1 = c) and the compute's (u'_1 = K / m); B: u_1 = l = 1 both
    a = sound_chain.chain_signal(n, t, "A", k, m) * (k / m) / c
    b = sound_chain.chain_signal(n, t, "B", k, m)
    assert sound_chain.linear_chain_signal(np.full(n, m), np.full(n + 1, k), t, "A") == pytest.approx(a, abs=1e-12)
    assert sound_chain.linear_chain_signal(np.full(n, m), np.full(n + 1, k), t, "B") == pytest.approx(b, abs=1e-12)
    # the initial conditions: at t = 0 nothing has reached the last ball
    assert a[0] == 0.0 and abs(b[0]) < 1e-12


def test_linear_chain_against_a_direct_integration():
    rng = np.random.default_rng(3)
    masses = rng.uniform(0.5, 1.5, 6)
    springs = rng.uniform(0.5, 2.0, 7)

    def rate(_, state):
        u, v = state[:6], state[6:]
        stretch = np.diff(np.concatenate([[0.0], u, [0.0]]))
        force = springs[1:] * stretch[1:] - springs[:-1] * stretch[:-1]
        return np.concatenate([v, force / masses])

    t = np.linspace(0.0, 20.0, 201)
    for condition in ("A", "B"):
        start = np.zeros(12)
        if condition == "A":
            start[6] = springs[0] / masses[0]
        else:
            start[0] = 1.0
        solved = solve_ivp(rate, (0.0, 20.0), start, t_eval=t, rtol=1e-11, atol=1e-13)
        expected = springs[-1] * solved.y[5]
        assert sound_chain.linear_chain_signal(masses, springs, t, condition) == pytest.approx(expected, abs=1e-8)


def test_front_converges_to_eq_16():
    errors = {}
    for n in (512, 2048):
        for condition in ("A", "B"):
            tau = np.linspace(-2.0, 2.0, 401) * n ** (1.0 / 3.0)
            exact = sound_chain.chain_signal(n, n + 1 + tau, condition)
            front = sound_chain.airy_front(n, tau, condition)
            errors[n, condition] = np.max(np.abs(exact - front)) / np.max(np.abs(exact))
    for condition in ("A", "B"):
        assert errors[2048, condition] < 0.035
        # the error falls about as N^(-2/3)
        assert errors[2048, condition] < 0.5 * errors[512, condition]
    # Fig. 12's variables collapse the front onto -8 Ai'(-2 x)
    n = 2048
    t = np.linspace(n - 30.0, n + 40.0, 2001)
    x, y = sound_chain.scaled_front(t, sound_chain.chain_signal(n, t, "A") * 1.0, n, 1.0, 1.0, 1.0, 1.0, 1.0)
    assert np.max(np.abs(y + 8.0 * airy(-2.0 * x)[1])) < 0.04 * np.max(np.abs(y))


def test_decay_exponents_of_eqs_9_and_10():
    sizes = [2048, 8192]
    # Eq. 9 (C7): F_A(t0) at t0 = N l / c falls as N^(-2/3)
    values = [abs(sound_chain.chain_signal(n, [float(n)], "A")[0]) for n in sizes]
    assert -sound.effective_exponents(sizes, values)[1][0] == pytest.approx(2.0 / 3.0, abs=0.02)
    # Eq. 10: the front of B as N^(-1) (at t0 itself B is near the zero of
    # Ai''(w) = w Ai(w): its first peak instead)
    peaks = []
    for n in sizes:
        t = n + 1 + np.linspace(-3.0, 3.0, 1201) * n ** (1.0 / 3.0)
        peaks.append(sound.coherent_peak(t, sound_chain.chain_signal(n, t, "B"))["amplitude"])
    assert -sound.effective_exponents(sizes, peaks)[1][0] == pytest.approx(1.0, abs=0.02)


def test_hertz_springs_and_walls():
    f = 1e-4
    masses, springs = sound_chain.hertz_chain([1.0, 1.0, 1.0], f)
    k = 0.5 * (3.0 * f) ** (1.0 / 3.0)          # dF/d delta of two unit balls at f
    assert springs == pytest.approx(np.full(4, k), rel=1e-12)      # identical walls: Appendix C
    assert masses == pytest.approx(np.full(3, math.pi / 6.0))
    _, rigid = sound_chain.hertz_chain([1.0, 1.0, 1.0], f, wall_modulus=2.0)
    assert rigid[[0, 3]] == pytest.approx([2.0 * k, 2.0 * k], rel=1e-12)
    # a pair of balls of diameters 0.8 and 1.2: the slope of the Hertz force at its overlap
    _, pair = sound_chain.hertz_chain([0.8, 1.2], f)
    r_star = 0.4 * 0.6 / 1.0

    def force(delta):
        return 4.0 / 3.0 * 0.5 * math.sqrt(r_star) * delta ** 1.5

    delta = (3.0 * f / (2.0 * math.sqrt(r_star))) ** (2.0 / 3.0)
    assert force(delta) == pytest.approx(f, rel=1e-12)
    h = 1e-6 * delta
    assert pair[1] == pytest.approx((force(delta + h) - force(delta - h)) / (2 * h), rel=1e-8)


def test_lattice_rows_give_eqs_18_and_19():
    for p in (1e-7, 1e-4):
        assert sound_chain.lattice_speed(p) == pytest.approx(sound.triangular_lattice_speed(p), rel=1e-12)
        assert sound_chain.lattice_speed(p, 1.0) == pytest.approx(sound.triangular_lattice_speed(p, 1.0), rel=1e-12)
        # the rigid planes' spring over the rows' (frictionless): 4 3^(1/6) / 3
        assert sound_chain.lattice_walls_ratio(p) == pytest.approx(4.0 * 3.0 ** (1.0 / 6.0) / 3.0, rel=1e-12)
        # the paper's "3^(5/6)/4 = 0.62" is its inverse
        assert 1.0 / sound_chain.lattice_walls_ratio(p) == pytest.approx(3.0 ** (5.0 / 6.0) / 4.0, rel=1e-12)
    # paper 003 Sec. V B: K_eff = 3^(7/6) 2^(-2) p^(1/3) per ball
    _, springs = sound_chain.lattice_row_chain(3, 1e-5)
    assert springs[1] == pytest.approx(3.0 ** (7.0 / 6.0) / 4.0 * 1e-5 ** (1.0 / 3.0), rel=1e-12)


def test_effective_exponents_with_errors():
    x = np.array([10.0, 20.0, 40.0])
    y = 3.0 * x ** -1.5
    _, slopes, errors = sound.effective_exponents_se(x, y, 0.1 * y)
    assert slopes == pytest.approx([-1.5, -1.5])
    assert errors == pytest.approx(np.full(2, math.sqrt(0.02) / math.log(2.0)))


def test_lattice_walls_change_the_front_slightly():
    # paper 003 Sec. V B / Fig. 12: measured as a unit pulse of the wall and
    # the force on the other wall, the chain of rows between rigid walls
    # (K_wall = 1.6 K) is close to the chain with identical wall springs,
    # the closer the longer
    ratios = []
    for n in (32, 512):
        t = np.linspace(0.0, 1.6 * n + 60.0, 6000)
        walls = np.ones(n + 1)
        walls[[0, -1]] = sound_chain.lattice_walls_ratio(1e-4)
        lattice = sound_chain.linear_chain_signal(np.ones(n), walls, t, "A")
        chain = sound_chain.linear_chain_signal(np.ones(n), np.ones(n + 1), t, "A")
        ratios.append(sound.coherent_peak(t, lattice)["amplitude"] / sound.coherent_peak(t, chain)["amplitude"])
    assert 1.0 < ratios[1] < ratios[0] < 1.15 and ratios[1] < 1.03
