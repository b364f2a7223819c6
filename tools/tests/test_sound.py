"""acoustic_tools.sound on synthetic signals and packings with known answers"""
import math

import numpy as np
import pytest
from scipy.optimize import brentq

from acoustic_tools import sound


def ricker(t, t0, width, amplitude):
    """amplitude (1 - u^2) exp(-u^2 / 2), u = (t - t0) / width: peak at t0,
    zero crossings at t0 -+ width"""
    u = (t - t0) / width
    return amplitude * (1.0 - u ** 2) * np.exp(-0.5 * u ** 2)


def test_coherent_peak_of_a_known_pulse():
    t = np.linspace(0.0, 100.0, 20001)
    t0, width, amplitude = 40.0, 3.0, 0.7
    f = ricker(t, t0, width, amplitude) + ricker(t, 60.0, 3.0, 2.0)    # a larger later arrival
    peak = sound.coherent_peak(t, f)
    # the 10 % level before the peak: (1 - u^2) exp(-u^2/2) = 0.1 for u < 0
    u10 = brentq(lambda u: (1 - u * u) * math.exp(-0.5 * u * u) - 0.1, -1.0, 0.0)
    assert peak["amplitude"] == pytest.approx(amplitude, rel=1e-6)
    assert peak["t_peak"] == pytest.approx(t0, abs=1e-4)
    assert peak["t10"] == pytest.approx(t0 + u10 * width, abs=1e-3)
    assert peak["t_zero"] == pytest.approx(t0 + width, abs=1e-3)
    assert peak["width"] == pytest.approx(width * (1.0 - u10), abs=2e-3)


def test_no_peak_is_an_error():
    t = np.linspace(0.0, 1.0, 11)
    with pytest.raises(ValueError):
        sound.coherent_peak(t, t)    # monotonic: no maximum


def test_time_of_flight_and_power_laws():
    assert sound.time_of_flight_speed(8.0, 30.0, 25.0, 95.0) == pytest.approx(17.0 / 65.0)
    x = np.array([8.0, 12.0, 18.0, 25.0])
    y = 3.0 * x ** -0.7
    exponent, prefactor = sound.power_law_fit(x, y)
    assert exponent == pytest.approx(-0.7)
    assert prefactor == pytest.approx(3.0)
    mid, slopes = sound.effective_exponents(x, y)
    assert np.allclose(slopes, -0.7)
    assert mid[0] == pytest.approx(math.sqrt(96.0))


def test_arrival_fit_of_points_on_a_line():
    """Fig. 6's fit: arrivals t = L / 0.25 + 3 give back c = 0.25, t0 = 3 and the range of L"""
    distance = np.array([8.0, 8.2, 12.0, 25.0, 50.5])
    fit = sound.arrival_fit(distance, distance / 0.25 + 3.0)
    assert fit["speed"] == pytest.approx(0.25, rel=1e-12) and fit["intercept"] == pytest.approx(3.0, rel=1e-12)
    assert (fit["L_min"], fit["L_max"], fit["samples"]) == (8.0, 50.5, 5)


def test_ensemble_mean_and_rms():
    t = np.linspace(0.0, 10.0, 101)
    base = np.sin(t)
    signals = [(t, base + 1.0), (t, base - 1.0), (t[:81], (base - 1.0)[:81]), (t[:81], (base + 1.0)[:81])]
    grid, mean, rms = sound.ensemble(signals)
    assert len(grid) == 81
    assert np.allclose(mean, base[:81])
    assert np.allclose(rms, 1.0)


def test_read_pulse_takes_the_last_block(tmp_path):
    path = tmp_path / "pulse.dat"
    path.write_text("# Time-averaged data\n# TimeStep Number-of-rows\n# Row c_p[1] c_p[2]\n"
                    "0 2\n1 0 5\n2 1 6\n100 3\n1 0 0\n2 0.5 1.5\n3 1 2.5\n")
    t, f = sound.read_pulse(path)
    assert list(t) == [0.0, 0.5, 1.0]
    assert list(f) == [0.0, 1.5, 2.5]


def test_rattlers_are_removed_one_after_the_other():
    # 1-2-3-4 a chain from the wall (j = 0): 1 touches the wall and 2; 2 touches
    # 1 and 3; 3 touches 2 and 4; 4 touches only 3; 5 touches nothing.  4 and 5
    # go first, then 3 (one contact left), then 2, then 1: all rattlers
    ids = [1, 2, 3, 4, 5]
    ci, cj = [1, 1, 2, 3], [0, 2, 3, 4]
    assert sound.rattlers(ids, ci, cj) == {1, 2, 3, 4, 5}
    # closing the loop 3-1 and adding a second wall contact to 3 keeps 1, 2, 3
    assert sound.rattlers(ids, ci + [3, 3], cj + [1, 0]) == {4, 5}


def test_static_properties_of_a_small_packing():
    # four grains of radius 0.5 in the bulk of a 4 x 10 cell (boundary 3):
    # 1, 2, 3 in a triangle of contacts, 4 a rattler; forces 1, 2, 3
    # (1 and 2 touch across the periodic x: their nearest images are 1 apart)
    grains = {"id": np.array([1, 2, 3, 4]), "x": np.array([0.2, 3.2, 3.7, 2.0]),
              "y": np.array([4.0, 4.0, 4.9, 6.0]), "z": np.zeros(4), "radius": np.full(4, 0.5)}
    contacts = {0: np.array([1, 2, 3]), 1: np.array([2, 3, 1]), 2: np.array([1.0, 2.0, 3.0])}   # by position
    out = sound.static_properties(grains, contacts, width=4.0, height=10.0, pressure=0.5, boundary=3.0)
    area = 4.0 * 4.0
    assert out["phi2"] == pytest.approx(4 * math.pi * 0.25 / area)
    assert out["phi3"] == pytest.approx(4 * 4.0 / 3.0 * math.pi * 0.125 / area)
    assert out["phi3_star"] == pytest.approx(3 * 4.0 / 3.0 * math.pi * 0.125 / area)
    assert out["f0"] == pytest.approx(0.25)
    assert out["z_star"] == pytest.approx(2.0)
    assert out["mean_force_over_p"] == pytest.approx(2.0 / 0.5)
    assert out["Z2"] == pytest.approx((1 + 4 + 9) / 3 / 4.0)
    assert out["Z3"] == pytest.approx((1 + 8 + 27) / 3 / 8.0)
    # fabric: 1-2 horizontal, 2-3 and 3-1 at n_y^2 = 0.81 / 1.06; the strong
    # contact (force 3 > mean 2) is 3-1
    assert out["F2"] == pytest.approx(2.0 / 3.0 * 0.81 / 1.06)
    assert out["F2_strong"] == pytest.approx(0.81 / 1.06)
    # the same grains in a 3D cell of depth 2: volume fractions halve, no Phi2
    deep = sound.static_properties(grains, contacts, width=4.0, height=10.0, pressure=0.5, boundary=3.0, depth=2.0)
    assert "phi2" not in deep
    assert deep["phi3_star"] == pytest.approx(out["phi3_star"] / 2.0)
    assert deep["z_star"] == out["z_star"]


def test_linear_response():
    good = {"C11": 1.0, "C11_half": 1.1, "C22": 2.0, "C22_half": 1.9, "C33": 0.5, "C33_half": 0.45}
    assert sound.linear_response(good)
    assert not sound.linear_response(dict(good, C33_half=0.2)), "a rearrangement in the second half"
    assert not sound.linear_response(dict(good, C22=-0.1)), "a negative modulus"
    assert not sound.linear_response(dict(good, C11=float("nan"))), "not a number"
    assert not sound.linear_response({"C11": 1.0}), "no half-way values"


def test_speeds():
    c_l, c_t = sound.sound_speeds(0.0188, 0.004, 0.52)
    assert c_l == pytest.approx(math.sqrt(0.0188 / 0.52))
    assert c_t == pytest.approx(math.sqrt(0.004 / 0.52))
    # paper 003 Eq. 18 at p = 1e-4, and Eq. 19 with eta = 1
    assert sound.triangular_lattice_speed(1e-4) == pytest.approx(0.24471, rel=1e-4)
    assert sound.triangular_lattice_speed(1e-4, eta=1.0) == pytest.approx(0.24471 * math.sqrt(4 / 3), rel=1e-4)


def test_figures_are_written(tmp_path):
    from acoustic_tools import sound_figures

    t = np.linspace(0.0, 100.0, 500)
    signals = [(t, np.exp(-((t - 40.0 - k) / 5.0) ** 2)) for k in range(3)]
    paths = [tmp_path / name for name in ("f4.png", "f6.png", "f7.png", "f8.png", "f9.png", "ratio.png")]
    sound_figures.fig4_signals(signals, sound.ensemble(signals), paths[0], "synthetic")
    sound_figures.fig6_arrival_times([8.0, 16.0, 25.0], [20.0, 50.0, 85.0], [30.0, 62.0, 100.0],
                                     [40.0, 75.0, 120.0], paths[1], "synthetic")
    sound_figures.fig7_exponents({"chain": ([8, 16, 32], [1.0, 0.63, 0.4], [2.0, 2.5, 3.2])}, paths[2])
    sound_figures.fig8_speeds([1e-6, 1e-5, 1e-4], [0.12, 0.18, 0.25], [0.01, 0.01, 0.01],
                              [0.07, 0.11, 0.17], [0.03, 0.05, 0.07], paths[3])
    sound_figures.fig9_spectrum(np.sqrt(np.linspace(0.0, 1.0, 50)) / (2 * math.pi), paths[4], "synthetic")
    sound_figures.stress_ratio_against_overshoot([1.5, 3.0, 10.0], [0.8, 1.0, 1.2], [1e-4, 1e-5, 1e-6], paths[5])
    # Fig. 7 with error bars, Fig. 8 with lattice points, Figs. 5 and 12
    more = [tmp_path / name for name in ("f7e.png", "f8l.png", "f5.png", "f12.png")]
    sound_figures.fig7_exponents({"poly": ([8, 16, 32], [1.0, 0.6, 0.35], [2.0, 2.6, 3.3], [0.05, 0.03, 0.02],
                                           [0.1, 0.1, 0.1])}, more[0])
    sound_figures.fig8_speeds([1e-6, 1e-5, 1e-4], [0.12, 0.18, 0.25], [0.01, 0.01, 0.01], [0.07, 0.11, 0.17],
                              [0.03, 0.05, 0.07], more[1], {"triangular lattice, frictionless": ([1e-5], [0.17])})
    sound_figures.fig5_heights({"H = 8": signals[0], "H = 25": signals[2]}, more[2], "synthetic")
    x = np.linspace(-3.0, 3.0, 50)
    sound_figures.fig12_shapes({"chain": (x, np.exp(-x * x), "line"), "lattice": (x, np.exp(-x * x), "points")},
                               more[3], "synthetic")
    for path in paths + more:
        assert path.stat().st_size > 1000, path


def test_packing_figures_are_readable(tmp_path):
    # Figs. 1, 3 and 10 on a small synthetic packing: written at the print
    # widths (one column, the page) and PRINT_DPI, the type PRINT_TYPE points
    from PIL import Image

    from acoustic_tools import sound_figures

    rng = np.random.default_rng(1)
    width, height = 10.0, 8.0
    x, y = [a.ravel() + 0.5 for a in np.meshgrid(np.arange(width), np.arange(height))]
    radius = np.full(len(x), 0.5)
    grains = {"x": x, "y": y, "radius": radius}
    segments = np.array([(x[i], y[i], x[i] + 1.0, y[i], f, f ** (1 / 3)) for i, f in
                         enumerate(rng.exponential(1e-4, len(x))) if x[i] + 1.0 < width])
    ux, uy = rng.normal(0.0, 0.01, (2, len(x)))
    paths = [tmp_path / name for name in ("f1.png", "f3.png", "f10.png")]
    sound_figures.fig1_network(grains, segments, segments[:, 4], segments[:, 5], width, height, paths[0],
                               "synthetic")
    sound_figures.fig3_snapshot(x, y, radius, ux, uy, width, height, 76.7, paths[1], "synthetic")
    shapes = [(f"n = {n}\nsynthetic\n$f$ = 0.01, PR = 0.5", x, y, radius, uy, ux) for n in range(5)]
    sound_figures.fig10_modes(shapes, width, height, paths[2], "synthetic")
    widths = {path: Image.open(path).size[0] for path in paths}
    dpi = sound_figures.PRINT_DPI
    assert widths[paths[0]] == pytest.approx(sound_figures.PAGE * dpi, abs=2)
    assert widths[paths[1]] == pytest.approx(sound_figures.COLUMN * dpi, abs=2)
    assert widths[paths[2]] == pytest.approx(sound_figures.PAGE * dpi, abs=2)
    assert sound_figures.PRINT_TYPE >= 10 and all(v == sound_figures.PRINT_TYPE
                                                  for v in sound_figures.PRINT_STYLE.values())


def test_c33_candidates_read_the_lines_where_asked():
    """C33 = 0.01 (z* - 3) over five H = 25 packings: the line in z* read at
    the paper's z* gives back the law there; the smallest overshoot is found;
    a packing of another height is left out"""
    from acoustic_tools import sound_collect
    z = [3.40, 3.45, 3.50, 3.55, 3.60]
    overshoot = [1.2, 1.1, 1.05, 1.1, 1.2]
    per_sample = {(1e-4, 25, k): {"z_star": zk, "overshoot": o, "C33": 0.01 * (zk - 3.0)}
                  for k, (zk, o) in enumerate(zip(z, overshoot))}
    per_sample[(1e-4, 8, 0)] = {"z_star": 9.0, "overshoot": 1.0, "C33": 1.0}
    c = sound_collect.c33_candidates(per_sample, [1e-4])[1e-4]
    paper_z = sound.PAPER_TABLE_I[1e-4]["z_star"][0]
    assert c["samples"] == 5 and c["slope_z"] == pytest.approx(0.01, rel=1e-9)
    assert c["C33_at_paper_z"] == pytest.approx(0.01 * (paper_z - 3.0), rel=1e-9)
    assert c["least_overshoot"] == pytest.approx(1.05) and c["paper"] == 4.0e-3


def test_mobilisation_of_known_contacts():
    """|F_t| / (mu F_n) of four contacts, one without normal force (left out)"""
    found = sound.mobilisation([1.0, 2.0, 1.0, 0.0], [0.5, 0.92, 0.1, 0.0], mu=0.5)
    assert found["fraction_at_limit"] == pytest.approx(1.0 / 3.0)
    assert found["fraction_above_0.9"] == pytest.approx(2.0 / 3.0)
    assert found["mean"] == pytest.approx((1.0 + 0.92 + 0.2) / 3.0)
    assert list(found["at_limit"]) == [True, False, False, False]
    with pytest.raises(ValueError):
        sound.mobilisation([1.0], [0.1], mu=0.0)


def test_c33_and_sliding_pairs_the_strains_seed_by_seed(tmp_path):
    """C33 measured at another strain (study.py run --moduli-strain) over
    C33 of the same seed at the default strain; a seed without its pair and
    another height are left out"""
    from acoustic_tools import sound_collect, study
    per_sample = {(1e-7, 25, s): {"C33": 1e-4 * s} for s in (1, 2, 3)}
    per_sample[(1e-7, 8, 1)] = {"C33": 1.0}
    for s, c33 in ((1, 0.5e-4), (2, 1.2e-4), (4, 9.0)):
        directory = tmp_path / f"p1e-7_H25_s{s}_e0.5"
        study.write_job(str(directory), {"kind": "sample", "p": 1e-7, "H": 25, "seed": s, "piston_mass": 1.0,
                                         "piston_speed": 0.001, "mu": 0.5, "moduli_strain": 0.5})
        study.write_result(str(directory), {"C33": c33})
    assert sound_collect.moduli_strains(str(tmp_path)) == [0.5]
    entry = sound_collect.c33_and_sliding(str(tmp_path), per_sample, [1e-7])[1e-7]
    found = entry["strains"][0.5]
    assert found["pairs"] == 2 and found["ratio"][0] == pytest.approx((0.5 + 0.6) / 2.0)
    assert entry["paper"] == 1.2e-4 and entry["packings"] == 0
    assert "C33(strain 0.5) / C33 (pairs)" in "\n".join(sound_collect.c33_sliding_table(
        {"1e-07": entry}))


def test_c33_and_piston_pairs_each_piston_seed_by_seed():
    """A slower piston's samples over the default piston's of the same seed:
    the paired ratios of the network's and the DEM's C33, the network's over
    Table II's, the checks of both; a seed without its pair, another height
    and a pressure without samples are left out"""
    from acoustic_tools import sound_collect
    per_sample = {(1e-7, 25, s): {"C33": 2e-4 * s, "C33_network": 1e-4 * s, "phi2": 0.82, "z_star": 3.2,
                                  "sigma_ratio": 0.8, "overshoot": 50.0} for s in (1, 2, 3)}
    per_sample[(1e-7, 8, 1)] = {"C33": 1.0, "C33_network": 1.0}
    slow = {(1e-7, 1): {"C33": 1e-4, "C33_network": 0.8e-4, "phi2": 0.81, "z_star": 3.18,
                        "sigma_ratio": 0.79, "overshoot": 20.0},
            (1e-7, 2): {"C33": 3e-4, "C33_network": 1.2e-4, "phi2": 0.80, "z_star": 3.19,
                        "sigma_ratio": 0.81, "overshoot": 10.0},
            (1e-7, 4): {"C33": 9.0, "C33_network": 9.0, "phi2": 0.5, "z_star": 9.0,
                        "sigma_ratio": 9.0, "overshoot": 9.0}}
    found = sound_collect.c33_and_piston(per_sample, {(1, 3.16e-5): slow}, [1e-7, 1e-6])
    assert list(found) == [1e-7]
    c = found[1e-7]["mass 1, dashpot speed 3.16e-05"]
    assert c["pairs"] == 2
    assert c["C33_network_ratio"][0] == pytest.approx((0.8 + 0.6) / 2.0)
    assert c["C33_ratio"][0] == pytest.approx((0.5 + 0.75) / 2.0)
    assert c["C33_network_over_paper"][0] == pytest.approx(1.0e-4 / 1.2e-4)
    assert c["phi2"][0] == pytest.approx(0.805) and c["default"]["phi2"][0] == pytest.approx(0.82)
    assert c["overshoot"][0] == pytest.approx(15.0)
    table = "\n".join(sound_collect.c33_piston_table({"1e-07": found[1e-7]}))
    assert "| 1e-07 | mass 1, dashpot speed 3.16e-05 | 2 |" in table


def test_piston_checks_leave_out_pistons_without_samples_at_1e_4(tmp_path):
    """A piston run at 1e-7 only (a job of study.py run --piston-speed) has
    no row in the table of the pistons at p = 1e-4"""
    from acoustic_tools import sound_collect, study
    for name, speed in (("p1e-7_H25_s1", 0.001), ("p1e-7_H25_s1_v3.16e-5", 3.16e-5)):
        study.write_job(str(tmp_path / name), {"kind": "sample", "p": 1e-7, "H": 25, "seed": 1, "piston_mass": 1.0,
                                               "piston_speed": speed, "mu": 0.5})
    assert len(sound_collect.pistons(str(tmp_path))) == 2
    assert sound_collect.piston_checks(str(tmp_path)) == {}


def test_fig5_draws_the_whole_record_of_a_signal_without_a_zero_crossing(tmp_path):
    import warnings

    from acoustic_tools import sound_figures

    t = np.linspace(0.0, 100.0, 500)
    gaussian = (t, np.exp(-((t - 40.0) / 5.0) ** 2))  # never crosses zero: t_zero is nan
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # matplotlib warns on the singular x range (0, 0)
        sound_figures.fig5_heights({"H = 8": gaussian}, tmp_path / "f5.png", "synthetic")
    assert (tmp_path / "f5.png").stat().st_size > 1000
