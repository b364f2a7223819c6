"""acoustic_tools.sound_modes on small networks whose answers are known:
two grains between two walls (F_sig in closed form), a column of grains
(the modal sum against a direct integration of M u'' = -K u, Appendix B's
apparent moduli of a homogeneous medium), and synthetic contact directions"""
import math

import numpy as np
import pytest
import scipy.integrate

from acoustic_tools import network_moduli, sound_modes


def column(n, k):
    """n grains of radius 1/2 (mass pi/6) on a vertical line touching each
    other and the walls y = 0 and y = n; every contact a spring k"""
    grains = {"id": np.arange(1.0, n + 1), "x": np.ones(n), "y": 0.5 + np.arange(n, dtype=float),
              "radius": np.full(n, 0.5)}
    ci = list(range(1, n)) + [1, n]
    cj = list(range(2, n + 1)) + [0, 0]
    contacts = {0: np.array(ci, float), 1: np.array(cj, float), 2: np.full(len(ci), 1e-4),
                3: np.full(len(ci), k)}
    return grains, contacts, float(n)


def test_two_grains_between_walls_in_closed_form():
    # vertical motion: m u'' = -K u with K = k [[2, -1], [-1, 2]], modes
    # w1^2 = k/m (in phase) and w2^2 = 3k/m; u(0) = 0, u'(0) = (k/m, 0) (the
    # impulse k of a unit pulse of the bottom wall); F_top = k u2
    k = 0.3
    grains, contacts, height = column(2, k)
    net = sound_modes.network(grains, contacts, 2.0, height)
    found = sound_modes.modes(net)
    m = math.pi / 6.0
    w1, w2 = math.sqrt(k / m), math.sqrt(3.0 * k / m)
    t = np.linspace(0.0, 20.0, 50)
    expected = k * (k / (2.0 * m)) * (np.sin(w1 * t) / w1 - np.sin(w2 * t) / w2)
    got = sound_modes.modal_signal(found["omega"], found["contribution"], t)
    assert np.allclose(got, expected, rtol=1e-9, atol=1e-12)


def test_modal_sum_is_the_motion_of_the_network():
    # the signal of Eq. 3 against M u'' = -K u integrated from u = 0,
    # M u' = b, on a column of 5 grains (translations and rotations)
    grains, contacts, height = column(5, 0.7)
    net = sound_modes.network(grains, contacts, 2.0, height)
    found = sound_modes.modes(net)
    K = net["K"].toarray()
    M = net["M"]
    size = len(M)

    def motion(_, state):
        return np.concatenate((state[size:], -(K @ state[:size]) / M))

    t = np.linspace(0.0, 30.0, 61)
    solution = scipy.integrate.solve_ivp(motion, (0.0, 30.0), np.concatenate((np.zeros(size), net["source"] / M)),
                                         t_eval=t, rtol=1e-10, atol=1e-13)
    direct = net["detector"] @ solution.y[:size]
    modal = sound_modes.modal_signal(found["omega"], found["contribution"], t)
    assert np.max(np.abs(modal - direct)) < 1e-6 * np.max(np.abs(direct))
    # the vertical modes of the column are those of a chain with walls
    # (Appendix C, Eq. C2): w_n = 2 sqrt(k/m) sin(n pi / (2 (N + 1)))
    chain = 2.0 * math.sqrt(0.7 / (math.pi / 6.0)) * np.sin(np.arange(1, 6) * math.pi / 12.0)
    for w in chain:
        assert np.min(np.abs(found["omega"] - w)) < 1e-9


def test_mode_shapes_and_participation():
    grains, contacts, height = column(4, 1.0)
    net = sound_modes.network(grains, contacts, 2.0, height)
    found = sound_modes.modes(net)
    shapes = found["shapes"]
    # mass-normalised: v^T M v = 1, and M-orthogonal
    assert np.allclose(shapes.T @ (net["M"][:, None] * shapes), np.eye(len(net["M"])), atol=1e-9)
    pr = sound_modes.participation_ratios(shapes, net["M"])
    assert np.all(pr > 0.0) and np.all(pr <= 1.0 + 1e-12)
    # one grain alone: a mode localised on it has PR = 1/N
    single = np.zeros((12, 1))
    single[4, 0] = 1.0
    assert sound_modes.participation_ratios(single, np.ones(12))[0] == pytest.approx(0.25)


def test_selected_modes_kinds():
    result = {"zero": np.array([True, True] + [False] * 18),
              "contribution": np.array([0, 0] + [0.01] * 18, float)}
    result["contribution"][[7, 11, 13]] = [0.5, -0.9, 0.3]
    participation = np.linspace(1.0, 0.1, 20)
    participation[18] = 0.01
    chosen = sound_modes.selected_modes(result, participation)
    assert chosen == {"lowest": [2, 3], "strongest": [7, 11, 13], "localised": [18]}


def test_labels_of_the_selected_modes():
    # Fig. 10's labels: the two lowest non-zero modes by their rank (the
    # second is not "lowest"), then the other kinds; an index not selected
    # is an error
    from acoustic_tools.sound_collect import mode_kind
    selected = {"lowest": [147, 148], "strongest": [853, 886, 977], "localised": [1838]}
    assert mode_kind(147, selected) == "lowest non-zero"
    assert mode_kind(148, selected) == "second-lowest non-zero"
    assert [mode_kind(i, selected) for i in (853, 886, 977)] == ["large $|a_n b_n|$"] * 3
    assert mode_kind(1838, selected) == "localised, high $f$"
    # the rank is by frequency (index), whatever the order of the list
    assert mode_kind(148, {"lowest": [148, 147]}) == "second-lowest non-zero"
    with pytest.raises(ValueError):
        mode_kind(5, selected)


def test_apparent_moduli_of_a_homogeneous_column():
    # a column of 41 grains, springs k between grains (length 1) and 2k to
    # the walls (length 1/2): a homogeneous medium of modulus k (per unit
    # width).  Displacements on the lines (Eq. B3, n = 1: the middle grain
    # on the middle line) give the global modulus exactly; forces
    # sin(n pi y / L2) (Eq. B2) give it to the discretisation of the sine
    grains, contacts, height = column(41, 1.0)
    contacts[3][-2:] = 2.0
    width = 1.0
    net = sound_modes.network(grains, contacts, width, height)
    global_c22 = network_moduli.network_moduli(grains, contacts, width, height)["C22"]
    assert global_c22 == pytest.approx(1.0 * height / (40 + 2 * 0.5) / width, rel=1e-6)
    lines = sound_modes.apparent_modulus_displacement(net, grains, 1, 1) / global_c22
    assert lines == pytest.approx(1.0, rel=1e-6)
    assert sound_modes.apparent_modulus_displacement(net, grains, 3, 1) / global_c22 == pytest.approx(1.0, abs=0.05)
    for n in (1, 2, 3):
        ratio = sound_modes.apparent_modulus_force(net, grains, contacts, n, 1) / global_c22
        assert ratio == pytest.approx(1.0, abs=0.01)
    # the stiffness scale goes through, the amplitude drops out (linear)
    stiffer = dict(contacts)
    stiffer[3] = 3.0 * contacts[3]
    net3 = sound_modes.network(grains, stiffer, width, height)
    assert sound_modes.apparent_modulus_force(net3, grains, stiffer, 2, 1, f0=1e-3) == pytest.approx(
        3.0 * sound_modes.apparent_modulus_force(net, grains, contacts, 2, 1), rel=1e-9)


def test_line_displacement():
    y = np.array([0.0, 2.5, 5.0, 7.5, 10.0])
    assert np.allclose(sound_modes.line_displacement(y, 1, 10.0, u0=2.0), [0, 1, 2, 1, 0])
    assert np.allclose(sound_modes.line_displacement(y, 3, 10.0), [0, 1, 0, -1, 0])
    with pytest.raises(ValueError):
        sound_modes.line_displacement(y, 2, 10.0)


def test_direction_histogram_and_segments():
    vertical, horizontal = math.pi / 2, 0.0
    angles = np.array([vertical] * 10 + [horizontal] * 30)
    forces = np.array([3.0] * 10 + [1.0] * 30)
    histogram = sound_modes.direction_histogram([(angles, forces)], bins=6)
    assert histogram["strong"]["F2"] == pytest.approx(1.0)
    assert histogram["weak"]["F2"] == pytest.approx(0.0)
    assert histogram["all"]["F2"] == pytest.approx(0.25)
    step = histogram["edges"][1] - histogram["edges"][0]
    for name in ("all", "strong", "weak"):
        assert np.sum(histogram[name]["density"]) * step == pytest.approx(1.0)
    # a contact across the periodic side is drawn from both grains
    grains = {"id": np.array([1.0, 2.0]), "x": np.array([0.4, 9.7]), "y": np.array([4.8, 5.0]),
              "radius": np.array([0.5, 0.5])}
    contacts = {0: np.array([1.0, 1.0]), 1: np.array([2.0, 0.0]), 2: np.array([1e-4, 2e-4]),
                3: np.array([0.1, 0.2])}
    segments = sound_modes.network_segments(grains, contacts, 10.0, 10.0)
    assert len(segments) == 3
    assert np.allclose(segments[0, :4], [0.4, 4.8, -0.3, 5.0])
    assert np.allclose(segments[1, :4], [10.4, 4.8, 9.7, 5.0])
    assert np.allclose(segments[2], [0.4, 4.8, 0.4, 0.0, 2e-4, 0.2])
    directions, f = sound_modes.contact_directions(grains, contacts, 10.0, 10.0)
    assert len(directions) == 1 and f[0] == 1e-4
    assert directions[0] == pytest.approx(math.pi - math.atan2(0.2, 0.7))
