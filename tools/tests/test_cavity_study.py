"""acoustic_tools.cavity_study: the sets of issue 43 (paper 004's cavity at
H/d = 30) as data, the length and cost rules, and the tidying of the
outputs of a cavity run as pieces (synthetic files)"""
import math
import os
import shutil

import pytest

from acoustic_tools import cavity, cavity_study as cs


def im_of(s):
    return cavity.inertial_number_from_NP_NU(s["NP"], s["NU"], 1.0 / s["Hd"])


def recorded_seconds(s):
    return (s["strain"] - s["tskip"]) * cs.hu_seconds(s["NU"], s["Hd"])


def test_the_scan_is_paper_004s():
    scan = cs.set_jobs("h30")
    assert all(s["Hd"] == 30 and s["LH"] == 5 and s["walls"] == "smooth" and s["freq"] == 0 for s in scan.values())
    ims = sorted({float(f"{im_of(s):.2g}") for s in scan.values()})
    assert len(ims) >= 7 and ims[0] == pytest.approx(1e-3, rel=1e-3) and ims[-1] == pytest.approx(0.6, rel=1e-3)
    for im in ims:
        pairs = {(s["NU"], s["NP"]) for s in scan.values() if float(f"{im_of(s):.2g}") == im}
        assert len(pairs) >= 2
        if im <= 1e-2 * 1.001:
            assert any(NU == 10 for NU, _ in pairs)          # N_U no longer confounded with I_M
    for s in scan.values():
        # records at 10 kHz; 10 s recorded after 1 s, or at least the paper's 891 d/U
        assert s["nrec"] == pytest.approx(1e4 * 1e-3 / (s["NU"] * math.sqrt(9.81e-3)), rel=1e-5)
        full = recorded_seconds(s) == pytest.approx(9.0, rel=1e-3) and \
            s["tskip"] * cs.hu_seconds(s["NU"]) == pytest.approx(1.0, rel=1e-2)
        assert full or ((s["strain"] - s["tskip"]) * s["Hd"] >= 890 and s["tskip"] >= 5)
        assert s["stress"] == 1


def test_packings_sensitivity_and_ultrasound():
    seeds = list(cs.set_jobs("h30").values()) + list(cs.set_jobs("h30seeds").values())
    for im in (1e-3, 1e-2, 0.1, 0.3):
        at = [s for s in seeds if im_of(s) == pytest.approx(im, rel=1e-3)]
        assert len({s["seed"] for s in at}) >= 3 and len({(s["NU"], s["NP"]) for s in at}) >= 2
    sens = cs.set_jobs("h30sens")
    assert sum(s["walls"] == "coulomb" for s in sens.values()) >= 1
    assert any(s["LH"] == 7 for s in sens.values())
    us = cs.set_jobs("h30us")
    assert {s["NP"] for s in us.values()} == {cs.US_NP} and all(s["uslid"] == 1 for s in us.values())
    groups = {}
    for s in us.values():
        groups.setdefault((s["NU"], s["freq"]), set()).add(s["seed"])
    assert len({NU for NU, _ in groups}) >= 3 and {f for _, f in groups} >= {0.0, 70e3}
    assert all(len(v) >= 3 for v in groups.values())


def test_time_step_length_and_chunks():
    # the deck's time step at H/d = 30, N_P = 1 (its log: dt 2.506e-06 s), and its scaling
    assert cs.time_step(1.0) == pytest.approx(2.506e-6, rel=1e-3)
    assert cs.time_step(100.0) == pytest.approx(cs.time_step(1.0) / 10)
    assert cs.np_for(1e-3, 1) == pytest.approx((30 ** -1.5 / 1e-3) ** 2, rel=1e-3)
    # the paper's 10 s when it fits, the paper's d/U otherwise
    assert cs.paper_length(0.04, 10) == (pytest.approx(330.15, abs=0.01), pytest.approx(33.02, abs=0.01))
    strain, tskip = cs.paper_length(3704, 10)
    assert tskip == cs.REDUCED_SKIP_HU and (strain - tskip) * 30 == pytest.approx(cs.PAPER_RECORD_DU, abs=1)
    for s in cs.set_jobs("h30").values():
        steps_per_hu = cs.hu_seconds(s["NU"]) / cs.time_step(s["NP"])
        assert 0.05 <= s["tchunk"] <= 4 and s["tchunk"] * steps_per_hu <= 2.1 * cs.CHUNK_STEPS
    assert cs.grains(30) == 4550 and cs.grains(10) == 506       # the deck's counts


def test_cost_model():
    s = cs.set_jobs("h30")["im3e-1_nu10"]
    prep, shear = cs.steps(s)
    assert shear == pytest.approx(10.0 / cs.time_step(s["NP"]), rel=1e-3)
    hours = cs.cost_hours(s, 1e6)
    assert hours == pytest.approx((prep + shear) * (4550 + 300) / 1e6 / 3600, rel=1e-9)
    us = dict(s, freq=70e3)
    assert cs.solve_interval(us) >= 1
    assert cs.cost_hours(us, 1e6, solve_steps=0) < cs.cost_hours(us, 1e6, solve_steps=40)
    lines = cs.plan(["h30", "h30sens"], 3e6)
    assert lines[-1].startswith("all: ") and any(line.startswith("| h30sens/") for line in lines)


def test_plan_progress_counts_finished_and_paused_runs(tmp_path):
    jobs = cs.set_jobs("h30")
    finished, paused = tmp_path / "h30" / "im3e-1_nu10", tmp_path / "h30" / "im1e-1_nu30"
    finished.mkdir(parents=True)
    paused.mkdir(parents=True)
    (finished / "result.json").write_text('{"Fnorm": 0.86}')
    prep, shear = cs.steps(jobs["im1e-1_nu30"])
    (paused / f"{jobs['im1e-1_nu30']['tag']}.resume").write_text(f"{round(shear / 2)} a.restart a.in 0\n")
    done = cs.done_fraction(str(paused), jobs["im1e-1_nu30"])
    assert done == pytest.approx((prep + round(shear / 2)) / (prep + shear))
    assert cs.done_fraction(str(finished), jobs["im3e-1_nu10"]) == 1.0
    assert cs.done_fraction(str(tmp_path / "h30" / "im1e-3_nu1"), jobs["im1e-3_nu1"]) == 0.0
    rate = 3e6
    lines = cs.plan(["h30"], rate, out=str(tmp_path))
    total = sum(cs.cost_hours(s, rate) for s in jobs.values())
    left = total - cs.cost_hours(jobs["im3e-1_nu10"], rate) - done * cs.cost_hours(jobs["im1e-1_nu30"], rate)
    assert lines[-1] == f"all: {total:.0f} h on one rank, {left:.1f} h left"
    assert any(line.startswith("| h30/im3e-1_nu10 |") and line.endswith(" 100 % | 0.0 |") for line in lines)


def test_job_settings_refuse_unknown_variables():
    with pytest.raises(ValueError):
        cs.job_settings("x", "y", 10, 1, 10, 4, 1, 0, colour="red")
    job = cs.job_settings("x", "y", 10, 1, 10, 4, 1, 0, walls="coulomb", tchunk=0.5)
    command = cs.command("lmp", "/here", "/dir", job)
    assert command[command.index("walls") + 1] == "coulomb" and command[command.index("tchunk") + 1] == "0.5"


def test_only_selects_a_named_run_alone():
    def names(sets, only):
        return [f"{set_name}/{name}" for set_name, name, _ in cs.select_runs(sets, only)]
    assert len(names(["h30"], None)) == len(cs.set_jobs("h30"))
    # a run's name selects it, not the runs whose names start with it
    assert names(["h30"], ["im1e-2_nu1"]) == ["h30/im1e-2_nu1"]
    assert names(["h30", "h30seeds"], ["h30/im3e-1_nu10"]) == ["h30/im3e-1_nu10"]
    # any other text is a part of set/name
    assert names(["h30"], ["im1e-2"]) == ["h30/im1e-2_nu1", "h30/im1e-2_nu10"]
    assert names(["h30", "h30seeds"], ["im1e-2_nu1_s"]) == ["h30seeds/im1e-2_nu1_s2", "h30seeds/im1e-2_nu1_s3"]
    assert names(["h30"], ["nu30", "im6e-1_nu10"]) == ["h30/im1e-1_nu30", "h30/im3e-1_nu30",
                                                       "h30/im6e-1_nu10", "h30/im6e-1_nu30"]


def test_tidy_series_chunks_and_dump(tmp_path):
    wall = tmp_path / "c.wall.txt"
    header = "# title\n# TimeStep F\n"
    # piece 1 ends at 20 (nskip 10); piece 2 writes its first step again; a killed piece 3 ran past 40
    wall.write_text(header + "15 1\n20 2\n" + header + "20 2\n25 3\n30 4\n" + header + "30 4\n35 5\n40 6\n45 7\n")
    cs.tidy_series(str(wall), upto=40, after=10)
    assert wall.read_text() == header + "15 1\n20 2\n25 3\n30 4\n35 5\n40 6\n"
    # a resumed piece at nskip writes a record at nskip: dropped
    wall.write_text(header + header + "10 0\n15 1\n")
    cs.tidy_series(str(wall), after=10)
    assert wall.read_text() == header + "15 1\n"
    flow = tmp_path / "c.flow"
    h = "# a\n# b\n# c\n"
    flow.write_text(h + "20 2 5\n1 x\n2 y\n" + h + "40 2 5\n1 x\n2 y\n60 2 5\n1 x\n")   # the last block cut by a kill
    cs.tidy_chunks(str(flow), upto=40)
    assert flow.read_text() == h + "20 2 5\n1 x\n2 y\n40 2 5\n1 x\n2 y\n"
    dump = tmp_path / "c.contacts"

    def frame(step, n):
        return (f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{n}\nITEM: BOX BOUNDS pp ff pp\n0 1\n0 1\n0 1\n"
                f"ITEM: ATOMS id v_ycontact v_fwall\n" + "".join(f"{k} 0.1 0.2\n" for k in range(n)))
    whole = frame(15, 2) + frame(20, 0) + frame(25, 1)
    dump.write_text(whole + frame(30, 3)[:-10])
    cs.tidy_dump(str(dump), upto=25)
    assert dump.read_text() == whole


def test_the_committed_record_gives_its_tables(tmp_path, capsys):
    # examples/cavity/record: collect from the record alone prints the committed tables.md
    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "cavity")
    record = os.path.join(here, "record")
    if not os.path.isdir(os.path.join(record, "h30")):
        pytest.skip("no H/d = 30 run recorded yet")
    copy = tmp_path / "record"
    shutil.copytree(record, copy)
    cs.main(here, ["collect", "--out", str(copy)])
    assert (copy / "tables.md").read_text() == open(os.path.join(record, "tables.md")).read()
    assert "| h30/im1e-2_nu1 |" in capsys.readouterr().out
