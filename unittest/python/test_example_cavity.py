"""examples/cavity (paper 004's lid-driven cavity) end to end on a small
cavity: the deck runs in LAMMPS, its three scales of wall force come from
different LAMMPS consumers (a dump of the contacts, compute reduce/chunk,
compute reduce) and must agree; acoustic_tools.cavity reads every output.
The small cavity runs as a job of the study (acoustic_tools.cavity_study,
behind examples/cavity/study.py: job.json, then in.cavity writes
result.json), and study.py collect reads it.  The same cavity run as pieces
(one LAMMPS process per chunk of shear, one of them killed) is the
uninterrupted one, bit for bit."""
import filecmp
import json
import math
import os
import re
import subprocess
import sys
import time

import matplotlib.image as mpimg
import numpy as np
import pytest

from acoustic_tools import cavity, cavity_study, lammps_output, study

LMP = os.environ.get("ACOUSTIC_LMP", "lmp")
HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "cavity")
# H/d = 4, L = 5 H: about 80 grains; I_M = 10 / sqrt(4) (1/4)^1.5 = 0.625
SMALL = {"Hd": 4, "NP": 4, "NU": 10, "strain": 4, "tskip": 1, "nrec": 20, "tag": "c"}


def run_deck(path, variables):
    command = [LMP, "-in", os.path.join(HERE, "in.cavity"), "-log", str(path / "log.lammps"), "-nocite",
               "-screen", "none", "-var", "dir", HERE]
    for name, value in variables.items():
        command += ["-var", name, str(value)]
    done = subprocess.run(command, cwd=path, capture_output=True, text=True, timeout=600)
    log = (path / "log.lammps").read_text()
    assert done.returncode == 0, log[-3000:]
    return log


@pytest.fixture(scope="module")
def small_run(tmp_path_factory):
    """the small cavity as the job OUT/test/small of the study (tag c)"""
    out = tmp_path_factory.mktemp("cavity")
    path = out / "test" / "small"
    settings = dict(cavity_study.job_settings("test", "small", SMALL["Hd"], SMALL["NP"], SMALL["NU"],
                                              SMALL["strain"], SMALL["tskip"], 0, tag=SMALL["tag"]),
                    nrec=SMALL["nrec"])
    printed = cavity_study.run_job(LMP, HERE, str(path), settings)
    assert printed.startswith("test/small: ") and "FAILED" not in printed, printed
    return path, (path / "log.lammps").read_text()


def params(path):
    """the run's parameters: its result.json"""
    return study.read_result(str(path))


def test_job_and_result(small_run):
    path, _ = small_run
    settings = study.read_job(str(path))
    assert settings["set"] == "test" and settings["name"] == "small" and settings["tag"] == "c"
    p = params(path)
    for key in ("d", "H", "L", "P", "U", "I_M", "NP", "NU", "dt", "nevery", "nskip", "nshear", "freq",
                "grains", "Hpacked", "Fnorm_running", "wall_seconds"):
        assert isinstance(p[key], (int, float)), key
    assert p["NP"] == SMALL["NP"] and p["Hd"] == SMALL["Hd"] and p["wall_seconds"] > 0


def test_collect_reads_the_job(small_run):
    path, _ = small_run
    out = path.parent.parent
    done = subprocess.run([sys.executable, os.path.join(HERE, "study.py"), "collect", "--out", str(out)],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert (out / "tables.md").read_text() == done.stdout and "| test/small | 4 | 4 | 10 | 0.625 |" in done.stdout
    row = json.loads((out / "summary.json").read_text())["runs"]["test/small"]
    p = params(path)
    assert row["run"] == "test/small" and row["grains"] == p["grains"] and row["wall_s"] == p["wall_seconds"]
    # the deck's running mean and the tools' mean of the records
    assert row["Fnorm"] == pytest.approx(p["Fnorm_running"], rel=1e-3)


def test_control_parameters_are_paper_004s(small_run):
    path, log = small_run
    p = params(path)
    d, H = p["d"], p["H"]
    assert H == pytest.approx(4 * d) and p["L"] == pytest.approx(5 * H)
    assert p["P"] == pytest.approx(cavity.pressure_from_NP(4, 0.6, 2500, 9.81, H), rel=1e-12)
    assert p["U"] == pytest.approx(cavity.velocity_from_NU(10, 9.81, d), rel=1e-12)
    assert p["I_M"] == pytest.approx(10 / math.sqrt(4) * (d / H) ** 1.5, rel=1e-12)
    assert "cavity result c:" in log
    # the deposit fills the cavity to about H; a dense 2D packing
    assert p["Hpacked"] / H == pytest.approx(1.0, abs=0.2)
    wall = lammps_output.read_ave_time(str(path / "c.wall.txt"))
    assert np.all((wall["phi2d"] > 0.6) & (wall["phi2d"] < 0.9))


def test_three_scales_of_wall_force_agree(small_run):
    path, _ = small_run
    p = params(path)
    wall = lammps_output.read_ave_time(str(path / "c.wall.txt"))
    F = wall["F"]
    portions = np.column_stack([wall[f"F_{i}"] for i in range(1, 11)])
    scale = np.abs(F).max()
    assert scale > 0.0 and np.all(np.isfinite(F))
    # wall scale = sum of the meso scale (compute reduce vs reduce/chunk)
    assert np.allclose(portions.sum(axis=1), F, rtol=0, atol=1e-5 * scale)
    # particle scale (dump of the contacts) against both
    snaps = lammps_output.read_dump(str(path / "c.contacts"))
    steps = np.array([s.timestep for s in snaps])
    assert np.array_equal(steps, wall["TimeStep"].astype(int))
    per_snapshot = np.array([s["v_fwall"].sum() for s in snaps])
    assert np.allclose(per_snapshot, F, rtol=0, atol=1e-5 * scale)
    # the tool's portions from the contact heights are the deck's
    ybot = 0.5 * p["d"]
    _, tool_portions = cavity.portion_force_series(snaps, ybot, ybot + wall["h"])
    assert np.allclose(tool_portions, portions, rtol=0, atol=1e-4 * scale)
    # a frictionless wall pushes: every contact force on the wall is a push
    assert all(np.all(s["v_fwall"] >= 0.0) for s in snaps)
    # records: every nevery steps after nskip
    assert np.all(np.diff(steps) == int(p["nevery"])) and steps[0] == p["nskip"] + p["nevery"]
    assert steps[-1] == p["nshear"] and p["nshear"] % p["nchunk"] == 0 and p["nskip"] % p["nchunk"] == 0


def test_mean_force_and_vortex(small_run):
    path, _ = small_run
    p = params(path)
    wall = lammps_output.read_ave_time(str(path / "c.wall.txt"))
    fnorm = wall["F"].mean() / (p["P"] * p["L"] * p["d"])
    # the deck's own running mean (fix ave/time ave running) is the mean of the records
    logged = float(re.search(r"F/\(PLd\) = ([0-9.eE+-]+)", small_run[1]).group(1))
    assert logged == pytest.approx(fnorm, rel=1e-3)
    # paper 004 Fig. 3b: between 0.5 and 0.9 (a small cavity: a wide margin)
    assert 0.3 < fnorm < 1.3
    blocks = lammps_output.read_ave_chunk(str(path / "c.flow"))
    cols, counts = cavity.time_average_chunks(blocks, first_step=p["nskip"])
    x, y, vx = cols["Coord1"], cols["Coord2"], cols["vx"]
    inside = (counts > 0) & (x > 0) & (x < p["L"])
    h = wall["h"].mean()
    top = inside & (y > h - p["d"])                    # the row under the lid
    bottom = inside & (y < 0.35 * h)
    # one vortex: the grains under the lid go with it, those near the bottom go back
    assert np.average(vx[top], weights=counts[top]) > 0.1 * p["U"]
    assert np.average(vx[bottom], weights=counts[bottom]) < 0.0
    _, _, ell = cavity.vortex_centre(x, y, np.where(counts > 0, vx, np.nan),
                                     np.where(counts > 0, cols["vy"], np.nan), p["L"])
    assert 0.0 < ell < 1.0


def _outputs(path):
    return sorted(f for f in os.listdir(path) if f.startswith("c.") and ".last" not in f and f != "c.resume")


def test_pieces_are_the_uninterrupted_run(small_run, tmp_path):
    """the small cavity in pieces of one chunk (in.cavity's restart points):
    two pieces, then one killed before its restart point (its resume line
    is the one before it, its outputs run past it, the last dump frame cut
    half-way), then the rest; records and result as the uninterrupted run"""
    whole, _ = small_run
    path = tmp_path / "test" / "pieces"
    settings = dict(study.read_job(str(whole)), name="pieces")
    printed = cavity_study.run_job(LMP, HERE, str(path), settings, piece_seconds=1e-3, max_pieces=2)
    assert "paused after 2 piece(s) at step" in printed and study.read_result(str(path)) is None, printed
    step = cavity_study.read_resume(str(path), "c")[0]
    assert step == 2 * params(whole)["nchunk"]
    resume = (path / "c.resume").read_text()
    printed = cavity_study.run_job(LMP, HERE, str(path), settings, piece_seconds=1e-3, max_pieces=1)
    assert cavity_study.read_resume(str(path), "c")[0] > step, printed
    (path / "c.resume").write_text(resume)              # killed before its resume line
    with open(path / "c.contacts", "a") as handle:      # and in the middle of a frame
        handle.write("ITEM: TIMESTEP\n999999\nITEM: NUMBER OF ATOMS\n7\n")
    printed = cavity_study.run_job(LMP, HERE, str(path), settings, piece_seconds=1e-3)
    assert printed.startswith("test/pieces: ") and "FAILED" not in printed, printed
    assert "resumed at step" in (path / f"log.piece{step}").read_text()
    assert _outputs(path) == _outputs(whole) and "c.wall.txt" in _outputs(path)
    for name in _outputs(whole):
        assert filecmp.cmp(path / name, whole / name, shallow=False), name
    one, pieced = params(whole), params(path)
    assert one.pop("wall_seconds") > 0 and pieced.pop("wall_seconds") > 0
    assert pieced == one


def test_no_piece_after_the_deadline(tmp_path):
    """study.py run --hours: no piece starts after the call's deadline"""
    settings = cavity_study.job_settings("test", "late", SMALL["Hd"], SMALL["NP"], SMALL["NU"], SMALL["strain"],
                                         SMALL["tskip"], 0, tag="c")
    printed = cavity_study.run_job(LMP, HERE, str(tmp_path / "late"), settings, deadline=time.time() - 1)
    assert "paused at the start" in printed and not (tmp_path / "late" / "log.lammps").exists()


def test_study_run_in_pieces_and_collect(tmp_path, monkeypatch):
    """study.py run of a set, in pieces (--piece-hours: one chunk each, two
    pieces per call with --max-pieces), repeated until done; then collect
    and figures read it"""
    tiny = {"c1": dict(Hd=4, LH=5, NP=4, NU=10, strain=3, tskip=1, freq=0, seed=2, walls="coulomb", stress=1,
                       tchunk=1, uslid=0)}
    # in the place of the h30 set, so that collect and figures take it for the H/d = 30 scan
    monkeypatch.setitem(cavity_study.SETS, "h30", tiny)
    out = tmp_path / "out"
    argv = ["run", "h30", "--out", str(out), "--lmp", LMP, "--piece-hours", "1e-7", "--max-pieces", "2"]
    cavity_study.main(HERE, argv)
    run = out / "h30" / "c1"
    assert study.read_result(str(run)) is None and cavity_study.read_resume(str(run), "cavity") is not None
    cavity_study.main(HERE, argv)
    p = study.read_result(str(run))
    assert p is not None and p["walls"] == "coulomb" and p["stress"] == 1
    assert study.read_job(str(run))["seed"] == 2 and "-var seed 2" in " ".join(
        cavity_study.command(LMP, HERE, str(run), study.read_job(str(run))))
    cavity_study.main(HERE, ["collect", "--out", str(out)])
    row = json.loads((out / "summary.json").read_text())["runs"]["h30/c1"]
    assert row["walls"] == "coulomb" and row["seed"] == 2 and "stationarity" in row and "zeros" in row
    assert row["mu_I_points"] > 0
    cavity_study.main(HERE, ["figures", "--out", str(out), "--figures", str(tmp_path / "figs")])
    widths = {png.name: mpimg.imread(str(png)).shape[1] for png in (tmp_path / "figs").glob("*.png")}
    assert "fig13_wall_pdfs_H30.png" in widths and min(widths.values()) >= 1200, widths
    # the record keeps the run's numbers without its recordings, and gives the same tables
    record = tmp_path / "record"
    cavity_study.main(HERE, ["record", "--out", str(out), "--record", str(record)])
    kept = sorted(os.listdir(record / "h30" / "c1"))
    assert kept == ["job.json", "region.json", "result.json", "row.json"]
    cavity_study.main(HERE, ["collect", "--out", str(record)])
    assert (record / "tables.md").read_text() == (out / "tables.md").read_text()
    assert json.loads((record / "summary.json").read_text()) == json.loads((out / "summary.json").read_text())
    cavity_study.main(HERE, ["figures", "--out", str(record), "--figures", str(tmp_path / "figs_record")])


def test_ultrasound_from_the_bottom(tmp_path):
    log = run_deck(tmp_path, dict(SMALL, strain=2, freq=70e3, tag="u"))
    assert study.read_result(str(tmp_path)) is None and (tmp_path / "u.result.json").exists()
    assert "not in the vibration network" in log      # region side walls: free surfaces, said once
    us = lammps_output.read_ave_time(str(tmp_path / "u.us.txt"))
    ratio = us["mu_ratio_mean"]
    assert len(ratio) > 3 and np.all(np.isfinite(ratio))
    assert np.all((ratio > 0.0) & (ratio <= 1.0)) and ratio.min() < 1.0
    wall = lammps_output.read_ave_time(str(tmp_path / "u.wall.txt"))
    assert np.all(np.isfinite(wall["F"]))


def test_bad_parameters_are_refused(tmp_path):
    for bad, what in (({"strain": 1, "tskip": 2}, "strain"), ({"Hd": 2}, "Hd >= 3"),
                      ({"walls": "rough"}, "walls must be smooth or coulomb"),
                      ({"append": 1, "restart": "none.restart"}, "needs -var restart"),
                      ({"strain": 1.2, "tskip": 1, "tchunk": 1}, "by at least one chunk")):
        command = [LMP, "-in", os.path.join(HERE, "in.cavity"), "-log", str(tmp_path / "log.bad"), "-nocite",
                   "-screen", "none", "-var", "dir", HERE]
        for name, value in dict(SMALL, **bad).items():
            command += ["-var", name, str(value)]
        subprocess.run(command, cwd=tmp_path, capture_output=True, text=True, timeout=60)
        text = (tmp_path / "log.bad").read_text()
        assert "ERROR: in.cavity" in text and what in text, text[-500:]
