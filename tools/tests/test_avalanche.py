"""acoustic_tools.avalanche on small synthetic dumps and series with known answers."""
import math

import numpy as np
import pytest

from acoustic_tools import avalanche as av
from acoustic_tools.lammps_output import Snapshot, read_dump

DT = 1e-3


def lammps_dump_text(frames, item, columns, xhi=10):
    """A LAMMPS text dump of (timestep, rows) frames: item ATOMS (dump custom)
    or ENTRIES (dump local), box 0 xhi x -1 10 x -0.5 0.5."""
    out = []
    for step, rows in frames:
        out += ["ITEM: TIMESTEP", str(step), f"ITEM: NUMBER OF {item}", str(len(rows)),
                "ITEM: BOX BOUNDS pp fm pp", f"0 {xhi}", "-1 10", "-0.5 0.5", f"ITEM: {item} {columns}"]
        out += [" ".join(f"{v:g}" for v in r) for r in rows]
    return "\n".join(out) + "\n"


def dump_text(frames):
    """A dump custom with columns id type radius mass x y vx vy omegaz v_th."""
    return lammps_dump_text(frames, "ATOMS", "id type radius mass x y vx vy omegaz v_th")


def layer_rows(theta, vtop, vbottom):
    """Two base grains (type 2, y = 0) and four grains: two low (y = 1), two high (y = 3)."""
    rows = [[1, 2, 0.5, 1, 1, 0, 0, 0, 0, theta], [2, 2, 0.5, 1, 3, 0, 0, 0, 0, theta]]
    for k, (y, v) in enumerate([(1, vbottom[0]), (1, vbottom[1]), (3, vtop[0]), (3, vtop[1])]):
        rows.append([3 + k, 1, 0.5, 2.0, 1 + 2 * k, y, v, 0, 0, theta])
    return rows


def test_sigma_l_known_values():
    assert av.sigma_l([2, 2, 2]) == 0.0
    assert av.sigma_l([1, 3]) == pytest.approx(0.5)            # std 1, mean 2
    assert av.sigma_l([-1, -3]) == pytest.approx(0.5)          # |mean| in the denominator
    assert math.isinf(av.sigma_l([-1, 1]))                     # no mean flow
    s1, s2 = av.sigma_layers([0, 0, 2, 2], [1, 3, 4, 4])       # split at the mean height 1
    assert (s1, s2) == (pytest.approx(0.0), pytest.approx(0.5))


def test_energy_ratio_known_value():
    # E_k = 0.5*2*(3^2+4^2) = 25, E_p = 2*10*(1.5-0.5) = 20
    assert av.energy_ratio([2.0], [1.5], [3.0], [4.0], g=10.0, yb=0.5) == pytest.approx(25 / 45)
    # rotation: 0.5 * 0.4 m r^2 w^2 = 0.5*0.4*2*1*4 = 1.6
    r = av.energy_ratio([2.0], [1.5], [3.0], [4.0], g=10.0, yb=0.5, radius=[1.0], omega=[2.0])
    assert r == pytest.approx(26.6 / 46.6)


def test_read_dump_and_frame_observables(tmp_path):
    path = tmp_path / "run.dump"
    path.write_text(dump_text([(100, layer_rows(12.5, (2, 2), (1, 3))),
                               (200, layer_rows(13.0, (0, 0), (0, 0)))]))
    frames = read_dump(path)
    assert [f.timestep for f in frames] == [100, 200]
    assert len(frames[0]) == 6
    np.testing.assert_allclose(frames[0].box[0], [0, 10])
    o = av.frame_observables(frames[0], g=10.0)
    assert o["theta"] == 12.5
    assert o["sigma1"] == pytest.approx(0.0)      # top: both at 2
    assert o["sigma2"] == pytest.approx(0.5)      # bottom: 1 and 3
    ek = 0.5 * 2 * (4 + 4 + 1 + 9)
    ep = 2 * 10 * (1 + 1 + 3 + 3)
    assert o["ratio"] == pytest.approx(ek / (ek + ep))
    still = av.frame_observables(frames[1], g=10.0)
    assert still["ratio"] == 0.0 and math.isinf(still["sigma1"])
    # observation window x in [0, 6): ids 3, 4 (y = 1, v = 1, 3) and 5 (y = 3, v = 2)
    o = av.frame_observables(frames[0], g=10.0, obs=(0.0, 0.6))
    assert (o["sigma1"], o["sigma2"]) == (pytest.approx(0.0), pytest.approx(0.5))


def test_read_dump_local_contacts(tmp_path):
    path = tmp_path / "run.contacts"
    path.write_text("ITEM: TIMESTEP\n5\nITEM: NUMBER OF ENTRIES\n2\nITEM: BOX BOUNDS pp fm pp\n"
                    "0 1\n0 1\n0 1\nITEM: ENTRIES f_us[1] f_us[2] f_us[3] f_us[4] f_us[5] f_us[6]\n"
                    "1 2 0.5 100 1e-9 0.25\n2 3 1.5 200 0 1\n")
    c = av.contact_columns(read_dump(path)[0])
    np.testing.assert_array_equal(c["i"], [1, 2])
    np.testing.assert_allclose(c["mu_ratio"], [0.25, 1.0])


def contacts_text(frames):
    """A dump local of fix acoustic/mindlin: rows i j f_n k_n U_t mu*/mu."""
    return lammps_dump_text(frames, "ENTRIES", "f_us[1] f_us[2] f_us[3] f_us[4] f_us[5] f_us[6]")


def test_friction_profile_against_height(tmp_path, capsys):
    # grains of diameter 1 at y = 1 (ids 3, 4) and y = 3 (ids 5, 6) on base
    # grains at y = 0: contact midpoints at 0.5 and 1 (bin 0-2), 2 and 3 (bin 2-4)
    dump, contacts = tmp_path / "run.dump", tmp_path / "run.contacts"
    dump.write_text(dump_text([(100, layer_rows(12.5, (0, 0), (0, 0))), (200, layer_rows(13.0, (0, 0), (0, 0))),
                               (300, layer_rows(12.5, (0, 0), (0, 0)))]))
    pairs = [(1, 3, 2.0), (3, 4, 1.0), (4, 5, 0.5), (5, 6, 0.25)]
    contacts.write_text(contacts_text([(100, [[i, j, fn, 1, 0, 1.0] for i, j, fn in pairs]),
                                       (300, [[i, j, fn, 1, 0, mu] for (i, j, fn), mu
                                              in zip(pairs, (0.2, 0.4, 0.8, 1.0))])]))
    atoms = av.last_frame_at(read_dump(dump), 12.5)
    assert atoms.timestep == 300
    with pytest.raises(ValueError, match="no dump frame at 14 deg"):
        av.last_frame_at(read_dump(dump), 14.0)
    with pytest.raises(SystemExit, match="no contact frame at timestep 200"):
        av.contacts_at(contacts, 200)
    z, x = av.contact_heights(atoms, av.contact_columns(av.contacts_at(contacts, 300)))
    np.testing.assert_allclose(z, [0.5, 1.0, 2.0, 3.0])
    np.testing.assert_allclose(x, [1, 1, 3, 5])
    mean, n = av.binned_means(z, [0.2, 0.4, 0.8, 1.0], [0.0, 2.0, 4.0, 6.0])
    np.testing.assert_allclose(mean[:2], [0.3, 0.9])
    assert list(n) == [2, 2, 0] and np.isnan(mean[2])
    assert av.main(["profile", str(dump), str(contacts), "--theta", "12.5"]) == 0
    rows = [line.split() for line in capsys.readouterr().out.splitlines() if not line.startswith("#")]
    assert rows == [["0-2", "2", "0.300", "1.00", "1.5"], ["2-4", "2", "0.900", "0.00", "0.375"]]
    # the observed window x < 2 keeps the contacts of grain 1 and 3 alone
    av.main(["profile", str(dump), str(contacts), "--theta", "12.5", "--obs", "0", "0.2"])
    rows = [line.split() for line in capsys.readouterr().out.splitlines() if not line.startswith("#")]
    assert rows == [["0-2", "2", "0.300", "1.00", "1.5"]]


def samples(n, **overrides):
    base = dict(ratio=np.full(n, 1e-10), sigma1=np.full(n, 5.0), sigma2=np.full(n, 5.0),
                mobile=np.zeros(n))
    for k, v in overrides.items():
        base[k] = v
    time = DT * np.arange(1, n + 1)
    return time, base


def classify(n, **overrides):
    time, s = samples(n, **overrides)
    return av.classify_angle(time, s["ratio"], s["sigma1"], s["sigma2"], s["mobile"], dt=DT)


def test_stable_despite_the_tilt_transient():
    ratio = np.full(100, 1e-9)
    ratio[:5] = 1e-4                      # transient of the tilt, inside the first 10 ms
    r = classify(100, ratio=ratio)
    assert r.state == "stable" and r.duration == pytest.approx(0.1)
    assert r.max_ratio == pytest.approx(1e-9)


def test_rearrangement_that_stops():
    ratio = np.full(100, 1e-9)
    ratio[40:60] = 1e-5
    r = classify(100, ratio=ratio)
    assert r.state == "stopped" and r.max_ratio == pytest.approx(1e-5)
    # a threshold above the rearrangement makes it stable
    time, s = samples(100, ratio=ratio)
    assert av.classify_angle(time, s["ratio"], s["sigma1"], s["sigma2"], s["mobile"],
                             eps_e=1e-4).state == "stable"


def test_motion_at_the_end_of_the_window():
    ratio = np.full(1300, 1e-9)
    ratio[95:] = 1e-5                     # still moving at 0.1 s, and at 0.1 + 1.2 s
    assert classify(1300, ratio=ratio, mobile=np.full(1300, 0.1)).state == "local"
    # followed at the same angle: no verdict before 0.1 s + tfollow
    assert classify(600, ratio=ratio[:600], mobile=np.full(600, 0.1)).state == "partial"
    time, s = samples(400, ratio=ratio[:400], mobile=np.full(400, 0.1))
    r = av.classify_angle(time, s["ratio"], s["sigma1"], s["sigma2"], s["mobile"], dt=DT, tfollow=0.3)
    assert r.state == "local" and r.duration == pytest.approx(0.4)
    # a local rearrangement that arrests after the window is followed to its end
    ratio = np.full(1300, 1e-9)
    ratio[95:400] = 1e-5
    r = classify(1300, ratio=ratio, mobile=np.full(1300, 0.1))
    assert r.state == "stopped" and r.duration == pytest.approx(0.410)
    # a flow that spreads but arrests at 0.3 s
    ratio = np.full(600, 1e-3)
    ratio[300:] = 1e-9
    r = classify(600, ratio=ratio, mobile=np.r_[np.full(300, 0.9), np.zeros(300)])
    assert r.state == "stopped" and r.duration == pytest.approx(0.310)
    # a flow that spreads and never gets uniform
    assert classify(600, ratio=np.full(600, 1e-3), mobile=np.full(600, 0.9)).state == "partial"


def test_uniform_flow_and_t_con():
    n = 600
    s1 = np.full(n, 2.0)
    s2 = np.full(n, 2.0)
    s1[200:] = 0.2
    s2[250:] = 0.8                        # both below from sample 250 on: t_con = 0.250 s
    s2[255] = 0.95                        # a blip: the 10-sample hold restarts at 256
    r = classify(n, ratio=np.full(n, 1e-3), sigma1=s1, sigma2=s2, mobile=np.full(n, 0.9))
    assert r.state == "uniform"
    assert r.t_con == pytest.approx(0.256)
    assert r.duration == pytest.approx(0.266)
    # sigma criteria met by a layer that does not move are no flow
    r = classify(n, ratio=np.full(n, 1e-9), sigma1=s1, sigma2=s2, mobile=np.zeros(n))
    assert r.state == "stable"
    # criteria of paper 000: 0.3 for the top half, 0.9 for the bottom half
    r = classify(n, ratio=np.full(n, 1e-3), sigma1=np.full(n, 0.35), sigma2=np.full(n, 0.5),
                 mobile=np.full(n, 0.9))
    assert r.state == "partial"
    assert av.t_con(DT * np.arange(n), s1, s2, hold=10) == pytest.approx(0.256)
    assert math.isnan(av.t_con([0, 1], [1, 1], [1, 1]))


def test_ramp_and_theta_m(tmp_path):
    rows = []
    t = 0.0
    for theta in (5.0, 9.5):              # pre-ramp
        for _ in range(10):
            t += DT
            rows.append([t, theta, 1e-4, 3, 3, 0, 0, 0.0, 1, 0])
    for theta, kind in ((10.0, "stable"), (10.5, "local"), (11.0, "uniform")):
        # fix print also prints at the set-up of the first run of an angle: a sample
        # at the time of the tilt, already with the new angle, which must be ignored
        rows.append([t, theta, 1e-2, 0.1, 0.5, 0.1, 0.05, 0.95, 1, 0])
        for k in range(100 if kind != "uniform" else 60):
            t += DT
            if kind == "stable":
                rows.append([t, theta, 1e-9, 3, 3, 0, 0, 0.0, 1, 0])
            elif kind == "local":
                rows.append([t, theta, 1e-4, 3, 3, 0, 0, 0.05, 1, 0])
            else:
                unif = k >= 20
                rows.append([t, theta, 1e-2, 0.1 if unif else 3, 0.5 if unif else 3, 0.1, 0.05, 0.95, 1, 0])
    path = tmp_path / "run.series"
    np.savetxt(path, rows, header="time theta ...")
    # local after the window alone (tfollow 0: the series has 0.1 s per angle)
    res = av.ramp_results(av.read_series(path), first_theta=10.0, tfollow=0.0)
    assert [r.state for r in res] == ["stable", "local", "uniform"]
    tm, tc = av.theta_m(res)
    assert tm == 11.0 and tc == pytest.approx(0.020)
    assert math.isnan(av.theta_m(res[:2])[0])


def test_uniform_stretches_of_a_t_con_run(tmp_path, capsys):
    # a t_con run at 19 deg tilted at t = 2 s (set-up lines at that time, at
    # the old and the new angle, ignored): uniform in samples 100-129 (30 ms),
    # 140-144 (5 ms, the mobile fraction drops at 145) and 150-399 (250 ms);
    # t_con counts from the tilt to the start of the first sample's ms
    n = 400
    ok = np.zeros(n, bool)
    ok[100:130] = ok[140:145] = ok[150:] = True
    mobile = np.full(n, 0.9)
    mobile[145:150] = 0.4
    sigma1 = np.where(ok | (np.arange(n) >= 145), 0.2, 0.5)
    rows = [[2.0, 0.0, 1e-2, 3, 3, 0, 0, 0.0, 1, 0], [2.0, 19.0, 1e-2, 3, 3, 0, 0, 0.0, 1, 0]]
    rows += [[2.0 + (k + 1) * DT, 19.0, 1e-2, sigma1[k], 0.5, 0.1, 0.05, mobile[k], 1, 0] for k in range(n)]
    path = tmp_path / "tcon.series"
    np.savetxt(path, rows, header="time theta ...")
    theta, end, streaks, tcons, covered = av.uniform_at_angle(av.read_series(path), holds=(0.01, 0.05, 0.3))
    assert theta == 19.0 and end == pytest.approx(0.4)
    assert [(round(t, 6), round(d, 6)) for t, d in streaks] == [(0.1, 0.03), (0.14, 0.005), (0.15, 0.25)]
    assert tcons[0.01] == pytest.approx(0.1) and tcons[0.05] == pytest.approx(0.15) and math.isnan(tcons[0.3])
    assert covered == pytest.approx(0.285 / 0.3)
    assert av.t_con(DT * np.arange(n), sigma1, np.full(n, 0.5), hold=30) == pytest.approx(0.1)
    assert av.t_con(DT * np.arange(n), sigma1, np.full(n, 0.5), hold=31) == pytest.approx(0.14), \
        "without the mobile fraction 140-399 is one stretch"
    with pytest.raises(ValueError):
        av.uniform_at_angle(av.read_series(path), theta=20.0)
    av.main(["uniform", str(path), "--holds", "0.01", "0.3", "--min", "0.01"])
    text = capsys.readouterr().out
    assert "(start s, length ms): 0.100 30, 0.150 250\n" in text
    assert "uniform 95% of the time" in text and "0.01 s: 0.100 s, 0.3 s: —" in text


def test_sigma1_spread_of_the_spreading_samples():
    # at 12 deg: sigma_1 = 0.1 ... 1.0 in mobile samples, 5.0 in still ones (left out)
    sigma1 = np.r_[np.linspace(0.1, 1.0, 10), np.full(5, 5.0), [0.7]]
    series = {"theta": np.r_[np.full(15, 12.0), [12.5]], "sigma1": sigma1,
              "mobile": np.r_[np.full(10, 0.9), np.zeros(5), [0.2]]}
    median, p10 = av.sigma1_spread(series, 12.0)
    assert median == pytest.approx(0.55) and p10 == pytest.approx(0.19)
    assert all(math.isnan(v) for v in av.sigma1_spread(series, 12.5))    # nothing spread there


def sheared_layer(a, b, e, theta=12.0):
    """Grains of diameter 1 on a 40 x 6 grid (x = 0.5 ... 39.5, y = 1 ... 6)
    over base grains at y = 0, box 0-40: vx = 1 + a (-1 for x < 20, +1
    beyond) + b (y - 5) + e (+1 / -1 alternating along x).  In the top half
    (y = 4, 5, 6) the mean is 1 and the three parts are orthogonal."""
    x, y = np.meshgrid(np.arange(40) + 0.5, np.arange(1, 7))
    x, y = x.ravel(), y.ravel()
    vx = 1 + a * np.where(x < 20, -1, 1) + b * (y - 5) + e * np.where(np.floor(x) % 2 == 0, 1, -1)
    n = len(x)
    cols = {"id": np.arange(1, n + 3), "type": np.r_[np.ones(n), 2, 2], "radius": np.full(n + 2, 0.5),
            "mass": np.ones(n + 2), "x": np.r_[x, 1, 3], "y": np.r_[y, 0, 0], "vx": np.r_[vx, 0, 0],
            "vy": np.zeros(n + 2), "v_th": np.full(n + 2, theta)}
    return Snapshot(0, np.array([[0, 40], [-1, 10], [-0.5, 0.5]], float), cols)


def test_sigma1_parts_of_a_known_layer():
    a, b, e = 0.2, 0.1, 0.15
    p = av.sigma1_parts(sheared_layer(a, b, e))
    assert p["v1"] == pytest.approx(1.0)
    assert p["v2"] == pytest.approx(1 - 3 * b)                   # y = 1, 2, 3: mean y - 5 = -3
    assert p["along"] == pytest.approx(a)
    assert p["depth"] == pytest.approx(b * math.sqrt(2 / 3))      # b (y - 5) over y = 4, 5, 6
    assert p["residual"] == pytest.approx(e)
    assert p["sigma1"] == pytest.approx(math.sqrt(a * a + 2 * b * b / 3 + e * e))
    assert p["fluct_over_shear"] == pytest.approx(e / b)          # shear rate 3 b over 3 d
    assert p["d"] == pytest.approx(1.0)
    # the observed window x < 20 holds one column: nothing along the slope
    p = av.sigma1_parts(sheared_layer(a, b, e), obs=(0.0, 0.5))
    assert p["along"] == pytest.approx(0.0, abs=1e-12)
    assert p["residual"] == pytest.approx(e / (1 - a))


def test_sigma1_parts_by_angle_takes_medians(capsys, tmp_path):
    frames = [sheared_layer(0.2, 0.1, e, theta) for e, theta in ((0.1, 12), (0.3, 12), (0.2, 12), (0.05, 13))]
    rows = av.sigma1_parts_by_angle(frames)
    assert [(t, p["frames"]) for t, p in rows] == [(12.0, 3), (13.0, 1)]
    assert rows[0][1]["residual"] == pytest.approx(0.2)
    assert av.sigma1_parts_by_angle(frames, thetas=[13.0])[0][1]["residual"] == pytest.approx(0.05)
    # the command line, from a dump file: v1 / sqrt(g d) = 1 / sqrt(4) with g = 4
    path = tmp_path / "run.dump"
    names = list(frames[0].columns)
    path.write_text(lammps_dump_text([(k, np.column_stack([f[c] for c in names]))
                                      for k, f in enumerate(frames)], "ATOMS", " ".join(names), xhi=40))
    assert av.main(["sigma-parts", str(path), "--g", "4", "--theta", "13"]) == 0
    out = [line.split() for line in capsys.readouterr().out.splitlines() if not line.startswith("#")]
    assert out == [["1", "13.00", "0.500", "0.700", f"{math.sqrt(0.04 + 0.02 / 3 + 0.0025):.3f}",
                    "0.200", "0.082", "0.050", "0.500"]]
    # one line per frame: the three frames at 12 deg, residuals 0.1, 0.3, 0.2 (timesteps 0, 1, 2)
    assert av.main(["sigma-parts", str(path), "--theta", "12", "--per-frame"]) == 0
    out = [line.split() for line in capsys.readouterr().out.splitlines() if not line.startswith("#")]
    assert [(r[0], r[1], r[7]) for r in out] == [("0", "12.00", "0.100"), ("1", "12.00", "0.300"),
                                                 ("2", "12.00", "0.200")]


def test_bottom_to_top_velocity_of_the_last_samples():
    # at 11 deg the flow first slides as a plug (vx2 = vx1), then shears:
    # the last 10 samples have vx2 / vx1 = 0.4; other angles do not count
    rows = [[k * DT, 10.5, 0, 0, 0, 1.0, 9.0] for k in range(5)]
    rows += [[(5 + k) * DT, 11.0, 0, 0, 0, 2.0, 2.0] for k in range(20)]
    rows += [[(25 + k) * DT, 11.0, 0, 0, 0, 1.0 + k % 2, 0.4 * (1.0 + k % 2)] for k in range(10)]
    rows += [[35 * DT, 11.5, 0, 0, 0, 1.0, 5.0]]
    series = dict(zip(av.SERIES_COLUMNS, np.array(rows).T))
    assert av.bottom_to_top_velocity(series, 11.0) == pytest.approx(0.4)
    assert av.bottom_to_top_velocity(series, 11.0, nsamples=30) == pytest.approx((0.4 * 15 + 40) / (15 + 40))
    # Bagnold's profile v = 1 - (1 - z)^1.5, halves of the layer: the 0.40 of the docstring
    z = (np.arange(100000) + 0.5) / 100000
    v = 1 - (1 - z) ** 1.5
    assert v[z < 0.5].mean() / v[z >= 0.5].mean() == pytest.approx(0.398, abs=1e-3)


def test_network_spectrum_of_a_clamped_grain():
    # grain 2 between clamped grains 1 and 3 along x, springs k: omega_x^2 = 2k/m,
    # no stiffness along y (a zero mode); the periodic image of 3 is used (box 0..4)
    k, m = 8.0, 2.0
    atoms = Snapshot(0, np.array([[0.0, 4.0], [-1, 1], [-1, 1]]),
                     {"id": np.array([1, 2, 3]), "type": np.array([2, 1, 2]),
                      "mass": np.array([1.0, m, 1.0]), "x": np.array([0.5, 1.5, 3.9]),
                      "y": np.zeros(3)})
    contacts = Snapshot(0, atoms.box, {"i": np.array([1, 2]), "j": np.array([2, 3]),
                                       "fn": np.ones(2), "kn": np.array([k, k]),
                                       "Ut": np.zeros(2), "mu_ratio": np.ones(2)})
    f = av.network_spectrum(atoms, contacts)
    np.testing.assert_allclose(f, [0.0, math.sqrt(2 * k / m) / (2 * math.pi)], atol=1e-12)


def test_fraction_of_modes_above_a_drive():
    # the zero modes are left out: 1 of the 4 non-zero modes lies above 25
    f = np.array([0.0, 1e-9, 10.0, 20.0, 30.0, 5.0])
    assert av.fraction_above(f, 25.0) == pytest.approx(0.25)
    assert av.fraction_above(f, 30.0) == 0.0
    assert av.fraction_above(f, 1.0) == 1.0


def test_band_from_a_density_of_states(tmp_path, capsys):
    # a triangular density 2 f / F^2 on [0, F], F = 100, on 100 bins of 1
    # (the exact bin averages): F(f) = (f / F)^2 below f, so 49 % below 70 and
    # 99 % below 100 sqrt(0.99); a drive above the band has every mode below it
    centres = np.arange(100) + 0.5
    density = 2.0 * centres / 100.0 ** 2
    below, tops = av.band_from_density(centres, density, 70.0, (0.99, 0.25))
    assert below == pytest.approx(0.49)
    assert tops[0] == pytest.approx(100.0 * math.sqrt(0.99), abs=0.01)
    assert tops[1] == pytest.approx(50.0)
    assert av.band_from_density(centres, density, 150.0)[0] == 1.0
    # bins above the band with the small negative densities of kpm's noise
    # count as empty: the same band
    noisy = np.concatenate((density, [-1e-4, 2e-5, -3e-5]))
    below_noisy, tops_noisy = av.band_from_density(np.arange(103) + 0.5, noisy, 70.0, (0.99, 0.25))
    assert below_noisy == pytest.approx(0.49 / (1.0 + 2e-5), rel=1e-12)
    assert tops_noisy[1] == pytest.approx(tops[1], rel=1e-4)
    # the same through the command line, from an in.modes histogram file
    hist = tmp_path / "modes.hist"
    hist.write_text("# Time-averaged data\n# TimeStep Number-of-rows\n0 100\n" +
                    "".join(f"{k + 1} {c} {d} 0\n" for k, (c, d) in enumerate(zip(centres, density))))
    av.main(["band", str(hist), "--drive", "70", "--shares", "0.25"])
    assert capsys.readouterr().out.strip() == "49.00% of the modes below 70; 25.0% below 50"


def test_figures_from_synthetic_runs(tmp_path):
    """Each figure of avalanche_figures.py is written from small synthetic files."""
    from acoustic_tools import avalanche_figures as figs
    dump = tmp_path / "run.dump"
    dump.write_text(dump_text([(100, layer_rows(11.0, (2, 2), (1, 3)))]))
    contacts = tmp_path / "run.contacts"
    contacts.write_text("ITEM: TIMESTEP\n100\nITEM: NUMBER OF ENTRIES\n3\nITEM: BOX BOUNDS pp fm pp\n"
                        "0 10\n-1 10\n-0.5 0.5\nITEM: ENTRIES f_us[1] f_us[2] f_us[3] f_us[4] f_us[5] f_us[6]\n"
                        "1 3 2.0 100 1e-9 0.25\n3 5 1.0 80 0 1\n4 6 0.5 50 0 0.5\n")
    series = tmp_path / "run.series"
    t = DT * np.arange(1, 41)
    np.savetxt(series, np.column_stack([t, np.full(40, 11.0), np.full(40, 1e-3), np.linspace(2, 0.1, 40),
                                        np.linspace(3, 0.5, 40), t, t, np.full(40, 0.9),
                                        np.ones(40), np.zeros(40)]))
    table7 = tmp_path / "thetam.txt"
    table7.write_text("3 20 1.0 14.5 0.5 20 14.5\n6 19.5 1.2 15 0.7 nan nan\n")
    tablek = tmp_path / "kappa.txt"
    tablek.write_text("0.1 6 1 0.5 0.9 1 periodic\n0.3 6 1 5 0.6 5 periodic\n0.3 6 2 4 0.6 4.5 periodic\n"
                      "0.1 8.7 1 1.5 0.8 2 free_ends\n0.3 8.7 1 3 0.6 nan free_ends\n")
    (tmp_path / "coupling.txt").write_text("6 16.5 0.4\n14.4 15 nan\n")
    table8 = tmp_path / "tcon.txt"
    table8.write_text("H6_0kHz 19.5 0.2 thetam\nH6_0kHz 20.5 0.1\nH6_70kHz 15 0.09 thetam\npaper000_H6_0kHz 19 1.15\n")
    hist = tmp_path / "modes.hist"
    hist.write_text("# Time-averaged data for fix hist\n# TimeStep Number-of-rows\n"
                    "100 3\n1 500 0.0004\n2 1500 0.0004\n3 2500 0.0002\n")
    runs = [["modes", str(dump), str(contacts), "--f0", "1"], ["modes", "--hist", str(hist)], ["sigma", str(series), "--theta", "11"],
            ["thetam", str(table7)], ["thetam", str(table7), "--free", str(table7), "--label", "periodic"],
            ["thetam", str(table7), "--coupling", str(tmp_path / "coupling.txt"), "kappa_scale 0.17"],
            ["tcon", str(table8)], ["kappa", str(tablek)], ["chains", str(dump), str(contacts)]]
    for k, args in enumerate(runs):
        out = tmp_path / f"fig{k}.png"
        assert figs.main(args + ["-o", str(out), "--dpi", "40"]) == 0
        assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_fig7_draws_the_points_of_another_coupling(tmp_path):
    """fig_thetam's couplings: the points of the table (theta_m on x, H/d on
    y) with their standard deviations as error bars, labelled with the name."""
    from acoustic_tools import avalanche_figures as figs
    table7 = [(3, 20, 1.0, 14.5, 0.5, 20, 14.5), (6, 19.5, 1.2, 15, 0.7, np.nan, np.nan)]
    coupling = [(6.07, 16.5, 0.41), (13.91, 14.75, 0.5)]
    fig = figs.fig_thetam(tmp_path / "fig7.png", table7, "free ends", couplings=[(coupling, "kappa_scale 0.17")])
    assert (tmp_path / "fig7.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    ax = fig.axes[0]
    drawn = [c for c in ax.containers if c.get_label() == "70 kHz, kappa_scale 0.17 (mean ± s.d.)"]
    assert len(drawn) == 1
    points, _, (bars,) = drawn[0].lines
    assert points.get_xdata().tolist() == [16.5, 14.75]
    assert points.get_ydata().tolist() == [6.07, 13.91]
    # each error bar spans mean - s.d. to mean + s.d. at its H/d
    spans = [sorted(x for x, _ in seg) for seg in bars.get_segments()]
    assert spans == [pytest.approx([16.09, 16.91]), pytest.approx([14.25, 15.25])]


def test_fig7_says_which_paper_values_are_interpolated(tmp_path):
    """Fig. 7's paper lines are a straight line through 20 deg (3 d) and
    17 deg (14.4 d) and the same 2 deg lower, labelled as interpolated; the
    values of the paper's text are drawn at their own H/d; the 70 kHz
    ensemble says its coupling; paper 000's colours."""
    from acoustic_tools import avalanche_figures as figs
    table7 = [(3.1, 20.6, 0.8, 20.4, 0.5, 20, 14.5), (13.9, 16.2, 1.3, 11.0, 0.4, 17, np.nan)]
    fig = figs.fig_thetam(tmp_path / "fig7.png", table7, "free ends, 400 d", coupling="kappa_scale 0.3", dpi=40)
    ax = fig.axes[0]
    lines = {line.get_label(): line for line in ax.get_lines()}
    interpolated = [name for name in lines if name.startswith("paper 000") and "interpolated" in name]
    assert len(interpolated) == 2
    zero = lines[interpolated[0]]
    assert zero.get_xdata().tolist() == pytest.approx([20, 17]) and zero.get_ydata().tolist() == [3, 14.4]
    assert lines[interpolated[1]].get_xdata().tolist() == pytest.approx([18, 15])
    stated = lines["paper 000, 0 kHz, stated in its text (20° at 3 d, 17° at 14.4 d)"]
    assert stated.get_xdata().tolist() == [20, 17]
    labels = [c.get_label() for c in ax.containers]
    assert "70 kHz, kappa_scale 0.3, free ends, 400 d (mean ± s.d.)" in labels
    assert [c.lines[0].get_color() for c in ax.containers] == [figs.COLOUR[0], figs.COLOUR[70]]


def test_fig8_stars_at_theta_m_squares_above(tmp_path):
    """Fig. 8: one panel per H/d; the ramps' flows at theta_m are stars, the
    runs above theta_m filled squares, blue at 0 and orange at 70 kHz; the
    paper's stated values sit on their own panel."""
    from acoustic_tools import avalanche_figures as figs
    rows = [("H6_0kHz_free_ends", 18.0, 0.5, "thetam"), ("H6_0kHz_free_ends", 19.0, 0.4, "run"),
            ("H6_70kHz_free_ends", 16.0, 0.3, "thetam"), ("H14.4_0kHz_free_ends", 16.5, 1.0, "thetam"),
            ("paper000_H6_0kHz", 19.0, 1.15)]
    fig = figs.fig_tcon(tmp_path / "fig8.png", rows, dpi=40, coupling="kappa_scale 0.3")
    assert [ax.get_title() for ax in fig.axes] == ["H = 6 d", "H = 14.4 d"]
    six = {line.get_label(): line for line in fig.axes[0].get_lines()}
    star = six["0 kHz, at θ_m (stars)"]
    assert star.get_marker() == "*" and star.get_color() == figs.COLOUR[0]
    assert star.get_xdata().tolist() == [18.0]
    square = six["0 kHz, above θ_m (filled squares)"]
    assert square.get_marker() == "s" and square.get_xdata().tolist() == [19.0]
    orange = six["70 kHz, kappa_scale 0.3, at θ_m (stars)"]
    assert orange.get_color() == figs.COLOUR[70]
    assert six["paper 000, 0 kHz: 1.15 s at 19° (stated in its text)"].get_ydata().tolist() == [1.15]
    assert not any(name.startswith("paper") for name in (line.get_label() for line in fig.axes[1].get_lines()))


def test_fig11_counts_the_ramps_of_each_frequency(tmp_path):
    """Fig. 11's panel titles count the ramps at each frequency (a panel
    whose 70 kHz ramps are not all run says so), and each frequency is in
    the legend once, even when the first packing has no ramp at it."""
    from acoustic_tools import avalanche_figures as figs
    rows = [(8.7, "1", 0.0, 15.0, 0.2, "spreading"), (8.7, "1", 0.0, 17.5, 0.9, "uniform"),
            (8.7, "2", 0.0, 16.0, 0.8, "uniform"), (8.7, "2", 70.0, 14.5, 0.9, "uniform"),
            (11.4, "1", 0.0, 16.0, 1.0, "uniform"), (11.4, "2", 0.0, 16.5, 1.0, "uniform"),
            (14.4, "1", 0.0, 16.0, 1.0, "uniform"), (14.4, "1", 70.0, 15.0, 1.0, "uniform")]
    fig = figs.fig_percolation(tmp_path / "fig11.png", rows, dpi=40)
    assert [ax.get_title() for ax in fig.axes] == ["H = 8.7 d (2 packings at 0 kHz, 1 at 70 kHz)",
                                                   "H = 11.4 d (2 packings at 0 kHz, none at 70 kHz)",
                                                   "H = 14.4 d (1 packing)"]
    handles, labels = fig.axes[0].get_legend_handles_labels()
    assert labels.count("0 kHz") == 1 and labels.count("70 kHz") == 1


def test_sigma_panels_wrap_into_a_readable_grid(tmp_path):
    # four runs at 19 deg: a 2 x 2 grid at least 1 200 px wide (one row of four
    # at 80 dpi was 245 px tall); the axes beyond the runs are hidden
    import matplotlib.image
    from acoustic_tools import avalanche_figures as figs
    n = 50
    rows = [[2.0, 19.0, 1e-2, 3, 3, 0, 0, 0.0, 1, 0]]
    rows += [[2.0 + (k + 1) * DT, 19.0, 1e-2, 0.2, 0.5, 0.1, 0.05, 0.9, 1, 0] for k in range(n)]
    path = tmp_path / "hold.series"
    np.savetxt(path, rows, header="time theta ...")
    runs = figs.sigma_runs([str(path)] * 4, [19.0] * 4)
    fig = figs.fig_sigma(tmp_path / "four.png", runs)
    assert [ax.get_subplotspec().get_geometry()[:2] for ax in fig.axes] == [(2, 2)] * 4
    height, width = matplotlib.image.imread(tmp_path / "four.png").shape[:2]
    assert width >= 1200 and height >= 700
    fig = figs.fig_sigma(tmp_path / "three.png", runs[:3])
    assert [ax.get_visible() for ax in fig.axes] == [True, True, True, False]
