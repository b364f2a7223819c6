"""The motion of a layer at one angle (acoustic_tools.avalanche_fields, paper
000's Figs. 6, 9, 14): the cells and columns of known velocities, the
frames and sigma_l samples of one angle, the angles a job keeps, the fields
set and what the record keeps (no LAMMPS: synthetic dumps and series)."""
import json
import os
import shutil

import numpy as np
import pytest

from acoustic_tools import avalanche_collect, avalanche_fields as fields, avalanche_study as a, study
from acoustic_tools.lammps_output import Snapshot

D = 7e-4


def _frame(step, theta, x, y, vx, types=None):
    n = len(x)
    types = np.ones(n, int) if types is None else np.asarray(types)
    box = np.array([[0.0, 100 * D], [0.0, 10 * D], [-0.5, 0.5]])
    return Snapshot(step, box, {"id": np.arange(1, n + 1), "type": types, "radius": np.full(n, 0.5 * D),
                                "x": np.asarray(x, float), "y": np.asarray(y, float), "vx": np.asarray(vx, float),
                                "vy": np.zeros(n), "v_th": np.full(n, float(theta))})


def test_speed_in_cells_and_columns():
    # a base grain at y = 0, grains at 1 and 3 d above it, x at 1, 5, 9 d
    x = [0.5 * D, 1 * D, 1 * D, 5 * D, 9 * D]
    y = [0.0, 1 * D, 3 * D, 1 * D, 1 * D]
    vx = [0.0, 1.0, 3.0, 5.0, 7.0]
    frame = _frame(0, 10, x, y, vx, types=[2, 1, 1, 1, 1])
    cells = fields.speed_cells(frame, (0.0, 12 * D), D, 4.0, cell=(4.0, 2.0))
    assert cells.shape == (2, 3)
    assert cells[0].tolist() == [1.0, 5.0, 7.0]             # the first 2 d above the base
    assert cells[1, 0] == 3.0 and np.isnan(cells[1, 1]) and np.isnan(cells[1, 2])
    left, speeds = fields.column_speeds(frame, D, column=4.0)
    assert left == pytest.approx([1 * D, 5 * D])               # from the back grain (x = 1 d), 8 d: two columns
    assert speeds.tolist() == [2.0, 6.0]                       # (1 + 3) / 2; 5 and 7 in the last, closed column


def _series(samples):
    """in.avalanche's series lines: (time, theta, sigma1, sigma2)."""
    rows = [(t, th, 1e-3, s1, s2, 0, 0, 0.5, 0.9, 0.1) for t, th, s1, s2 in samples]
    return {name: np.array([r[k] for r in rows], float) for k, name in
            enumerate(("time", "theta", "ratio", "sigma1", "sigma2", "vx1", "vx2", "mobile", "mu_mean", "frac"))}


def test_angle_fields_take_the_frames_of_the_angle_at_the_kept_times():
    dt = 1e-5                                     # 100 steps per ms
    # angle 10 until t = 0.5 s, then 10.5 (the tilt at 0.5 s) until 1.8 s
    samples = [(0.001 * k, 10.0, 1.0, 1.0) for k in range(1, 501)]
    samples += [(0.5 + 0.001 * k, 10.5, 0.1 + 0.001 * k, 0.5) for k in range(1, 1301)]
    series = _series(samples)
    rng = np.random.default_rng(1)
    x, y = rng.uniform(0, 100 * D, 50), rng.uniform(0, 8 * D, 50)
    frames = [_frame(int(round(t / dt)), 10.0 if t <= 0.5 + 1e-9 else 10.5, x, y, np.full(50, t))
              for t in np.arange(0.05, 1.801, 0.05)]
    f = fields.angle_fields(frames, series, 10.5, dt, (0.25, 0.75))
    assert [s["t"] for s in f["snapshots"]] == pytest.approx([0.05, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2])
    # the speed of a frame is its time: the snapshot at 0.4 s since the tilt is the frame at 0.9 s
    cells = fields.as_array(f["snapshots"][2]["speed"])
    assert np.nanmin(cells) == np.nanmax(cells) == pytest.approx(0.9)
    assert f["window_d"] == [25.0, 75.0] and f["t_end"] == pytest.approx(1.3)
    assert f["sigma_t"][:2] == pytest.approx([0.005, 0.010]) and f["sigma1"][0] == pytest.approx(0.105)
    assert f["mobile"][:2] == [0.5, 0.5], "the mobile fraction beside the sigmas"
    with pytest.raises(ValueError, match="no series samples at 11"):
        fields.angle_fields(frames, series, 11.0, dt, (0.25, 0.75))


def test_the_angles_a_job_keeps():
    def angle(theta, state, followed):
        return {"theta": theta, "state": state, "time": followed}
    ramp = {"angles": [angle(10, "stable", 0.1), angle(10.5, "local", 1.3), angle(11, "stable", 0.1),
                       angle(11.5, "local", 1.3), angle(12, "local", 1.3), angle(12.5, "stopped", 0.4),
                       angle(13, "uniform", 0.2)]}
    assert fields.job_angles({"kind": "ramp"}, ramp) == [11.5, 12.0, 12.5, 13.0]
    assert fields.job_angles({"kind": "ramp"}, ramp, before=1) == [12.5, 13.0]
    assert fields.job_angles({"kind": "tcon"}, {"angles": [angle(14, "uniform", 1.3)]}) == [14.0]


def test_the_fields_set_holds_theta_m_with_dumps():
    jobs = a.production("fields")
    assert len(jobs) == 4 and all(what == "tcon" for what, _ in jobs)
    for _, (ramp, options) in jobs:
        assert ramp["seed"] == 1 and ramp["H"] in (6.0, 14.4) and ramp["kappa"] == a.KAPPA
        assert options == {"steps": (0,), "tuniform": a.FIELDS_HOLD, "dumpevery": 50}
    s = a.tcon_settings(jobs[0][1][0], 17.5, a.FIELDS_HOLD, 50)
    assert s["dumpevery"] == 50 and a.job_name(s) == "free400_H6_s1_tcon_f0_17.5_u1.2_k0.17"
    assert a.keeps_fields(s) and a.keeps_fields(jobs[1][1][0])
    assert not a.keeps_fields(a.ramp_settings(a.packing_settings(6, 1), 70e3, kappa=0.3))
    assert not a.keeps_fields(a.ramp_settings(a.packing_settings(3, 1), 70e3))


def test_the_record_keeps_the_fields_of_a_calibrated_ramp(tmp_path):
    dt = 1e-5
    s = a.ramp_settings(a.packing_settings(6, 1), 70e3, theta0=10)
    directory = tmp_path / "out" / a.job_name(s)
    directory.mkdir(parents=True)
    study.write_job(str(directory), s)
    result = {"theta_m": 10.5, "t_con": 0.2, "dt": dt,
              "angles": [{"theta": 10.0, "state": "local", "time": 1.3},
                         {"theta": 10.5, "state": "uniform", "time": 0.3}]}
    study.write_result(str(directory), result)
    with open(directory / "f70.series", "w") as out:
        out.write("# time theta ...\n")
        for k in range(1, 1601):
            t = 0.001 * k
            out.write(f"{t:.4f} {10.0 if t <= 1.3 + 1e-9 else 10.5:.2f} 1e-4 0.5 1.0 0 0 0.2 0.8 0.1\n")
    rng = np.random.default_rng(2)
    n = 60
    with open(directory / "f70.dump", "w") as out:
        for t in np.arange(0.05, 1.601, 0.05):
            step = int(round(t / dt))
            out.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{n}\nITEM: BOX BOUNDS pp ff pp\n"
                      f"0 {500 * D}\n0 {10 * D}\n-0.5 0.5\nITEM: ATOMS id type radius mass x y vx vy omegaz v_th\n")
            theta = 10.0 if t <= 1.3 + 1e-9 else 10.5
            for k in range(n):
                out.write(f"{k + 1} {2 if k < 5 else 1} {0.5 * D} 1e-6 {rng.uniform(0, 400 * D)} "
                          f"{0.0 if k < 5 else rng.uniform(D, 6 * D)} {t} 0 0 {theta}\n")
    # a ramp at the coupling before the calibration: no fields kept
    old = a.ramp_settings(a.packing_settings(6, 2), 70e3, kappa=0.3)
    (tmp_path / "out" / a.job_name(old)).mkdir()
    study.write_job(str(tmp_path / "out" / a.job_name(old)), old)
    study.write_result(str(tmp_path / "out" / a.job_name(old)), result)
    record = tmp_path / "record"
    assert a.record(str(tmp_path / "out"), str(record)) == 2
    assert not (record / a.job_name(old) / "fields.json").exists()
    kept = fields.read_fields(str(record / a.job_name(s)))
    assert [x["theta"] for x in kept["angles"]] == [10.0, 10.5]
    assert kept["angles"][0]["window_d"] == [150.0, 350.0]          # the middle half of the 400 d layer (base 500 d)
    assert kept["theta_m"] == 10.5 and len(kept["angles"][0]["snapshots"]) == 7
    assert os.path.getsize(record / a.job_name(s) / "fields.json") < 50e3
    # the figures from the record: Figs. 6/9 and 14 at 6 d (70 kHz only here)
    jobs = avalanche_collect.load(str(record))
    made = avalanche_collect.job_fields(jobs[a.job_name(s)])
    assert made == kept
    # the same packing 2000 d long (paper_length) with another theta_m: not
    # the fields of the 400 d layer's figures
    long = a.ramp_settings(a.packing_settings(6, 1, layer=a.PAPER_LAYER), 70e3, theta0=10, window=a.PAPER_WINDOW)
    shutil.copytree(record / a.job_name(s), record / a.job_name(long))
    study.write_job(str(record / a.job_name(long)), long)
    kept_long = dict(kept, theta_m=11.0)
    with open(record / a.job_name(long) / "fields.json", "w") as handle:
        json.dump(kept_long, handle)
    runs = avalanche_collect.fields_runs(str(record), 6.0)
    assert sorted(runs) == [(70, "at"), (70, "below")]
    assert runs[(70, "below")][0] == "70 kHz, θ = 10° (θ_m − 0.5°)"
    rows = avalanche_collect.fields_rows(str(record))
    assert [(r[0], r[1]) for r in rows] == [(6.0, "70 kHz, θ = 10.5° (θ_m, until uniform)"),
                                          (6.0, "70 kHz, θ = 10° (θ_m − 0.5°)")]
    # sigma_1 = 0.5 and sigma_2 = 1.0 throughout: never below their criteria; all the grains move alike
    assert all(np.isnan(r[2]) and np.isnan(r[3]) for r in rows)
    assert all(m == 1.0 for _, m in rows[1][4])
    # both layers of the packing side by side: how each flow covers its window
    spread = avalanche_collect.spread_runs(str(record), 6.0)
    assert [(layer, f) for layer, f, _ in spread] == [(a.PAPER_LAYER, 70.0), (400.0, 70.0)]
    assert spread[0][2] == kept_long and spread[1][2] == kept
    written = avalanche_collect.fields_figures(str(record), str(tmp_path / "figures"))
    assert [os.path.basename(p) for p in written] == ["fig6_9_fields_H6.png", "fig14_front_H6.png",
                                                      "paper_length_spread_H6.png"]
    assert os.path.getsize(written[-1]) > 10e3
    with open(record / a.job_name(s) / "fields.json") as handle:
        json.load(handle)                                                # strict JSON: no NaN


def test_sigma_times_need_the_criterion_held_not_a_lone_sample():
    """Figs. 6/9 in numbers: the time from which a sigma stays below its
    criterion for the ramps' hold (0.01 s, two samples of 5 ms here); the
    lone low sample right after the tilt does not count."""
    t = 0.005 * np.arange(1, 11)
    sigma = np.array([0.25, 1.2, 1.1, 0.29, 1.3, 0.2, 0.25, 0.1, 1.0, 0.2])
    assert avalanche_collect._first_held_below(t, sigma, 0.3) == t[5]
    assert avalanche_collect._first_held_below(t, sigma, 0.3, hold=0.015) == t[5]
    assert np.isnan(avalanche_collect._first_held_below(t, sigma, 0.3, hold=0.03))
    assert np.isnan(avalanche_collect._first_held_below(t, np.ones(10), 0.3))
    # with the mobile fraction: only samples of a layer that has spread count
    # (more than half of the grains mobile); the still layer's low sigma
    # at the tilt does not
    sigma = np.array([0.2, 0.2, 0.2, 1.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2])
    mobile = np.array([0.0, 0.1, 0.2, 0.6, 0.6, 0.4, 0.7, 0.8, 0.9, 1.0])
    assert avalanche_collect._first_held_below(t, sigma, 0.3) == t[0]
    assert avalanche_collect._first_held_below(t, sigma, 0.3, mobile=mobile) == t[6]
