"""Paper 000's snapshots (Figs. 10, 12, 13): the production set, what the
record keeps of a snapshot job's dumps (acoustic_tools.avalanche_snapshots)
and the figures drawn from it (no LAMMPS: synthetic dumps)."""
import json
import os

import matplotlib.image
import numpy as np
import pytest

from acoustic_tools import avalanche_collect, avalanche_snapshots as snaps, avalanche_study as a, study

HERE = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "avalanche")


def test_the_diameter_is_the_decks():
    d = [line.split()[3] for line in open(os.path.join(HERE, "in.material"))
         if line.split()[:3] == ["variable", "d", "equal"]]
    assert [float(x) for x in d] == [snaps.D]


def test_snapshot_set():
    jobs = a.production("snapshots")
    assert all(what == "ramp" for what, _ in jobs)
    settings = [s for _, s in jobs]
    assert {(s["freq"], s["U0"]) for s in settings} == {(70e3, 1e-5), (30e3, 1e-5), (70e3, 1e-3), (70e3, 1e-4),
                                                        (70e3, 1e-6)}
    for s in settings:
        assert (s["kind"], s["H"], s["seed"], s["kappa"]) == ("snapshot", 14.4, 4, a.KAPPA)
        assert s["theta0"] == s["thetamax"] == 15.0 and s["switch_on"] == 14.5 and s["tfollow"] == 0
        assert (s["dumpevery"], s["dumplocal"], s["dumpq"]) == (1, 1, 1)
    names = {a.job_name(s) for s in settings}
    assert len(names) == 5
    others = {a.job_name(job if what == "ramp" else job[0]) for name in a.PRODUCTION if name != "snapshots"
              for what, job in a.production(name)}
    assert not names & others
    assert a.job_name(settings[0]) == "free400_H14.4_s4_snap_f70_u1e-5_k0.17_on14.5"
    # kept out of the ensembles and of the switch-on study
    assert not avalanche_collect._in_ensemble({"settings": settings[0]})


class _Runner(a.Runner):
    """A Runner whose LAMMPS processes are recorded, not run; the tilt at
    rest ends at rest."""

    def __init__(self, tmp_path):
        build = tmp_path / "build"
        (build / "lammps").mkdir(parents=True)
        (build / "lammps" / "lmp").write_text("#!/bin/sh\n")
        (build / "lammps" / "lmp").chmod(0o755)
        super().__init__(str(build), str(tmp_path / "out"), str(tmp_path), say=lambda line: None)
        self.calls = []

    def lammps(self, directory, deck, variables, log, contact=None):
        self.calls.append((deck, dict(variables)))
        if deck == "in.deposit":
            study.write_result(directory, {"grains": 6000, "base": 300, "H_measured": 14.4})
        elif variables.get("resultfile") == "quiet.json":
            with open(os.path.join(directory, "quiet.json"), "w") as f:
                json.dump({"angles": [{"theta": float(variables["thetamax"]), "state": "stable"}]}, f)
            open(os.path.join(directory, "quiet.static.restart"), "w").close()
        else:
            study.write_result(directory, {"theta_m": None, "t_con": None})
        return 0.0


def test_the_runner_tilts_at_rest_then_drives_with_the_jobs_amplitude(tmp_path):
    s = a.production("snapshots")[2][1]        # 70 kHz, U0/d = 1e-3
    runner = _Runner(tmp_path)
    runner.ramp(s)
    decks = [(deck, v.get("tag")) for deck, v in runner.calls]
    assert decks == [("in.deposit", None), ("in.avalanche", "quiet"), ("in.avalanche", "snap_f70_u1e-3")]
    quiet, drive = runner.calls[1][1], runner.calls[2][1]
    # the tilt at rest is the ramps' protocol from 10 deg (a quick pre-ramp to 14 deg makes the layer flow)
    assert quiet["freq"] == 0 and (quiet["theta0"], quiet["thetamax"]) == ("10", "14.5") and "dumpq" not in quiet
    assert quiet["restart"] == "../free400_H14.4_s4_deposit/deposit.restart"
    assert (drive["theta0"], drive["thetamax"], drive["tfollow"]) == ("15.00", "15", "0")
    assert (drive["U0"], drive["dumpq"], drive["dumpevery"], drive["dumplocal"]) == ("0.001", 1, 1, 1)
    # a flow that becomes uniform is still followed the whole 0.1 s (paper 000's frames at 18-72 ms)
    assert drive["tuniform"] == "0.1" and "tuniform" not in quiet
    assert drive["restart"] == "../free400_H14.4_s4_quiet10-14.5/quiet.static.restart" and drive["pre"] == 0
    assert os.path.exists(os.path.join(runner.directory(s), "quiet.json"))
    # the other snapshot jobs start from the same tilt: it runs once
    runner.ramp(a.production("snapshots")[0][1])
    assert [v.get("tag") for _, v in runner.calls[3:]] == ["snap_f70_u1e-5"]
    # an ordinary ramp sets neither
    ramp = _Runner(tmp_path / "other")
    ramp.ramp(a.ramp_settings(a.packing_settings(6, 1), 70e3))
    assert not {"U0", "dumpq", "tuniform"} & set(ramp.calls[-1][1])


# ------------------------------------------------------------------ synthetic dumps

D = snaps.D


def _layer(rng):
    """A layer 100 d long and 4 d deep on a row of base grains (type 2)."""
    xs, ys, types = [], [], []
    for k in range(100):
        xs.append((k + 0.5) * D)
        ys.append(0.0)
        types.append(2)
        for row in range(4):
            xs.append((k + 0.5 + 0.1 * rng.standard_normal()) * D)
            ys.append((row + 1) * D)
            types.append(1)
    return np.array(xs), np.array(ys), np.array(types)


def _write_dumps(directory, tag, steps, rng):
    x, y, types = _layer(rng)
    n = len(x)
    ids = np.arange(1, n + 1)
    pairs = [(i, i + 1) for i in range(1, n) if abs(x[i] - x[i - 1]) < 1.5 * D] + [(2, 0), (7, 0)]
    with open(os.path.join(directory, f"{tag}.dump"), "w") as dump, \
            open(os.path.join(directory, f"{tag}.contacts"), "w") as local:
        for step in steps:
            dump.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{n}\nITEM: BOX BOUNDS pp ff pp\n"
                       f"0 {100 * D}\n0 {10 * D}\n-0.5 0.5\n"
                       "ITEM: ATOMS id type radius mass x y vx vy omegaz v_th f_us[1] f_us[2]\n")
            for k in range(n):
                qx, qy = (0.0, 7e-9) if types[k] == 2 else rng.standard_normal(2) * 1e-8
                dump.write(f"{ids[k]} {types[k]} {0.5 * D} 1e-6 {x[k]} {y[k]} 0 0 0 15 {qx:.6g} {qy:.6g}\n")
            local.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ENTRIES\n{len(pairs)}\nITEM: BOX BOUNDS pp ff pp\n"
                        f"0 1\n0 1\n0 1\nITEM: ENTRIES c_1 c_2 c_3 c_4 c_5 c_6\n")
            for i, j in pairs:
                local.write(f"{i} {j} {rng.uniform(0.1, 2):.6g} 1e5 1e-9 {rng.uniform(0, 1):.6g}\n")
    return ids, x, types, pairs


def _job(tmp_path, freq=70e3, U0=1e-5, times=(1, 2)):
    s = a.snapshot_settings(a.packing_settings(14.4, 4), freq, U0, times)
    directory = tmp_path / "out" / a.job_name(s)
    directory.mkdir(parents=True)
    study.write_job(str(directory), s)
    study.write_result(str(directory), {"theta_m": None, "t_con": None})
    return s, str(directory)


def test_frames_are_cut_to_the_layers_middle(tmp_path):
    rng = np.random.default_rng(3)
    s, directory = _job(tmp_path)
    ids, x, types, pairs = _write_dumps(directory, s["tag"], (1000, 1200, 1400, 1600), rng)
    frames = snaps.job_frames(directory, s)
    assert sorted(frames) == [1, 2]
    snap = frames[2]
    assert snap["t_ms"] == 2.0 and snap["timestep"] == 1400 and snap["theta"] == 15.0
    assert snap["U0"] == pytest.approx(1e-5 * D) and snap["freq"] == 70e3
    x0, x1 = snap["window"]
    assert x1 - x0 == pytest.approx(snaps.WINDOW * D)
    grains = x[types == 1]
    assert 0.5 * (x0 + x1) == pytest.approx(0.5 * (grains.min() + grains.max()))
    inside = {int(t) for t, xx in zip(ids, x) if x0 <= xx <= x1}
    assert set(snap["grains"]["id"]) == inside
    kept = {(i, j) for i, j in zip(snap["contacts"]["i"], snap["contacts"]["j"])}
    assert kept == {(i, j) for i, j in pairs if i in inside and (j in inside or j == 0)}
    assert len(snap["grains"]["qx"]) == len(inside)


def test_the_record_keeps_what_the_dumps_give(tmp_path):
    rng = np.random.default_rng(4)
    s, directory = _job(tmp_path)
    _write_dumps(directory, s["tag"], (0, 200, 400), rng)
    record = tmp_path / "record"
    assert a.record(str(tmp_path / "out"), str(record)) == 1
    recorded = record / a.job_name(s)
    assert sorted(os.listdir(recorded)) == ["job.json", "result.json", "snapshot_1ms.json", "snapshot_2ms.json"]
    from_record = snaps.read_snapshots(str(recorded))
    from_dumps = snaps.read_snapshots(directory, s)
    assert sorted(from_record) == sorted(from_dumps) == [1, 2]
    for t in (1, 2):
        for part in ("grains", "contacts"):
            for name, column in from_dumps[t][part].items():
                assert np.array_equal(from_record[t][part][name], column), (t, part, name)
    with pytest.raises(ValueError, match="no frame at 5 ms"):
        snaps.job_frames(directory, dict(s, snapshots=[5]))


def test_figures_of_the_snapshots_that_are_there(tmp_path):
    rng = np.random.default_rng(5)
    s, directory = _job(tmp_path, freq=30e3, times=(72,))
    _write_dumps(directory, s["tag"], [1000 + 10 * k for k in range(80)], rng)
    a.record(str(tmp_path / "out"), str(tmp_path / "record"))
    written = avalanche_collect.snapshot_figures(str(tmp_path / "record"), str(tmp_path / "figures"))
    assert [os.path.basename(p) for p in written] == ["fig12_snapshot_30kHz.png"]
    assert matplotlib.image.imread(written[0]).shape[1] >= 1200


def test_snapshot_numbers():
    # a base grain, grains at 1, 2.5 and 7 d above it; three contacts
    # between grains (middles at 1.75, 4.75 and 4 d) and one with the wall
    snap = {"d": D, "U0": 1e-8,
            "grains": {"id": np.array([1, 2, 3, 4]), "type": np.array([2, 1, 1, 1]),
                       "y": np.array([0.0, 1.0, 2.5, 7.0]) * D, "qx": np.array([0.0, 0.0, 3e-10, 0.0]),
                       "qy": np.array([0.0, 1e-8, 4e-10, 1e-11])},
            "contacts": {"i": np.array([2, 3, 2, 2]), "j": np.array([3, 4, 4, 0]),
                         "mu_ratio": np.array([0.2, 0.9, 0.4, 0.1])}}
    n, share, low, high, medians = snaps.snapshot_numbers(snap, bottom=3.0, top=4.5, bands=4)
    assert n == 3
    assert share == pytest.approx(2 / 3) and low == 1.0 and high == 0.0
    assert medians[0] == pytest.approx(1.0) and medians[1] == pytest.approx(0.05)
    assert np.isnan(medians[2]) and medians[3] == pytest.approx(1e-3)


def test_snapshot_rows_of_the_record(tmp_path):
    rng = np.random.default_rng(6)
    s, directory = _job(tmp_path, freq=30e3, times=(1, 2))
    _write_dumps(directory, s["tag"], (0, 200, 400), rng)
    a.record(str(tmp_path / "out"), str(tmp_path / "record"))
    rows = avalanche_collect.snapshot_rows(str(tmp_path / "record"))
    assert [r[:3] for r in rows] == [(30.0, 1e-5, 1), (30.0, 1e-5, 2)]
    from_dumps = avalanche_collect.snapshot_rows(str(tmp_path / "out"))
    assert [r[:6] for r in from_dumps] == [r[:6] for r in rows]
    np.testing.assert_equal([r[6:] for r in from_dumps], [r[6:] for r in rows])
