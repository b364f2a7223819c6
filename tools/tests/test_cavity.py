"""acoustic_tools.cavity and cavity_figures on synthetic data with known answers
(paper 004, granular lid-driven cavity)"""
import math

import numpy as np
import pytest
from scipy import integrate, signal, special, stats

from acoustic_tools import cavity, lammps_output


# ---------------------------------------------------------------------------
# Eq. 1-4

def test_control_parameters_and_the_papers_inertial_numbers():
    d, H, rho_p, phi, g = 1e-3, 0.03, 2500.0, 0.6, 9.81
    P = cavity.pressure_from_NP(2.0, phi, rho_p, g, H)
    U = cavity.velocity_from_NU(10.0, g, d)
    assert P == pytest.approx(2.0 * 0.6 * 2500 * 9.81 * 0.03)
    assert U == pytest.approx(10.0 * math.sqrt(9.81e-3))
    im = cavity.inertial_number(d, rho_p, phi, P, H, U)
    assert im == pytest.approx(d * math.sqrt(phi * rho_p / P) * U / H)
    assert im == pytest.approx(cavity.inertial_number_from_NP_NU(2.0, 10.0, d / H))
    # the (N_U, N_P, I_M) of paper 004's captions, all with H/d = 30
    for NU, NP, quoted in ((10, 1, 6.09e-2), (10, 25, 1.22e-2), (1, 25, 1.2e-3), (10, 0.04, 0.3)):
        assert cavity.inertial_number_from_NP_NU(NP, NU, 1.0 / 30.0) == pytest.approx(quoted, rel=0.02)
    assert cavity.volume_fraction_3d(0.9) == pytest.approx(0.6)


def test_mean_force_model_limits():
    r1, r2, I0 = 0.53, 0.86, 0.02
    assert cavity.mean_force_model(1e-9, r1, r2, I0) == pytest.approx(r1, abs=1e-6)
    assert cavity.mean_force_model(1e9, r1, r2, I0) == pytest.approx(r2, abs=1e-6)
    assert cavity.mean_force_model(I0, r1, r2, I0) == pytest.approx(0.5 * (r1 + r2))


def test_fit_mean_force_exact_curve():
    I = np.logspace(-3.5, 0.0, 25)
    F = cavity.mean_force_model(I, 0.53, 0.86, 0.02)
    (r1, r2, I0), _ = cavity.fit_mean_force(I, F)
    assert (r1, r2, I0) == (pytest.approx(0.53, rel=1e-6), pytest.approx(0.86, rel=1e-6),
                            pytest.approx(0.02, rel=1e-5))


def test_fit_mean_force_with_noise():
    # 40 points with Gaussian noise s = 0.01: the expected standard errors are
    # s sqrt(diag((J^T J)^-1)), J the Jacobian in (r1, r2, ln I0) at the truth
    true = np.array([0.53, 0.86, 0.02])
    s = 0.01
    I = np.logspace(-3.5, 0.0, 40)
    F = cavity.mean_force_model(I, *true) + s * np.random.default_rng(4).standard_normal(len(I))
    w = 1.0 / (1.0 + true[2] / I)
    J = np.column_stack([1.0 - w, w, -(true[1] - true[0]) * w * w * true[2] / I])
    expected = s * np.sqrt(np.diag(np.linalg.inv(J.T @ J)))
    expected[2] *= true[2]                          # s_I0 = I0 s_lnI0
    fit, err = cavity.fit_mean_force(I, F)
    assert np.all(np.abs(np.array(fit) - true) < 4.0 * expected)
    assert np.all(expected < [0.006, 0.006, 0.002])  # tight enough to catch a wrong fit
    # the returned errors scale with the residuals: within 35 % of the expected
    assert np.allclose(err, expected, rtol=0.35)


# ---------------------------------------------------------------------------
# Eq. 6

def test_autocorrelation_matches_the_direct_sum():
    x = np.random.default_rng(1).standard_normal(300) + 3.0
    C = cavity.autocorrelation(x, 20)
    f = x - x.mean()
    direct = np.array([np.dot(f[:len(f) - k], f[k:]) for k in range(21)]) / np.dot(f, f)
    assert C[0] == pytest.approx(1.0)
    assert np.allclose(C, direct, atol=1e-12)
    assert np.all(np.isnan(cavity.autocorrelation(np.full(50, 2.0), 5)))


def test_ar1_correlation_time():
    # x_{n+1} = a x_n + noise: C(k) = a^k, C = 0.15 at k = ln 0.15 / ln a (18.0
    # steps for a = 0.9).  Bartlett: var C(k) ~ (1 + a^2)/(1 - a^2)/N, so with
    # N = 1e6 s_C = 0.003 and s_k = s_C / |dC/dk| = 0.003/(0.15 ln(1/a)) = 0.2
    # steps (1.1 %): 4 % is 3.5 standard deviations
    a, n, dt = 0.9, 1_000_000, 1e-4
    x = signal.lfilter([1.0], [1.0, -a], np.random.default_rng(7).standard_normal(n))
    C = cavity.autocorrelation(x, 60)
    k = np.arange(61)
    assert np.all(np.abs(C - a ** k) < 0.015)
    expected = math.log(0.15) / math.log(a) * dt
    assert cavity.correlation_time(C, dt) == pytest.approx(expected, rel=0.04)


def test_correlation_time_interpolates_the_first_crossing():
    C = 1.0 - np.arange(12) / 10.0                  # 0.15 at lag 8.5 exactly
    assert cavity.correlation_time(C, 2.0) == pytest.approx(17.0)
    a = 0.8
    C = a ** np.arange(20)
    k = math.ceil(math.log(0.15) / math.log(a))     # first sample below 0.15
    frac = (C[k - 1] - 0.15) / (C[k - 1] - C[k])
    assert cavity.correlation_time(C, 1.0) == pytest.approx(k - 1 + frac)
    # the lowest crossing of a non-monotonic C is kept; none gives NaN
    C = np.array([1.0, 0.5, 0.1, 0.4, 0.05])
    assert cavity.correlation_time(C, 1.0) == pytest.approx(1.0 + 0.35 / 0.4)
    assert math.isnan(cavity.correlation_time(np.array([1.0, 0.8, 0.5, 0.3]), 1.0))
    times, mean = cavity.portion_correlation_times(
        np.column_stack([signal.lfilter([1.0], [1.0, -0.5], np.random.default_rng(3).standard_normal(20000)),
                         np.sin(np.arange(20000) * 1e-5)]), 1.0, 10)
    assert math.isnan(times[1]) and mean == pytest.approx(times[0])
    assert times[0] == pytest.approx(math.log(0.15) / math.log(0.5), rel=0.15)


# ---------------------------------------------------------------------------
# Eq. 7

PARAMS = [(0.2, 0.6, 0.8), (1.0, 0.2, 1.7), (-0.5, 1.0, 0.3)]


@pytest.mark.parametrize("mu,sigma,f0", PARAMS)
def test_trunc_lognormal_pdf_is_the_truncated_lognormal(mu, sigma, f0):
    total, _ = integrate.quad(lambda f: cavity.trunc_lognormal_pdf(f, mu, sigma, f0), 0.0, np.inf)
    assert total == pytest.approx(1.0, abs=1e-7)
    # the density of X - f0, X log-normal, given X > f0; S = P(X > f0)
    X = stats.lognorm(s=sigma, scale=math.exp(mu))
    f = np.array([1e-3, 0.3, 1.0, 2.5, 7.0])
    assert np.allclose(cavity.trunc_lognormal_pdf(f, mu, sigma, f0), X.pdf(f + f0) / X.sf(f0), rtol=1e-10)
    assert np.allclose(cavity.trunc_lognormal_cdf(f, mu, sigma, f0), 1.0 - X.sf(f + f0) / X.sf(f0))
    assert np.all(cavity.trunc_lognormal_pdf([-1.0, 0.0], mu, sigma, f0) == 0.0)


def _quantile_sample(n, mu, sigma, f0):
    """n points at the quantiles (k + 1/2)/n of Eq. 7: a sample without noise"""
    survival = special.ndtr(-(math.log(f0) - mu) / sigma)
    v = (np.arange(n) + 0.5) / n
    return np.exp(mu - sigma * special.ndtri(v * survival)) - f0


def _standard_errors(samples, fit):
    """sqrt(diag(inverse observed information)) of (mu, sigma, f0) at fit,
    the Hessian of the log-likelihood by central differences"""
    p, h, k = np.asarray(fit, float), 1e-3, len(fit)
    def ll(q):
        return cavity.trunc_lognormal_loglik(samples, *q)
    hess = np.zeros((k, k))
    for i in range(k):
        for j in range(k):
            ei, ej = np.eye(k)[i] * h, np.eye(k)[j] * h
            hess[i, j] = (ll(p + ei + ej) - ll(p + ei - ej) - ll(p - ei + ej) + ll(p - ei - ej)) / (4 * h * h)
    return np.sqrt(np.diag(np.linalg.inv(-hess)))


@pytest.mark.parametrize("mu,sigma,f0", PARAMS[:2])
def test_fit_trunc_lognormal(mu, sigma, f0):
    true = np.array([mu, sigma, f0])
    # noiseless quantiles: the maximum likelihood is the truth up to O(1/n)
    assert np.allclose(cavity.fit_trunc_lognormal(_quantile_sample(20000, mu, sigma, f0)), true, atol=5e-3)
    # n = 20000 random samples: distributed as Eq. 7 (Kolmogorov-Smirnov), and
    # the fit within 4 standard errors of the observed information (which for
    # these parameters are 0.05 or less on mu, 0.02 on sigma, 0.11 on f0)
    x = cavity.sample_trunc_lognormal(20000, mu, sigma, f0, np.random.default_rng(11))
    assert x.min() > 0
    assert stats.kstest(x, lambda f: cavity.trunc_lognormal_cdf(f, mu, sigma, f0)).pvalue > 1e-3
    fit = cavity.fit_trunc_lognormal(x)
    se = _standard_errors(x, fit)
    assert np.all(se < [0.06, 0.025, 0.12])
    assert np.all(np.abs(np.array(fit) - true) < 4.0 * se)


def test_normalised_and_portion_pdfs():
    x = np.random.default_rng(5).exponential(3.0, 5000)
    centres, dens = cavity.normalised_pdf(x, 40)
    width = centres[1] - centres[0]
    assert np.sum(dens) * width == pytest.approx(1.0)
    assert np.sum(centres * dens) * width == pytest.approx(1.0, abs=width)    # mean of x / mean = 1
    same = np.column_stack([x] * 10)
    c2, mean = cavity.mean_portion_pdf(same * np.arange(1, 11), 30)
    c1, one = cavity.normalised_pdf(x, np.linspace(0.0, (x / x.mean()).max(), 31))
    assert np.allclose(c1, c2) and np.allclose(mean, one)


# ---------------------------------------------------------------------------
# Fig. 3a: the vortex

def cellular_field(L, H, x0, y0, nx, ny, pad=2):
    """psi = sin(pi (x/L)^p) sin(pi (y/H)^q), its maximum moved to (x0, y0)
    by p, q with (x0/L)^p = (y0/H)^q = 1/2; zero on the four walls.  The
    velocity (vx = dpsi/dy, vy = -dpsi/dx) at the centres of nx x ny bins
    of the cavity and of pad empty (NaN) bins around it, flat."""
    p, q = math.log(0.5) / math.log(x0 / L), math.log(0.5) / math.log(y0 / H)
    X, Y = np.meshgrid((np.arange(-pad, nx + pad) + 0.5) * L / nx, (np.arange(-pad, ny + pad) + 0.5) * H / ny)
    inside = (X > 0) & (X < L) & (Y > 0) & (Y < H)
    Xc, Yc = np.clip(X, 1e-9, L), np.clip(Y, 1e-9, H)
    sx, sy = (Xc / L) ** p, (Yc / H) ** q
    vx = np.where(inside, np.sin(np.pi * sx) * np.cos(np.pi * sy) * np.pi * q * sy / Yc, np.nan)
    vy = np.where(inside, -np.cos(np.pi * sx) * np.pi * p * sx / Xc * np.sin(np.pi * sy), np.nan)
    return X.ravel(), Y.ravel(), vx.ravel(), vy.ravel()


@pytest.mark.parametrize("x0,y0", [(3.2, 0.6), (2.5, 0.5), (4.1, 0.7)])
def test_vortex_centre_of_a_cellular_field(x0, y0):
    L, H, nx, ny = 5.0, 1.0, 50, 10
    dx, dy = L / nx, H / ny
    X, Y, vx, vy = cellular_field(L, H, x0, y0, nx, ny)
    order = np.random.default_rng(0).permutation(len(X))        # any bin order
    for v in (vy[order], None):
        xc, yc, ell = cavity.vortex_centre(X[order], Y[order], vx[order], v, L)
        assert abs(xc - x0) < 0.15 * dx and abs(yc - y0) < 0.15 * dy
        assert ell == pytest.approx((L - xc) / L)
    # the maximum is 0.5 bin from the nearest bin centre when x0 = 3.2 (bins
    # of 0.1 centred at 3.15, 3.25): the refinement is needed
    _, _, ell = cavity.vortex_centre(X, Y, vx, vy, L, x_right=L + 0.5)
    assert ell == pytest.approx((L + 0.5 - x0) / L, abs=0.15 * dx / L)


def test_vortex_from_an_ave_chunk_file(tmp_path):
    # the field through the file as fix ave/chunk bin/2d writes it (%g, empty
    # bins with count 0 and velocity 0), two blocks with different counts
    L, H, x0, y0 = 5.0, 1.0, 3.2, 0.6
    X, Y, vx, vy = cellular_field(L, H, x0, y0, 50, 10)
    lines = ["# Chunk-averaged data for fix flowrec and group grains",
             "# Timestep Number-of-chunks Total-count", "# Chunk Coord1 Coord2 Ncount vx vy"]
    for step, scale in ((1000, 1.0), (2000, 3.0)):
        counts = np.where(np.isfinite(vx), scale, 0.0)
        lines.append(f"{step} {len(X)} {counts.sum():g}")
        lines += [f"  {k + 1} {X[k]:g} {Y[k]:g} {counts[k]:g} {np.nan_to_num(vx[k]):g} {np.nan_to_num(vy[k]):g}"
                  for k in range(len(X))]
    path = tmp_path / "cavity.flow"
    path.write_text("\n".join(lines) + "\n")
    flow, total = cavity.time_average_chunks(lammps_output.read_ave_chunk(path))
    assert np.all(np.isnan(flow["vx"][total == 0]))
    xc, yc, _ = cavity.vortex_centre(flow["Coord1"], flow["Coord2"], flow["vx"], flow["vy"], L)
    assert abs(xc - x0) < 0.015 and abs(yc - y0) < 0.015


# ---------------------------------------------------------------------------
# the mean flow and the wall portions, through the readers of lammps_output

def test_average_of_ave_chunk_blocks(tmp_path):
    path = tmp_path / "c.txt"
    path.write_text("# Chunk-averaged data for fix flow and group all\n"
                    "# Timestep Number-of-chunks Total-count\n"
                    "# Chunk Coord1 Coord2 Ncount vx vy\n"
                    "10 3 4\n  1 0.5 0.5 3 1 -1\n  2 0.5 1.5 1 2 0\n  3 1.5 0.5 0 0 0\n"
                    "20 3 4\n  1 0.5 0.5 1 5 1\n  2 0.5 1.5 3 6 0\n  3 1.5 0.5 0 0 0\n")
    blocks = lammps_output.read_ave_chunk(path)
    mean, total = cavity.time_average_chunks(blocks)
    assert list(total) == [4.0, 4.0, 0.0]
    assert mean["vx"][:2] == pytest.approx([(3 * 1 + 1 * 5) / 4, (1 * 2 + 3 * 6) / 4])
    assert mean["vy"][0] == pytest.approx(-0.5)
    assert math.isnan(mean["vx"][2])
    assert list(mean["Coord1"]) == [0.5, 0.5, 1.5] and list(mean["Ncount"]) == [2.0, 2.0, 0.0]
    later, _ = cavity.time_average_chunks(blocks, first_step=15)
    assert list(later["vx"][:2]) == [5.0, 6.0]


def test_portion_forces_of_dumped_contacts(tmp_path):
    box = "ITEM: BOX BOUNDS pp ff pp\n-1e-03 5.1e-02\n-1e-03 4.4e-02\n-1e-03 1e-03\n"
    text = ("ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n2\n" + box +
            "ITEM: ATOMS id v_ycontact v_fwall\n7 0.0125 1.5e-3\n12 0.02 2\n"
            "ITEM: TIMESTEP\n200\nITEM: NUMBER OF ATOMS\n0\n" + box +
            "ITEM: ATOMS id v_ycontact v_fwall\n"
            "ITEM: TIMESTEP\n300\nITEM: NUMBER OF ATOMS\n1\n" + box +
            "ITEM: ATOMS id v_ycontact v_fwall\n3 0.001 4\n")
    path = tmp_path / "cavity.contacts"
    path.write_text(text)
    snaps = lammps_output.read_dump(path)
    # portions of the wall between y = 0.005 and 0.025: 0.0125 is in the 4th
    # of ten, 0.02 in the 8th, 0.001 below the bottom counts in the 1st
    steps, forces = cavity.portion_force_series(snaps, 0.005, 0.025)
    assert list(steps) == [100, 200, 300] and forces.shape == (3, 10)
    expected = np.zeros((3, 10))
    expected[0, 3], expected[0, 7], expected[2, 0] = 1.5e-3, 2.0, 4.0
    assert np.allclose(forces, expected)
    assert np.allclose(cavity.portion_forces([0.0125, 0.02, 0.03], [1.0, 2.0, 3.0], 0.005, 0.025, 4),
                       [0.0, 1.0, 0.0, 5.0])


# ---------------------------------------------------------------------------
# figures

def test_figures_are_written(tmp_path):
    from acoustic_tools import cavity_figures as cf

    rng = np.random.default_rng(2)
    IM = np.array([1e-3, 5e-3, 2e-2, 8e-2, 0.3])
    paths = {name: tmp_path / f"{name}.png" for name in ("f2", "f3", "f9", "f10", "f12", "f13", "f14", "phi")}
    cf.fig3_vortex_and_force(IM, [0.5, 0.5, 0.45, 0.35, 0.3],
                             cavity.mean_force_model(IM, 0.53, 0.86, 0.02) + 0.01 * rng.standard_normal(5),
                             paths["f3"], title="synthetic")
    C = np.array([0.9 ** np.arange(80) * (1 + 0.01 * i) for i in range(10)])
    cf.fig9_autocorrelation(1e-4, C, paths["f9"], "synthetic")
    cf.fig10_correlation_times(IM, rng.random((5, 10)) * [[1], [1], [1], [np.nan], [0.1]], paths["f10"])
    samples = {im: cavity.sample_trunc_lognormal(2000, 0.2, 0.4 + im, 0.8, rng) for im in IM[:3]}
    cf.fig12_particle_pdfs(samples, paths["f12"])
    cf.fig13_wall_pdfs(samples, paths["f13"], fits={im: (0.2, 0.4 + im, 0.8) for im in IM[:3]})
    series = rng.gamma(3.0, 1.0, (3000, 10))
    cf.fig14_meso_pdfs(series, {1e-3: series, 1e-2: rng.exponential(1.0, (3000, 10))}, paths["f14"])
    cf.fig_volume_fraction(IM, [0.60, 0.60, 0.59, 0.57, 0.53], paths["phi"])
    gx, gy = np.meshgrid(np.linspace(0.05, 4.95, 50), np.linspace(0.05, 0.95, 10))
    cf.fig2_streamlines(gx.ravel(), gy.ravel(), (np.sin(np.pi * gx / 5) * np.cos(np.pi * gy)).ravel(),
                        (-0.2 * np.cos(np.pi * gx / 5) * np.sin(np.pi * gy)).ravel(), 5.0, paths["f2"], centre=(2.5, 0.5))
    for path in paths.values():
        data = path.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 5000
