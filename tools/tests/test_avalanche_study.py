"""acoustic_tools.avalanche_study: the production sets of issue 42 at the
calibrated coupling, the names of their jobs beside those run before the
calibration, and the observation window of the decks (no LAMMPS)."""
import os

import pytest

from acoustic_tools import avalanche_study as a


def test_the_calibrated_coupling_is_the_default():
    assert a.KAPPA == 0.17 and a.KAPPA_BEFORE == 0.3
    assert a.ramp_settings(a.packing_settings(6, 1), 70e3)["kappa"] == a.KAPPA
    # in.avalanche and in.modes take the same default
    here = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "avalanche")
    for deck in ("in.avalanche", "in.modes"):
        defaults = [line.split()[3] for line in open(os.path.join(here, deck))
                    if line.split()[:3] == ["variable", "kappa", "index"]]
        assert defaults == [f"{a.KAPPA:g}"], deck


def test_no_calibrated_job_takes_the_name_of_one_run_before():
    packing = a.packing_settings(6, 1)
    before = {a.job_name(job) for name in ("free", "tcon", "switch_on", "kappa_free") for what, job in
              a.production(name) if what == "ramp"}
    now = {a.job_name(job) for name in ("thickness", "sensitivity", "paper_length", "table1") for what, job in
           a.production(name)}
    assert not before & now
    assert a.job_name(a.ramp_settings(packing, 70e3)) == "free400_H6_s1_f70_k0.17"
    assert a.job_name(a.ramp_settings(packing, 70e3, kappa=0.3)) == "free400_H6_s1_f70"   # the record's name


def test_thickness_set():
    jobs = a.production("thickness")
    assert all(what == "ramp" for what, _ in jobs)
    settings = [s for _, s in jobs]
    assert len(settings) == 5 * 4 * 2
    assert {(s["H"], s["seed"], s["freq"]) for s in settings} == {
        (float(H), seed, f) for H in a.THICKNESSES for seed in (1, 2, 3, 4) for f in (0.0, 70e3)}
    assert {s["kappa"] for s in settings} == {a.KAPPA}
    assert all(s["free"] == 1 and s["layer"] == 400 and s["switch_on"] is None and s["theta0"] == 10
               for s in settings)


def test_tcon_set_at_the_same_distance_above_theta_m():
    jobs = a.production("tcon_cal")
    assert {(ramp["H"], ramp["freq"]) for _, (ramp, _) in jobs} == {
        (H, f) for H in (6.0, 11.4, 14.4) for f in (0.0, 70e3)}
    for _, (ramp, options) in jobs:
        assert options["steps"] == (1, 2, 3) and ramp["kappa"] == a.KAPPA
        assert options["angles"] == ((19.0,) if ramp["H"] == 6 else ())
    # the t_con runs go on from the thickness set's ramps (same job)
    thickness = {a.job_name(s) for _, s in a.production("thickness")}
    assert {a.job_name(ramp) for _, (ramp, _) in jobs} <= thickness


def test_sensitivity_set_pairs_with_the_thickness_set():
    settings = [s for _, s in a.production("sensitivity")]
    assert sorted({s["kappa"] for s in settings}) == [0.14, 0.21]
    assert {s["H"] for s in settings} == {14.4} and {s["freq"] for s in settings} == {70e3}
    # the same deposits as the thickness set: its 0 Hz ramps are the reference
    deposits = {s["deposit"] for _, s in a.production("thickness") if s["H"] == 14.4}
    assert {s["deposit"] for s in settings} == deposits


def test_paper_length_layers_observe_571_d_in_the_middle():
    settings = [s for _, s in a.production("paper_length")]
    assert {(s["H"], s["freq"]) for s in settings} == {(H, f) for H in (6.0, 14.4) for f in (0.0, 70e3)}
    for s in settings:
        assert s["layer"] == 2000 and s["window"] == 571 and s["piece"] == "auto"
        g = a.geometry_variables(s)
        L = 2000 + 2 * a.MARGIN
        lo, hi = float(g["obslo"]) * L, float(g["obshi"]) * L
        assert hi - lo == pytest.approx(571, abs=5e-3)   # 6 decimals of the box length and (lo + hi) / 2 == pytest.approx(L / 2)
        assert a.job_name(s).endswith("_w571")
    # without a window: the middle half, as before (the record's jobs)
    g = a.geometry_variables(a.packing_settings(6, 1))
    assert float(g["obshi"]) - float(g["obslo"]) == pytest.approx(200 / 500, abs=1e-6)
    with pytest.raises(ValueError):
        a.geometry_variables(dict(a.packing_settings(6, 1), window=500))


def test_tcon_runs_keep_the_window_of_their_ramp():
    ramp = a.ramp_settings(a.packing_settings(6, 1, layer=2000), 70e3, window=571)
    s = a.tcon_settings(ramp, 19.0)
    assert s["window"] == 571 and a.geometry_variables(s) == a.geometry_variables(ramp)


def test_table1_runs_the_same_simulated_time_at_both_frequencies():
    settings = [s for _, s in a.production("table1")]
    assert [(s["H"], s["freq"]) for s in settings] == [(3.0, 0.0), (3.0, 70e3), (14.4, 0.0), (14.4, 70e3)]
    for s in settings:
        # one angle, held exactly the window (no follow), no dumps, one process
        assert s["theta0"] == s["thetamax"] == a.TABLE1_THETA and s["tfollow"] == 0
        assert s["dumpevery"] == 0 and s["dumplocal"] == 0 and s["piece"] == 0
    # in.deposit's count of grains for these lengths: the paper's N
    for H, grains in a.TABLE1:
        assert round(H * a.table1_layer(H, grains) * a.GRAINS_PER_AREA) == pytest.approx(grains, rel=2e-3)


def test_every_set_is_known_and_the_sets_before_keep_their_coupling():
    for name in a.PRODUCTION:
        assert a.production(name), name
    for name in ("periodic", "free", "more"):
        assert {s["kappa"] for _, s in a.production(name)} == {a.KAPPA_BEFORE}
    with pytest.raises(ValueError):
        a.production("nothing")


class _FakeRunner(a.Runner):
    """A Runner whose LAMMPS processes write what the decks would (a result
    and the restart files) with the given theta_m, and are counted."""

    def __init__(self, tmp_path, theta_m=17.5, recorded=None):
        build = tmp_path / "build"
        (build / "lammps").mkdir(parents=True)
        lmp = build / "lammps" / "lmp"
        lmp.write_text("#!/bin/sh\n")
        lmp.chmod(0o755)
        super().__init__(str(build), str(tmp_path / "out"), str(tmp_path), say=lambda line: None,
                         recorded=recorded)
        self.theta_m, self.calls = theta_m, []

    def lammps(self, directory, deck, variables, log, contact=None):
        self.calls.append((os.path.basename(directory), deck))
        if deck == "in.deposit":
            result = {"grains": 100, "base": 20, "H_measured": 6.0}
            open(os.path.join(directory, "deposit.restart"), "w").close()
        else:
            theta = float(variables["theta0"])
            result = {"theta_m": self.theta_m if variables["tag"].startswith("f") else theta, "t_con": 0.1}
            open(os.path.join(directory, f"{variables['tag']}.static.restart"), "w").close()
        a.study.write_result(directory, result)
        return 0.0


def _record(record, settings, result):
    directory = os.path.join(record, a.job_name(settings))
    a.study.write_job(directory, settings)
    a.study.write_result(directory, result)


def test_a_recorded_ramp_is_not_run_again(tmp_path):
    ramp = a.ramp_settings(a.packing_settings(3, 1), 0, theta0=10)
    _record(str(tmp_path / "record"), ramp, {"theta_m": 21.0, "t_con": None})
    runner = _FakeRunner(tmp_path, recorded=str(tmp_path / "record"))
    assert runner.ramp(ramp)["theta_m"] == 21.0
    assert runner.calls == []
    # without the record it runs (deposit, then the ramp)
    fresh = _FakeRunner(tmp_path / "fresh")
    assert fresh.ramp(ramp)["theta_m"] == 17.5
    assert [deck for _, deck in fresh.calls] == ["in.deposit", "in.avalanche"]


def test_tcon_runs_of_a_recorded_ramp_run_it_again_for_its_static_state(tmp_path):
    ramp = a.ramp_settings(a.packing_settings(6, 2), 70e3, theta0=10)
    record = str(tmp_path / "record")
    _record(record, ramp, {"theta_m": 17.5, "t_con": None})
    runner = _FakeRunner(tmp_path, recorded=record)
    results = runner.tcon(ramp, steps=(1, 2))
    assert [r["theta_m"] for r in results] == [18.5, 19.5]
    assert [name for name, _ in runner.calls] == [
        a.job_name(a.deposit_settings(a.packing_settings(6, 2))), a.job_name(ramp),
        a.job_name(a.tcon_settings(ramp, 18.5)), a.job_name(a.tcon_settings(ramp, 19.5))]
    # the t_con runs recorded too: nothing runs
    for theta in (18.5, 19.5):
        _record(record, a.tcon_settings(ramp, theta), {"theta_m": theta, "t_con": 0.2})
    again = _FakeRunner(tmp_path / "again", recorded=record)
    assert [r["t_con"] for r in again.tcon(ramp, steps=(1, 2))] == [0.2, 0.2]
    assert again.calls == []


def test_a_ramp_run_again_to_another_theta_m_stops_the_production(tmp_path):
    ramp = a.ramp_settings(a.packing_settings(6, 3), 0, theta0=10)
    record = str(tmp_path / "record")
    _record(record, ramp, {"theta_m": 18.0, "t_con": None})
    runner = _FakeRunner(tmp_path, theta_m=18.5, recorded=record)
    with pytest.raises(SystemExit, match="not the same ramp"):
        runner.tcon(ramp, steps=(1,))


def test_run_selects_one_thickness():
    jobs = a.selected(a.production("thickness"), [8.7])
    assert len(jobs) == 8 and {s["H"] for _, s in jobs} == {8.7}
    tcon = a.selected(a.production("tcon_cal"), [6, 14.4])
    assert len(tcon) == 16 and {ramp["H"] for _, (ramp, _) in tcon} == {6.0, 14.4}
    assert a.selected(a.production("table1")) == a.production("table1")


def test_a_killed_piece_counts_up_to_its_last_whole_angle(tmp_path):
    d = str(tmp_path)
    resume = tmp_path / "f70.resume"
    resume.write_text("12 0.5 1000 f70.restart 12.5 f70.last0.in\n")
    a.piece_begins(d, "f70")
    a.piece_ends(d)
    assert a.killed_pieces_time(d) == 0, "a piece that ended wrote its own total"
    a.piece_begins(d, "f70")                      # killed: never ends
    pieces = a._read_pieces(d)
    now = pieces[-1]["start"]
    pieces[-1]["start"] = now - 100.0             # began 100 s ago,
    a._write_pieces(d, pieces)
    os.utime(resume, (now - 60.0, now - 60.0))    # wrote its last whole angle 40 s later
    a.piece_begins(d, "f70")                      # killed before its first angle
    a.piece_begins(d, "f70")
    a.piece_ends(d)
    pieces = a._read_pieces(d)
    assert [p.get("kept") for p in pieces] == [None, pytest.approx(40.0), 0.0, None]
    assert all("end" in p for p in (pieces[0], pieces[-1])) and "end" not in pieces[1]
    assert a.killed_pieces_time(d) == pytest.approx(40.0)
    assert a.killed_pieces_time(str(tmp_path / "none")) == 0
