"""The fluctuation analysis of acoustic_tools.cavity for paper 004 (issue
43) on synthetic data with known answers: zero records and Eq. 7, the
stationarity check, Eq. 5, the meso portions, the local mu(I) (Eqs. 16-20)
and the fields of in.cavity's TAG.stress"""
import math

import numpy as np
import pytest

from acoustic_tools import cavity


def test_zero_fraction_and_eq7_with_zeros():
    rng = np.random.default_rng(11)
    mu, sigma, f0, p0 = 0.1, 0.5, 0.6, 0.2
    positive = cavity.sample_trunc_lognormal(40000, mu, sigma, f0, rng)
    n0 = int(p0 / (1 - p0) * len(positive))
    values = rng.permutation(np.concatenate([positive, np.zeros(n0)]))
    assert cavity.zero_fraction(values) == pytest.approx(n0 / len(values))
    # the positive records, scaled by the mean of all: Eq. 7 of x / m,
    # m = mean of all = (1 - p0) mean(positive); its parameters in the
    # scaled variable are mu - ln m, sigma, f0 / m
    fit = cavity.fit_eq7_with_zeros(values)
    m = values.mean()
    assert fit["p0"] == pytest.approx(n0 / len(values)) and fit["n_positive"] == len(positive)
    assert fit["mean"] == pytest.approx(m)
    assert fit["mu"] == pytest.approx(mu - math.log(m), abs=0.05)
    assert fit["sigma"] == pytest.approx(sigma, abs=0.03)
    assert fit["f0"] == pytest.approx(f0 / m, rel=0.1)
    # the histogram without the zeros integrates to 1 - p0 and follows (1 - p0) Eq. 7
    edges = np.linspace(0, 8, 81)
    x, dens, q0 = cavity.pdf_with_zeros(values, edges)
    assert q0 == fit["p0"]
    assert np.sum(dens * np.diff(edges)) == pytest.approx(1 - q0, abs=2e-3)
    model = (1 - q0) * cavity.trunc_lognormal_pdf(x, fit["mu"], fit["sigma"], fit["f0"])
    assert np.max(np.abs(dens - model)[x < 3]) < 0.05 * model.max()
    # a record of zeros only: no fit
    assert math.isnan(cavity.fit_eq7_with_zeros(np.zeros(50))["mu"])


def test_eq7_gaussian_limit_keeps_location_and_spread():
    rng = np.random.default_rng(12)
    # a log-normal shape well short of the limit: location and spread are its own
    mu, sigma, f0 = 0.1, 0.5, 0.6
    loc, spread, limit = cavity.eq7_location_spread(mu, sigma, f0)
    x = np.exp(mu + sigma * rng.standard_normal(400000))
    assert not limit and loc == pytest.approx((x - f0).mean(), rel=0.01) and spread == pytest.approx(x.std(), rel=0.01)
    # Gaussian records (mean 1, sd 0.3, nearly none below 0): the likelihood climbs on to
    # f0 -> infinity, sigma -> 0; mu, sigma, f0 drift but the location and spread are the Gaussian's
    values = 1.0 + 0.3 * rng.standard_normal(20000)
    fit = cavity.fit_eq7_with_zeros(values[values > 0])
    assert fit["gaussian_limit"] and fit["f0"] > cavity.EQ7_GAUSSIAN_F0 and fit["sigma"] < 0.01
    assert fit["loc"] == pytest.approx(1.0, abs=0.02) and fit["spread"] == pytest.approx(0.3, abs=0.02)
    assert math.isnan(cavity.eq7_location_spread(np.nan, 0.5, 1.0)[0])


def _ar1(n, phi, rng):
    x = np.empty(n)
    x[0] = 0
    e = rng.standard_normal(n)
    for k in range(1, n):
        x[k] = phi * x[k - 1] + e[k]
    return x


def test_stationarity_of_steady_and_drifting_records():
    rng = np.random.default_rng(5)
    steady = 10 + _ar1(40000, 0.9, rng)
    s = cavity.stationarity(steady)
    assert abs(s["z"]) < 3.5 and s["rel"] == pytest.approx(0, abs=0.04)
    assert s["cv1"] == pytest.approx(np.std(steady[:20000]) / np.mean(steady[:20000]))
    # a record whose second half sits 1 higher (a transient not skipped, a
    # slow drift): the halves differ by 1, about 10 of their standard errors
    step = np.where(np.arange(len(steady)) >= 20000, 1.0, 0.0)
    drift = steady + step
    d = cavity.stationarity(drift)
    assert d["mean2"] - d["mean1"] == pytest.approx(1.0 + s["mean2"] - s["mean1"], abs=1e-9)
    assert d["z"] > 5
    both = cavity.stationarity(np.column_stack([steady, drift]))
    assert both["z"][1] == pytest.approx(d["z"]) and both["z"][0] == pytest.approx(s["z"])
    with pytest.raises(ValueError):
        cavity.stationarity(np.ones(15))


def test_eq5_fit():
    ell = np.linspace(0.15, 0.6, 12)
    F = 0.88 - 0.5 * ell
    (c1, c2), (e1, e2), r2 = cavity.fit_eq5(ell, F)
    assert (c1, c2) == (pytest.approx(0.88), pytest.approx(0.5)) and r2 == pytest.approx(1.0)
    rng = np.random.default_rng(1)
    (c1, c2), (e1, e2), r2 = cavity.fit_eq5(np.append(ell, np.nan), np.append(F + 0.01 * rng.standard_normal(12), 1))
    assert abs(c1 - 0.88) < 4 * e1 and abs(c2 - 0.5) < 4 * e2 and 0.9 < r2 < 1


def test_central_portions():
    assert cavity.central_portions(10) == list(range(2, 9))     # paper 004's i = 3..9
    assert cavity.central_portions(3) == [1]


def test_local_rheology_of_a_simple_shear():
    # vx = gamma y: D_xy = gamma / 2; in-plane pressure p2, shear stress tau
    d, rho, gamma, p2, tau = 1e-3, 2500.0, 40.0, 300.0, 90.0
    x = np.linspace(0, 0.02, 21)
    y = np.linspace(0, 0.01, 11)
    X, Y = np.meshgrid(x, y)
    Dxx, Dyy, Dxy = cavity.strain_rate_2d(x, y, gamma * Y, 0 * X)
    assert np.allclose(Dxx, 0) and np.allclose(Dyy, 0) and np.allclose(Dxy, gamma / 2)
    # the stress resisting the shear vx = gamma y: the material above drags the material below
    # along +x, a traction +tau on a plane of normal +y, sigma_xy = -tau counted positive in compression
    I, mu = cavity.local_rheology(np.full_like(X, p2), np.full_like(X, p2), np.full_like(X, -tau), Dxx, Dyy, Dxy,
                                  d, rho)
    assert np.allclose(mu, tau / p2)
    assert np.allclose(I, math.sqrt(3 / 8) * d * gamma * math.sqrt(rho / p2))
    # no deformation or no pressure: undefined
    I0, mu0 = cavity.local_rheology(p2, p2, tau, 0.0, 0.0, 0.0, d, rho)
    assert np.isnan(I0) and np.isnan(mu0)


def test_fit_mu_I():
    rng = np.random.default_rng(3)
    I = np.logspace(-4, 0, 300)
    mu = cavity.mu_I_model(I, *cavity.PAPER_MU_I) + 0.005 * rng.standard_normal(len(I))
    (m1, m2, i0), (e1, e2, ei) = cavity.fit_mu_I(I, mu)
    assert abs(m1 - 0.12) < 4 * e1 and abs(m2 - 0.40) < 4 * e2 and abs(i0 - 0.13) < 4 * ei
    assert e1 < 0.01 and e2 < 0.02


def test_eq20_line_says_when_the_fit_is_not_constrained():
    from acoustic_tools import cavity_collect
    rng = np.random.default_rng(4)
    I = np.logspace(-4, 0, 300)
    mu = cavity.mu_I_model(I, *cavity.PAPER_MU_I) + 0.005 * rng.standard_normal(len(I))
    line = cavity_collect.eq20_line((*cavity.fit_mu_I(I, mu), len(I)))
    assert line.startswith("Eq. 20 fit") and "(300 bins)" in line and "not constrained" not in line
    # four points of a flat mu: I0 and mu2 are free
    flat = cavity.fit_mu_I([1e-3, 2e-3, 3e-3, 4e-3], [0.3, 0.31, 0.29, 0.3])
    assert "not constrained" in cavity_collect.eq20_line((*flat, 4))


def test_stress_and_velocity_fields_of_chunk_sums():
    # two bins of d x d, grains with known per-atom stress (N m, LAMMPS's
    # sign: negative in compression) and velocities
    d = 1e-3
    columns = {"Coord1": np.array([0.5e-3, 1.5e-3]), "Coord2": np.array([0.5e-3, 0.5e-3]),
               "Ncount": np.array([2.0, 0.0]), "c_satom[1]": np.array([-2e-7, 0.0]),
               "c_satom[2]": np.array([-4e-7, 0.0]), "c_satom[4]": np.array([1e-7, 0.0]),
               "vx": np.array([0.2, 0.0]), "vy": np.array([-0.1, 0.0])}
    x, y, sxx, syy, sxy, vx, vy = cavity.stress_and_velocity_fields(columns, d * d, d)
    assert sxx[0, 0] == pytest.approx(2e-7 / d ** 3) and syy[0, 0] == pytest.approx(4e-7 / d ** 3)
    assert sxy[0, 0] == pytest.approx(-1e-7 / d ** 3)
    assert vx[0, 0] == pytest.approx(0.1) and vy[0, 0] == pytest.approx(-0.05)
    assert np.isnan(sxx[0, 1]) and np.isnan(vx[0, 1])
    blocks = [(10, {"a": np.array([1.0, 2.0])}), (20, {"a": np.array([3.0, 4.0])}), (30, {"a": np.array([5.0, 0.0])})]
    assert np.allclose(cavity.mean_blocks(blocks, first_step=10)["a"], [4.0, 2.0])


def test_new_figures_are_written(tmp_path):
    from acoustic_tools import cavity_figures as cf

    rng = np.random.default_rng(2)
    paths = {name: tmp_path / f"{name}.png" for name in ("f4", "f5", "f6", "f8", "f11", "f14", "f19", "f20", "mem")}
    ell = np.array([0.2, 0.3, 0.4, 0.5])
    rows = [{"I_M": im, "NU": NU, "dtc_mean_dU": 2.0 / (1 + im / 0.01), "dtc_mean_s": 2e-3 / NU / (1 + im / 0.01)}
            for im in (1e-3, 1e-2, 0.1) for NU in (1, 10)]
    groups = {im: {"dtc_mean_dU": (1.0, 0.1, 2), "dtc_mean_s": (1e-3, np.nan, 1)} for im in (1e-3, 1e-2, 0.1)}
    cf.fig_memory(rows, groups, paths["mem"])
    cf.fig4_force_vortex(ell, 0.88 - 0.5 * ell, [0.3, 0.1, 0.03, 0.01], paths["f4"], fit=(0.88, 0.5))
    C = 0.9 ** np.arange(200)
    cf.fig8_autocorrelation({1e-2: (1e-4, C, 1e-2), 0.3: (1e-4, C ** 3, 1e-3)}, paths["f8"])
    samples = {(1, 37.0): cavity.sample_trunc_lognormal(3000, 0.0, 0.5, 0.6, rng),
               (10, 3704.0): cavity.sample_trunc_lognormal(3000, 0.0, 0.5, 0.6, rng)}
    cf.fig11_particle_pairs({1e-3: samples}, paths["f11"])
    # portions with zero records (no grain on the portion): they stay out of the densities
    series = rng.gamma(3.0, 1.0, (3000, 10)) * (rng.random((3000, 10)) > 0.2)
    cf.fig14_meso_pdfs(series, {1e-3: series, 1e-2: rng.exponential(1.0, (3000, 3))}, paths["f14"])
    x, y = np.linspace(0.5e-3, 0.1495, 150), np.linspace(0.5e-3, 0.0445, 45)
    X, Y = np.meshgrid(x, y)
    I = 1e-3 + 0 * X
    cf.fig6_mu_map(x, y, I, cavity.mu_I_model(I, *cavity.PAPER_MU_I) * (1 + 0.3 * np.sin(X * 40)), paths["f6"], 0.15, 0.03)
    cf.fig5_orientations(x, y, 0 * X + 2, 0 * X + 1, 0.5 + 0 * X, 0 * X, 0 * X, 1 + 0 * X, paths["f5"], 0.15, 0.03)
    Ip = np.logspace(-4, -1, 100)
    cf.fig19_mu_I({1e-3: (Ip, cavity.mu_I_model(Ip, 0.12, 0.4, 0.13))}, paths["f19"], fit=(0.12, 0.4, 0.13))
    wall = {0.3: np.where(rng.random(3000) < 0.1, 0.0, rng.exponential(1.0, 3000)), 1e-3: rng.normal(1, 0.3, 3000)}
    cf.fig20_loglinear({1e-3: samples[(1, 37.0)]}, wall, paths["f20"])
    for path in paths.values():
        data = path.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 5000


def test_by_im_groups_packings_and_pairs():
    from acoustic_tools import cavity_collect

    def row(im, NU, NP, seed, F):
        fit = {"mu": 0.1, "sigma": 0.5, "f0": 1.0, "p0": 0.0, "n": 10, "n_positive": 10, "mean": 1.0}
        return ({"I_M": im, "NU": NU, "NP": NP, "seed": seed, "Fnorm": F, "ell_over_L": 0.3, "dtc_mean_dU": 2.0,
                 "dtc_mean_s": 0.02, "cv_wall": 0.5, "skew_wall": 0.1, "eq7_wall": fit, "eq7_meso": fit,
                 "eq7_particle": fit}, None)
    runs = {"h30/a": row(1.0e-3, 1, 37.04, 1, 0.50), "h30/b": row(1.0e-3, 10, 3704, 1, 0.52),
            "h30seeds/c": row(1.0e-3, 1, 37.04, 2, 0.54), "h30/d": row(0.3, 10, 0.04115, 1, 0.85),
            "scan/e": row(1.0e-3, 1, 1000, 1, 0.9)}
    groups = cavity_collect.by_im(runs)
    assert sorted(groups) == [1e-3, 0.3]
    q = groups[1e-3]
    assert q["runs"] == 3 and q["pairs"] == [(1, 37.04), (10, 3704)] and q["seeds"] == [1, 2]
    mean, sem, n = q["Fnorm"]
    assert mean == pytest.approx(0.52) and sem == pytest.approx(0.02 / math.sqrt(3)) and n == 3
    assert groups[0.3]["Fnorm"][2] == 1 and np.isnan(groups[0.3]["Fnorm"][1])
    # a fit at Eq. 7's Gaussian limit is counted and left out of mu, sigma, f0, not of the location
    runs["h30/b"][0]["eq7_wall"] = {"mu": 12.0, "sigma": 3e-6, "f0": 1.6e5, "p0": 0.0}
    q = cavity_collect.by_im(runs)[1e-3]
    assert q["eq7_wall_gaussian"] == 1 and q["eq7_wall_mu"][2] == 2 and q["eq7_wall_loc"][2] == 3
    assert q["eq7_wall_mu"][0] == pytest.approx(0.1) and q["eq7_meso_gaussian"] == 0
    assert "Gaussian limit: location" in cavity_collect.e7(runs["h30/b"][0]["eq7_wall"])
    assert cavity_collect.e7(runs["h30/a"][0]["eq7_wall"]) == "0.1, 0.5, 1"


def test_spectrum_position(tmp_path):
    # a uniform density of states over 0 .. 100 kHz on 50 bins of 3 kHz up to 150 kHz
    centres = 1500.0 + 3000.0 * np.arange(50)
    density = np.where(centres < 100e3, 1.0, 0.0)
    density /= np.sum(density) * 3000.0
    below, band = cavity.spectrum_position(centres, density, 70e3)
    # the bins of centres below 100 kHz end at 99 kHz: a uniform density over 0 .. 99 kHz
    assert below == pytest.approx(70 / 99) and band == pytest.approx(0.999 * 99e3)
    assert cavity.spectrum_position(centres, density, 200e3)[0] == 1.0
    path = tmp_path / "c.modes.hist"
    path.write_text("# Time-averaged data for fix spectrum\n# TimeStep Number-of-rows\n# Row c_spectrum[1] c_spectrum[2]\n"
                    "100 2\n1 1000 1e-4\n2 3000 4e-4\n")
    x, dens = cavity.read_modes_histogram(str(path))
    assert np.allclose(x, [1000, 3000]) and np.allclose(dens, [1e-4, 4e-4])


def test_principal_direction():
    # simple shear vx = gamma y: extension along 45 degrees; a stress larger along y: its major axis at 90 degrees
    assert cavity.principal_direction(0.0, 0.0, 1.0) == pytest.approx(math.pi / 4)
    assert abs(cavity.principal_direction(1.0, 2.0, 0.0)) == pytest.approx(math.pi / 2)
    assert cavity.principal_direction(3.0, 1.0, 0.0) == pytest.approx(0.0)
    # the resisting stress of that shear (sxy = -tau, compression positive): major compression at -45 degrees
    assert cavity.principal_direction(1.0, 1.0, -0.3) == pytest.approx(-math.pi / 4)


def test_smooth_field():
    # a linear field is kept by a normalised kernel away from the edges; NaN bins stay NaN
    # and do not leak into their neighbours
    y, x = np.mgrid[0:20, 0:30].astype(float)
    field = 2.0 * x + y
    field[5, 5] = np.nan
    out = cavity.smooth_field(field, 0.5)
    assert np.isnan(out[5, 5]) and np.isfinite(out[5, 6])
    far = (np.hypot(x - 5, y - 5) > 3) & (x > 2) & (x < 27) & (y > 2) & (y < 17)
    assert np.allclose(out[far], field[far], atol=0.01)
    # next to the empty bin the kernel is lopsided: within a fraction of the field's step
    assert abs(out[5, 6] - field[5, 6]) < 1.0
    assert np.allclose(cavity.smooth_field(np.ones((5, 5)), 1.0), 1.0)


def test_us_effects_are_paired_by_packing(tmp_path):
    from acoustic_tools import cavity_collect, cavity_figures as cf

    def row(NU, freq, seed, F, dtc, below=np.nan):
        fit = {"mu": 0.0, "sigma": 0.01, "f0": 1e3, "p0": 0.0, "spread": 0.5 + freq * 1e-6,
               "gaussian_limit": True}                               # sigma says nothing there; spread does
        return ({"I_M": 0.0061 * NU, "NU": NU, "freq": freq, "seed": seed, "Fnorm": F, "dtc_mean_dU": dtc,
                 "cv_wall": 0.5, "skew_wall": 0.2, "eq7_wall": fit, "modes_below_drive": below}, None)
    runs = {}
    for seed, shift in ((1, 0.00), (2, 0.05), (3, -0.03)):          # packings differ by more than the effect
        runs[f"h30us/a{seed}"] = row(1, 0.0, seed, 0.55 + shift, 2.0 + shift)
        runs[f"h30us/b{seed}"] = row(1, 70e3, seed, 0.53 + shift + 0.001 * seed, 1.5 + shift, below=0.98)
    runs["h30us/c1"] = row(1, 35e3, 1, 0.56, 2.0, below=0.79)        # no undriven twin for seeds 2, 3
    effects = cavity_collect.us_effects(runs)
    q = effects[(1, 70e3)]
    mean, sem, n = q["Fnorm"]
    assert n == 3 and mean == pytest.approx(-0.02 + 0.002) and sem == pytest.approx(0.001 / math.sqrt(3))
    assert q["dtc_mean_dU"][0] == pytest.approx(-0.5) and q["eq7_wall_spread"][0] == pytest.approx(0.07)
    assert q["modes_below_drive"][0] == pytest.approx(0.98)
    assert effects[(1, 35e3)]["Fnorm"][2] == 1
    text = cavity_collect.print_tables({}, None) + ""
    assert "effect of the drive" not in text
    cf.fig_us_effects(effects, tmp_path / "us.png")
    assert (tmp_path / "us.png").read_bytes()[:4] == b"\x89PNG"
