"""acoustic_tools.network_moduli against elastic moduli known in closed form: a
column of grains (springs in series) and the triangular lattice (Lame
constants of central and tangential springs)"""
import math

import numpy as np
import pytest

from acoustic_tools import network_moduli, sound


def packing(ids, x, y, bonds, wall_contacts, k, k_wall):
    """grains of radius 1/2 and the contact table of fix acoustic/mindlin's
    local array by position (0: i, 1: j or 0 for a wall, 3: k_n)"""
    grains = {"id": np.array(ids, float), "x": np.array(x, float), "y": np.array(y, float),
              "radius": np.full(len(ids), 0.5)}
    ci = [i for i, _ in bonds] + list(wall_contacts)
    cj = [j for _, j in bonds] + [0] * len(wall_contacts)
    kn = [k] * len(bonds) + [k_wall] * len(wall_contacts)
    contacts = {0: np.array(ci, float), 1: np.array(cj, float), 3: np.array(kn, float)}
    return grains, contacts


def column(n, k, width):
    """n touching grains on a vertical line between walls at y = 0 and y = n"""
    ids = list(range(1, n + 1))
    bonds = [(i, i + 1) for i in range(1, n)]
    return packing(ids, [1.0] * n, [0.5 + i for i in range(n)], bonds, [1, n], k, k), float(n)


def triangular_lattice(nx, rows, k, k_wall):
    """rows of nx grains (spacing 1, periodic along x), parallel to the walls,
    the bottom and top rows touching them; returns the packing, its width
    and height and the distance between the centres of the outer rows"""
    def tag(r, c):
        return r * nx + (c % nx) + 1
    ids, x, y, bonds = [], [], [], []
    for r in range(rows):
        for c in range(nx):
            ids.append(tag(r, c))
            x.append(c + 0.5 * (r % 2))
            y.append(0.5 + r * math.sqrt(3.0) / 2.0)
            bonds.append((tag(r, c), tag(r, c + 1)))
            if r + 1 < rows:
                for above in ((c - 1, c) if r % 2 == 0 else (c, c + 1)):
                    bonds.append((tag(r, c), tag(r + 1, above)))
    walls = [tag(0, c) for c in range(nx)] + [tag(rows - 1, c) for c in range(nx)]
    span = (rows - 1) * math.sqrt(3.0) / 2.0
    return packing(ids, x, y, bonds, walls, k, k_wall), float(nx), span + 1.0, span


def test_column_is_springs_in_series():
    n, k, width = 7, 3.0, 2.0
    (grains, contacts), height = column(n, k, width)
    moduli = network_moduli.network_moduli(grains, contacts, width, height)
    # n + 1 springs in series: force k / (n + 1) * eps h on the width
    assert moduli["C22"] == pytest.approx(k * height / ((n + 1) * width), rel=1e-9)


@pytest.mark.parametrize("eta", [0.0, 0.5, 1.0])
def test_triangular_lattice_longitudinal_modulus(eta):
    # C22 = (3 sqrt(3) / 4) k (1 + eta / 3) between rigid walls (k_wall >> k),
    # over the strain between the centres of the outer rows
    k = 2.0
    (grains, contacts), width, height, span = triangular_lattice(4, 30, k, 1e9 * k)
    moduli = network_moduli.network_moduli(grains, contacts, width, height, eta=eta)
    expected = 3.0 * math.sqrt(3.0) / 4.0 * k * (1.0 + eta / 3.0)
    assert moduli["C22"] * span / height == pytest.approx(expected, rel=1e-5)


def test_triangular_lattice_shear_modulus_converges():
    # C33 = (sqrt(3) / 4) k (1 + eta): the walls pin the contact points of the
    # outer rows, a boundary layer whose weight falls as 1 / rows
    k, eta = 1.0, 1.0
    expected = math.sqrt(3.0) / 4.0 * k * (1.0 + eta)
    errors = []
    for rows in (20, 40, 80):
        (grains, contacts), width, height, _ = triangular_lattice(4, rows, k, 1e9 * k)
        c33 = network_moduli.network_moduli(grains, contacts, width, height, eta=eta)["C33"]
        errors.append(abs(c33 / expected - 1.0))
    assert errors[-1] < 0.005
    assert errors[0] / errors[1] == pytest.approx(2.0, rel=0.15)
    assert errors[1] / errors[2] == pytest.approx(2.0, rel=0.15)


def test_frictionless_walls_carry_no_shear():
    (grains, contacts), width, height, _ = triangular_lattice(4, 10, 1.0, 1e3)
    assert network_moduli.network_moduli(grains, contacts, width, height, eta=0.0)["C33"] == 0.0


def test_linear_and_blind_to_rattlers():
    (grains, contacts), width, height, _ = triangular_lattice(4, 10, 1.0, 10.0)
    small = network_moduli.network_moduli(grains, contacts, width, height, strain=1e-7)
    large = network_moduli.network_moduli(grains, contacts, width, height, strain=1e-3)
    assert large["C22"] == pytest.approx(small["C22"], rel=1e-9)
    assert large["C33"] == pytest.approx(small["C33"], rel=1e-9)
    # a grain without contacts (a rattler) changes nothing
    with_rattler = {key: np.append(value, extra) for (key, value), extra in
                    zip(grains.items(), (999.0, 2.2, 3.3, 0.4))}
    moduli = network_moduli.network_moduli(with_rattler, contacts, width, height)
    assert moduli["C22"] == pytest.approx(small["C22"], rel=1e-9)
    assert moduli["C33"] == pytest.approx(small["C33"], rel=1e-9)


def test_normal_model_is_the_frictionless_network():
    # model "normal" (a packing of mu = 0): normal springs on the translations,
    # whatever eta says; the lattice's C22 = (3 sqrt(3) / 4) k and no shear
    k = 2.0
    (grains, contacts), width, height, span = triangular_lattice(4, 30, k, 1e9 * k)
    normal = network_moduli.network_moduli(grains, contacts, width, height, eta=1.0, model="normal")
    assert normal["C22"] * span / height == pytest.approx(3.0 * math.sqrt(3.0) / 4.0 * k, rel=1e-5)
    assert normal["C33"] == 0.0
    assert normal["C22"] == pytest.approx(
        network_moduli.network_moduli(grains, contacts, width, height, eta=0.0)["C22"], rel=1e-9)
    B, springs, _ = network_moduli.compatibility(grains, contacts, width, height, model="normal")
    assert B.shape[1] == 2 * len(grains["id"]) and not np.any(springs[1::2])
    with pytest.raises(ValueError):
        network_moduli.network_moduli(grains, contacts, width, height, model="tangential")


def lattice_with_tangential_forces(k, ratio):
    """the triangular lattice of springs k between walls, and a
    tangential.dump of its grain-grain contacts with F_n = 2 and |F_t| =
    ratio F_n: grains, contacts, span, tangential, summary (W, h)"""
    (grains, contacts), width, height, span = triangular_lattice(4, 30, k, 1e9 * k)
    bulk = contacts[1] != 0
    normal_force = np.full(int(bulk.sum()), 2.0)
    tangential = {0: contacts[0][bulk], 1: contacts[1][bulk], 2: normal_force, 3: ratio * normal_force}
    return grains, contacts, span, tangential, {"W": width, "h": height}


def test_contacts_at_the_coulomb_limit_lose_their_tangential_spring():
    # every grain-grain contact of the lattice at the Coulomb limit: central
    # springs in the bulk, C22 = (3 sqrt(3) / 4) k (the closed form at eta =
    # 0), and no shear modulus at all, since the grains at the walls then
    # roll freely under their wall contacts' tangential springs; with none
    # at the limit, the network is the whole one, bit for bit
    from acoustic_tools import sound_collect
    k = 2.0
    grains, contacts, span, tangential, summary = lattice_with_tangential_forces(k, 0.5)
    width, height, normal_force = summary["W"], summary["h"], tangential[2]
    sliding = sound_collect.contact_mobilisation(tangential, grains, contacts, summary, mu=0.5)
    assert sliding["mobilised"] == 1.0 and sliding["mobilisation_mean"] == pytest.approx(1.0)
    assert sliding["C22_slipping"] * span / height == pytest.approx(3.0 * math.sqrt(3.0) / 4.0 * k, rel=1e-5)
    full = network_moduli.network_moduli(grains, contacts, width, height)
    assert abs(sliding["C33_slipping"]) < 1e-4 * full["C33"]    # (the regularisation's 1e-12)
    tangential[3] = 0.4 * normal_force
    sticking = sound_collect.contact_mobilisation(tangential, grains, contacts, summary, mu=0.5)
    assert sticking["mobilised"] == 0.0 and sticking["mobilised_0.9"] == 0.0
    assert sticking["C33_slipping"] == full["C33"] and sticking["C22_slipping"] == full["C22"]


def test_c33_without_the_most_mobilised_contacts():
    # the lattice's grain-grain contacts at m = 0.8 (|F_t| = 0.4 F_n, mu 0.5):
    # at the threshold 0.8 all of them lose their tangential springs (the
    # network of contacts at the Coulomb limit: no shear modulus), at 0.6
    # too; at m = 0.7 only the threshold 0.6 removes them, and 0.8 keeps
    # the whole network bit for bit; the shares count grain-grain contacts
    from acoustic_tools import sound_collect
    grains, contacts, _, tangential, summary = lattice_with_tangential_forces(2.0, 0.4)
    width, height, normal_force = summary["W"], summary["h"], tangential[2]
    full = network_moduli.network_moduli(grains, contacts, width, height)
    m = sound.mobilisation(tangential[2], tangential[3], 0.5)["m"]
    found = sound_collect.c33_without_mobilised(m, tangential, grains, contacts, summary)
    assert found["mobilised_0.8"] == 1.0 and found["mobilised_0.6"] == 1.0
    assert abs(found["C33_without_0.8"]) < 1e-4 * full["C33"]
    tangential[3] = 0.35 * normal_force
    m = sound.mobilisation(tangential[2], tangential[3], 0.5)["m"]
    found = sound_collect.c33_without_mobilised(m, tangential, grains, contacts, summary)
    assert found["mobilised_0.8"] == 0.0 and found["C33_without_0.8"] == full["C33"]
    assert found["mobilised_0.6"] == 1.0 and abs(found["C33_without_0.6"]) < 1e-4 * full["C33"]
