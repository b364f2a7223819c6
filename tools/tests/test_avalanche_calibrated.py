"""acoustic_tools.avalanche_collect on synthetic jobs of issue 42's production
sets at the calibrated coupling (kappa_scale 0.17; job.json and result.json
written here as the run command and the decks write them): theta_m per
thickness with standard errors and the shift paired by packing, t_con above
theta_m (tcon_cal), the shift against kappa_scale (sensitivity), the
2000 d layers beside the 400 d ones (paper_length) and Table 1's
(t70 - t0)/t70 from the wall times (table1), each against values worked out
by hand; the sets run before the calibration (0.3) stay apart."""
import json
import os

import numpy as np
import pytest

from acoustic_tools.avalanche_study import (KAPPA, TABLE1, deposit_settings, packing_settings, ramp_settings,
                                            table1_settings, tcon_settings)
from test_avalanche_collect import Pack, angle, ramp_result, write


def uniform_at(theta, start=None):
    """The angle states of a ramp from start (default theta - 1) that flows uniformly at theta."""
    start = theta - 1.0 if start is None else start
    return [(th, "stable") for th in np.arange(start, theta, 0.5)] + [(theta, "uniform")]


def ramps(p, f0, f70, tcon0=0.5, tcon70=0.2):
    if f0 is not None:
        p.ramp("f0", uniform_at(f0), f0, tcon0)
    if f70 is not None:
        p.ramp("f70", uniform_at(f70), f70, tcon70, mu=0.6)
    return p


@pytest.fixture
def thickness(tmp_path):
    """Free-ends 400 d packings at 0.17 (H = 3 d: three packings, the third
    without its 70 kHz ramp; H = 6 d: two) and the same packings' ramps at
    0.3 (the sets before the calibration: other angles)."""
    for seed, f0, f70 in ((1, 20.0, 15.0), (2, 21.0, 17.5), (3, 19.5, None)):
        ramps(Pack(tmp_path, 3, seed, 3.0, kappa=KAPPA), f0, f70)
        ramps(Pack(tmp_path, 3, seed, 3.0, kappa=0.3), 22.0, 21.0)
    for seed, f0, f70 in ((1, 18.0, 16.0), (2, 17.5, 15.5)):
        ramps(Pack(tmp_path, 6, seed, 6.1, kappa=KAPPA), f0, f70)
        ramps(Pack(tmp_path, 6, seed, 6.1, kappa=0.3), 18.5, 14.5)
    return tmp_path


def markdown(collect, top, tables):
    return collect.write_tables(collect.study_data(str(top)), str(tables))


def test_theta_m_per_thickness_with_standard_errors_and_the_paired_shift(collect, thickness, tmp_path):
    cal = collect.calibrated_study(str(thickness))
    assert list(cal["ensembles"]) == ["free ends, 400 d"] and cal["label"] == "free ends, 400 d"
    r3, r6 = cal["summary"]["free ends, 400 d"][0]
    # 0 kHz over the three packings: 20, 21, 19.5
    assert r3["theta0"] == pytest.approx((np.mean([20, 21, 19.5]), np.std([20, 21, 19.5], ddof=1), 3))
    # the shift paired by packing: 20 - 15 = 5 and 21 - 17.5 = 3.5 (packing 3 has no 70 kHz ramp)
    assert r3["shift"] == pytest.approx((4.25, 1.5 / np.sqrt(2), 2))
    assert collect.standard_error(r3["shift"])[0] == pytest.approx(0.75)
    assert r6["shift"] == pytest.approx((2.0, 0.0, 2))
    # the ensembles at 0.3 are those of the same packings' ramps at 0.3 only
    before = collect.ensembles(str(thickness))["free ends, 400 d"]
    assert {p["f0"][0] for p in before[3.0]} == {22.0} and {p["f70"][0] for p in before[6.0]} == {14.5}
    assert collect.kappa_study(str(thickness), free=1) == [], "the 0.17 ramps are not the kappa study before"
    text = markdown(collect, thickness, tmp_path / "tables")
    assert text.startswith("\n## The study at kappa_scale 0.17 (the calibrated coupling)\n")
    calibrated, before_text = text.split("## Before the calibration: kappa_scale 0.3 (run before the calibration: "
                                         "sensitivity study)\n")
    # mean ± s.d. (s.e.): 20.17 ± 0.76 (0.44); 16.25 ± 1.77 (1.25); shift 4.25 ± 1.06 (0.75), 2 pairs
    assert ("| 3 (3.00) | 3 | 500 + 80, 80 d | 20.17 ± 0.76 (0.44)° | 16.25 ± 1.77 (1.25)° | 4.25 ± 1.06 (0.75)° "
            "| 2 | 20 (stated)° | 14.5 (stated)° | 5.5 (stated)° |") in calibrated
    # at 6 d the paper's values are interpolated (20 - 3 * 3 / 11.4 = 19.2) and said so
    assert ("| 6 (6.10) | 2 | 500 + 80, 80 d | 17.75 ± 0.35 (0.25)° | 15.75 ± 0.35 (0.25)° | 2.00 ± 0.00 (0.00)° "
            "| 2 | ≈ 19.2 (interpolated)° | ≈ 17.2 (interpolated)° | ≈ 2 (its text)° |") in calibrated
    assert "- H = 3 d: s1: 20 / 15°, 5°, 0.50 / 0.20 s; s2: 21 / 17.5°, 3.5°" in calibrated
    assert "| 22.00 ± 0.00° | 21.00 ± 0.00° |" in before_text and "22.00" not in calibrated
    # Fig. 7's table of the calibrated ensemble: H/d, means and s.d., paper's stated values
    rows = np.loadtxt(tmp_path / "tables" / "thetam_calibrated.txt")
    assert rows[0, :5] == pytest.approx([3.0, 20 + 1 / 6, np.std([20, 21, 19.5], ddof=1), 16.25,
                                         np.std([15, 17.5], ddof=1)], abs=1e-4)   # 6 digits (%g)
    assert rows[0, 5:] == pytest.approx([20, 14.5]) and np.isnan(rows[1, 5:]).all()
    summary = json.loads((tmp_path / "tables" / "summary_calibrated.json").read_text())
    assert summary["kappa_scale"] == KAPPA
    assert summary["geometries"]["free ends, 400 d"]["rows"][0]["shift"] == pytest.approx([4.25, 1.5 / np.sqrt(2), 2])


def test_the_first_spreading_flow_beside_theta_m(collect, tmp_path):
    # 70 kHz ramps that creep and spread (partial) before they flow uniformly
    for seed, f0, onset, f70 in ((1, 21.0, 16.5, 21.0), (2, 19.5, 17.0, 19.0)):
        p = Pack(tmp_path, 3, seed, 3.0, kappa=KAPPA)
        p.ramp("f0", uniform_at(f0), f0, 0.5)
        p.creeping(10.0, onset, f70)
    text = markdown(collect, tmp_path, tmp_path / "tables")
    # theta_m shift: 0 and 0.5; first spreading: 0 kHz 21, 19.5 (= theta_m), 70 kHz 16.5, 17: shifts 4.5, 2.5
    assert "| 0.25 ± 0.35 (0.25)° | 2 |" in text
    assert ("- H = 3 d: 0 kHz 20.25 ± 1.06 (0.75)°, 70 kHz 16.75 ± 0.35 (0.25)°, "
            "shift paired by packing 3.50 ± 1.41 (1.00)° (2 pairs)") in text


def test_tcon_at_the_same_distance_above_theta_m(collect, tmp_path):
    s1 = ramps(Pack(tmp_path, 6, 1, 6.0, kappa=KAPPA), 18.0, 16.0, tcon0=0.8, tcon70=0.3)
    s2 = ramps(Pack(tmp_path, 6, 2, 6.0, kappa=KAPPA), 17.5, 15.5, tcon0=0.6, tcon70=0.1)
    for theta, t in ((19.0, 0.4), (20.0, 0.3), (21.0, 0.2)):
        s1.tcon("f0", theta, t)
    for theta, t in ((18.5, 0.6), (19.5, 0.5), (20.5, None), (19.0, 0.7)):
        s2.tcon("f0", theta, t)
    s1.tcon("f70", 17.0, 0.2)
    s2.tcon("f70", 16.5, 0.4)
    packs = collect.calibrated_study(str(tmp_path))["ensembles"]["free ends, 400 d"][6.0]
    assert collect.tcon_above(packs, "f0", 1.0) == [0.4, 0.6]
    assert collect.tcon_above(packs, "f0", 3.0)[0] == 0.2 and np.isnan(collect.tcon_above(packs, "f0", 3.0)[1])
    text = markdown(collect, tmp_path, tmp_path / "tables")
    # at theta_m: 0.8, 0.6; +1: 0.4, 0.6; +2: 0.3, 0.5; +3: 0.2 and one not uniform; 19 deg: 0.4 (s1's +1) and 0.7
    assert ("| 6 | 0 kHz | 0.70 ± 0.14 s (2) | 0.50 ± 0.14 s (2) | 0.40 ± 0.14 s (2) "
            "| 0.20 s (1; 1 not uniform within 1.3 s) | 0.55 ± 0.21 s (2) | 1.15 s at 19° (stated) |") in text
    assert ("| 6 | 70 kHz | 0.20 ± 0.14 s (2) | 0.30 ± 0.14 s (2) | — | — | — "
            "| 0.3 s at 19° (stated) |") in text
    lines = (tmp_path / "tables" / "tcon_calibrated.txt").read_text().splitlines()
    assert "H6_0kHz_free_ends 18 0.8 thetam" in lines and "H6_0kHz_free_ends 19 0.7 run" in lines
    assert "H6_70kHz_free_ends 16.5 0.4 run" in lines and len(lines) == 4 + 6 + 2


def test_shift_against_kappa_scale_at_14_4_d(collect, tmp_path, capsys):
    # the 0 Hz ramps at 0.17; 70 kHz at 0.17: 15, 15.5; 0.14: 16, 16.5; 0.21: 14, 15
    for seed, f0, f70, low, high in ((1, 17.0, 15.0, 16.0, 14.0), (2, 18.0, 15.5, 16.5, 15.0)):
        ramps(Pack(tmp_path, 14.4, seed, 13.9, kappa=KAPPA), f0, f70)
        for k, t70 in ((0.14, low), (0.21, high)):
            Pack(tmp_path, 14.4, seed, 13.9, kappa=k).ramp("f70", uniform_at(t70), t70, 0.3, mu=0.7)
    # packing 1's band calibration: 99.9 % of its modes below 90 kHz at 0.3
    (tmp_path / "band").mkdir()
    (tmp_path / "band" / "free400_H14.4_s1.json").write_text(json.dumps({"reference": {"kappa": 0.3, "top": 90e3}}))
    rows = collect.sensitivity_study(str(tmp_path))
    assert [r[:6] for r in rows] == [(0.14, 14.4, "1", 17.0, 16.0, 1.0), (0.14, 14.4, "2", 18.0, 16.5, 1.5),
                                     (0.17, 14.4, "1", 17.0, 15.0, 2.0), (0.17, 14.4, "2", 18.0, 15.5, 2.5),
                                     (0.21, 14.4, "1", 17.0, 14.0, 3.0), (0.21, 14.4, "2", 18.0, 15.0, 3.0)]
    summary = collect.sensitivity_summary(rows)
    assert summary[0.17][1] == pytest.approx((2.25, 0.5 / np.sqrt(2), 2))
    assert collect.standard_error(summary[0.17][1])[0] == pytest.approx(0.25)
    assert summary[0.21][1] == pytest.approx((3.0, 0.0, 2))
    assert collect.kappa_study(str(tmp_path), free=1) == []
    text = markdown(collect, tmp_path, tmp_path / "tables")
    assert ("- kappa_scale 0.17: θ_m 70 kHz 15.25 ± 0.35 (0.25)° (n = 2), "
            "shift 2.25 ± 0.35 (0.25)° (pairs: 2)") in text
    assert ("- kappa_scale 0.14: θ_m 70 kHz 16.25 ± 0.35 (0.25)° (n = 2), "
            "shift 1.25 ± 0.35 (0.25)° (pairs: 2)") in text
    assert "| 0.21 | 2 | — | 18° | 15° | 3° | 0.700 | 3° |" in text, "no band calibration of packing 2"
    # 90 kHz x (0.21 / 0.3)^(1/3) = 79.9 kHz
    assert "| 0.21 | 1 | 79.9 | 17° | 14° | 3° | 0.700 | 3° |" in text
    assert (tmp_path / "tables" / "kappa_calibrated.txt").read_text().splitlines()[0] == \
        "0.14 14.4 1 1 0.7 1 free_ends"
    assert "left out" not in capsys.readouterr().err


def test_paper_length_layers_beside_the_400_d_layers(collect, tmp_path):
    ramps(Pack(tmp_path, 6, 1, 6.0, kappa=KAPPA), 18.0, 16.0)
    ramps(Pack(tmp_path, 6, 2, 6.0, kappa=KAPPA), 18.5, 16.0)
    long = packing_settings(6, 1, layer=2000)
    write(tmp_path, deposit_settings(long), {"grains": 12680, "base": 2100, "length": 2100.0, "H_measured": 6.0})
    # at 0 kHz two flows spread over part of the window before theta_m
    for freq, states in ((0, [(16.0, "stable"), (16.5, "partial"), (17.0, "partial"), (17.5, "uniform")]),
                         (70e3, uniform_at(16.5))):
        write(tmp_path, ramp_settings(long, freq, window=571),
              ramp_result([angle(th, st) for th, st in states], states[-1][0], 0.4))
    cal = collect.calibrated_study(str(tmp_path))
    assert list(cal["ensembles"]) == ["free ends, 400 d", "free ends, 2000 d"]
    assert cal["ensembles"]["free ends, 2000 d"][6.0][0]["window"] == 571
    text = markdown(collect, tmp_path, tmp_path / "tables")
    part = text.split("### layers of paper 000's length")[1]
    assert "| 6 | 2000 d, 571 d | 1 | 12680 + 2100 | 17.50° | 16.50° | 1.00° | 0.40 / 0.40 | 60 / 60 |" in part
    assert "| 6 | 400 d, 200 d | 2 | 500 + 80 | 18.25 ± 0.35° | 16.00 ± 0.00° | 2.25 ± 0.35 (0.25)° " in part
    spreading = [line for line in part.split("###")[0].splitlines() if line.startswith("- H = ")]
    assert spreading[:3] == ["- H = 6 d, 2000 d, packing 1, 0 kHz: 16.5°: partial, 0.00, 1 / 1; "
                             "17°: partial, 0.00, 1 / 1; 17.5°: uniform, 0.00, 1 / 1",
                             "- H = 6 d, 2000 d, packing 1, 70 kHz: 16.5°: uniform, 0.00, 1 / 1",
                             "- H = 6 d, 400 d, packing 1, 0 kHz: 18°: uniform, 0.00, 1 / 1"]
    assert len(spreading) == 6  # both ramps of the two 400 d packings: one line each
    assert collect.spreading_angles({"angles": [angle(10, "stable"), angle(10.5, "local")]}) == []


def test_table1_from_the_wall_times(collect, tmp_path):
    # paper 000's N = 8 000 at 3 d and 32 000 at 14.4 d (49 % and 26 %);
    # here (t70 - t0)/t70 = (150 - 100)/150 = 33 % and (1250 - 1000)/1250 = 20 %
    for (H, n), grains, walls in zip(TABLE1, (7990, 31950), ((100.0, 150.0), (1000.0, 1250.0))):
        for freq, wall in zip((0, 70e3), walls):
            s = table1_settings(H, n, freq)
            assert collect.one_angle(s) and s["kappa"] == KAPPA
            write(tmp_path, s, dict(ramp_result([angle(10, "stable")], None, None), wall_time=wall))
        write(tmp_path, deposit_settings({k: s[k] for k in ("H", "seed", "free", "layer", "Edem", "rest")}),
              {"grains": grains, "base": int(s["layer"]) + 100, "length": s["layer"] + 100, "H_measured": H})
    rows = collect.table1_study(str(tmp_path))
    assert [(r[0], r[1], r[9], r[10]) for r in rows] == [(3.0, 7990, 8000, 0.49), (14.4, 31950, 32000, 0.26)]
    assert [r[8] for r in rows] == pytest.approx([50 / 150, 250 / 1250])
    assert rows[0][4:6] == (0.1, 0.1), "the same time at the angle at both frequencies"
    cal = collect.calibrated_study(str(tmp_path))
    assert cal["ensembles"] == {}, "one-angle runs are no ramps of theta_m"
    text = markdown(collect, tmp_path, tmp_path / "tables")
    assert "| 3 | 7990 + 2786, 2786 d | 0.1 / 0.1 | 100 / 150 | 33 % | 49 % (N = 8000) |" in text
    assert "| 14.4 | 31950 + 2339, 2339 d | 0.1 / 0.1 | 1000 / 1250 | 20 % | 26 % (N = 32000) |" in text
    assert "## Before the calibration" not in text, "no set before the calibration here"
    assert (tmp_path / "tables" / "table1.txt").read_text().splitlines() == [
        "3 7990 2786 2786 100 150 0.333333 8000 0.49", "14.4 31950 2339 2339 1000 1250 0.2 32000 0.26"]


def test_figures_draw_the_calibrated_study_beside_the_sensitivity_study(collect, thickness, tmp_path, monkeypatch):
    Pack(thickness, 6, 1, 6.1, kappa=KAPPA).tcon("f0", 19.0, 0.4)
    Pack(thickness, 6, 1, 6.1, kappa=0.3).tcon("f0", 19.5, 0.3)
    # a ramp at the sensitivity set's 0.21 at 3 d: neither the sensitivity
    # set (14.4 d) nor the kappa_scale study before the calibration
    Pack(thickness, 3, 1, 3.0, kappa=0.21).ramp("f70", uniform_at(16.0), 16.0, 0.3)
    data = collect.study_data(str(thickness))
    assert data["calibrated"]["sensitivity"] == [] and data["kappa"]["kappa_free"] == []
    assert ("H6_0kHz_free_ends", 19.0, 0.4, "run") in data["calibrated"]["tcon"]
    assert ("H6_0kHz_free_ends", 19.5, 0.3, "run") in data["tcon"]
    drawn = {}
    fig_thetam = collect.figs.fig_thetam

    def spy(path, table, label, free, free_label, *args, **options):
        drawn.update(table=np.asarray(table), label=label, free=np.asarray(free), free_label=free_label)
        return fig_thetam(path, table, label, free, free_label, *args, **options)

    monkeypatch.setattr(collect.figs, "fig_thetam", spy)
    written = collect.draw_figures(data, str(tmp_path / "figures"))
    # Fig. 7: the 0.17 ensemble as the study's result, the 0.3 one beside it as the sensitivity study
    assert drawn["label"] == "free ends, 400 d, kappa_scale 0.17 (the calibrated coupling): the study's result"
    assert drawn["free_label"] == ("free ends, 400 d, kappa_scale 0.3 (run before the calibration: "
                                   "sensitivity study)")
    assert drawn["table"][:, 3] == pytest.approx([16.25, 15.75]) and drawn["free"][:, 3] == pytest.approx([21, 14.5])
    assert [os.path.basename(w) for w in written] == ["fig7_thetam.png", "fig8_tcon.png", "fig8_tcon_k0.3.png",
                                                      "fig11_percolation.png"]
    assert all(open(w, "rb").read(4) == b"\x89PNG" for w in written)


def test_the_production_sets_of_issue_42_reach_the_tables(collect, tmp_path):
    # every job of the sets thickness, tcon_cal, sensitivity, paper_length
    # and table1 as avalanche_study.production writes its job.json, with
    # results: theta_m 20 - 0.25 H (+ 0.5 for packing 2) at 0 Hz, 3 deg lower at
    # 70 kHz, 2 deg lower at kappa_scale 0.14, 4 deg lower at 0.21
    from acoustic_tools import avalanche_study as a

    def theta_of(s):
        theta = 20.0 - 0.25 * s["H"] + (0.5 if s["seed"] == 2 else 0.0)
        return theta if s["freq"] == 0 else theta - {0.14: 2.0, 0.17: 3.0, 0.21: 4.0}[s["kappa"]]

    def deposit_of(s):
        packing = {k: s[k] for k in ("H", "seed", "free", "layer", "Edem", "rest")}
        write(tmp_path, deposit_settings(packing), {"grains": int(round(a.GRAINS_PER_AREA * s["H"] * s["layer"])),
                                                    "base": int(s["layer"]) + 100, "length": s["layer"] + 100,
                                                    "H_measured": s["H"]})

    for name in ("thickness", "sensitivity", "paper_length", "table1"):
        for _, s in a.production(name):
            deposit_of(s)
            if collect.one_angle(s):
                write(tmp_path, s, dict(ramp_result([angle(10, "stable")], None, None),
                                        wall_time=100.0 if s["freq"] == 0 else 150.0))
            else:
                theta = theta_of(s)
                write(tmp_path, s, ramp_result([angle(th, st) for th, st in uniform_at(theta)], theta, 0.5))
    for _, (ramp, options) in a.production("tcon_cal"):
        theta_m = theta_of(ramp)
        for theta in [theta_m + step for step in options["steps"]] + [x for x in options["angles"] if x > theta_m]:
            s = tcon_settings(ramp, theta)
            write(tmp_path, s, ramp_result([angle(s["theta"], "uniform")], s["theta"], 0.3))
    data = collect.study_data(str(tmp_path))
    assert data["ensembles"] == {} and data["label"] is None, "nothing at 0.3"
    cal = data["calibrated"]
    by_h = cal["ensembles"]["free ends, 400 d"]
    assert sorted(by_h) == [3.0, 6.0, 8.7, 11.4, 14.4] and {len(packs) for packs in by_h.values()} == {4}
    rows = cal["summary"]["free ends, 400 d"][0]
    # the shift is 3 deg for every packing: mean 3, s.d. 0, four pairs
    assert {r["shift"] for r in rows} == {(3.0, 0.0, 4)}
    assert rows[0]["theta0"] == pytest.approx((19.25 + 0.125, np.std([19.25, 19.75, 19.25, 19.25], ddof=1), 4))
    # t_con runs at theta_m + 1, 2, 3 at 6, 11.4 and 14.4 d, and 19 deg at 6 d (above every theta_m there)
    assert [len(collect.tcon_above(by_h[H], "f70", 2.0)) for H in (6.0, 11.4, 14.4)] == [4, 4, 4]
    assert len(collect.tcon_runs_at_angle(by_h[6.0], "f0", 19.0)) == 4
    assert {r[0]: r[5] for r in cal["sensitivity"]} == {0.14: 2.0, 0.17: 3.0, 0.21: 4.0}
    assert len(cal["sensitivity"]) == 12
    assert sorted(cal["ensembles"]["free ends, 2000 d"]) == [6.0, 14.4]
    assert [(r[0], r[9]) for r in cal["table1"]] == [(3.0, 8000), (14.4, 32000)]
    assert [r[8] for r in cal["table1"]] == pytest.approx([1 / 3, 1 / 3])
    text = collect.write_tables(data, str(tmp_path / "tables"))
    assert "Before the calibration" not in text and "### layers of paper 000's length" in text
    assert sorted(os.listdir(tmp_path / "tables")) == [
        "kappa_calibrated.txt", "summary.json", "summary_calibrated.json", "table1.txt", "tables.md",
        "tcon_calibrated.txt", "thetam_calibrated.txt"]


def test_percolation_rows_are_every_tested_angle_of_the_calibrated_ramps(collect, thickness):
    cal = collect.calibrated_study(str(thickness))
    rows = collect.percolation_rows(cal["ensembles"][cal["label"]])
    # H = 3 d: packings 1, 2 at both frequencies, packing 3 at 0 Hz; H = 6 d: two packings, both
    ramps = {(H, seed, f) for H, seed, f, *_ in rows}
    assert ramps == {(3.0, "1", 0.0), (3.0, "1", 70.0), (3.0, "2", 0.0), (3.0, "2", 70.0), (3.0, "3", 0.0),
                     (6.0, "1", 0.0), (6.0, "1", 70.0), (6.0, "2", 0.0), (6.0, "2", 70.0)}
    # uniform_at(theta): the angles from theta - 1 in 0.5 deg steps, uniform at theta (theta_m)
    assert sorted(r[3] for r in rows if r[:3] == (3.0, "2", 70.0)) == [16.5, 17.0, 17.5]
    assert [r[3] for r in rows if r[5] == "uniform" and r[:3] == (6.0, "1", 0.0)] == [18.0]
    # the ramps at 0.3 are not among them
    assert not any(r[3] == 22.0 for r in rows if r[0] == 3.0 and r[2] == 0.0)


def test_fig3_from_a_kept_band_calibration(collect, tmp_path):
    centres = (np.arange(150) + 0.5) * 1e3
    density = np.where(centres < 75e3, 1.0 / 75e3, 0.0)
    at = {"kappa": KAPPA, "share": 0.999, "top": 74.9e3, "below_75kHz": 1.0, "in_5_45kHz": 0.53,
          "histogram": np.column_stack([centres, density]).tolist()}
    (tmp_path / "band").mkdir()
    with open(tmp_path / "band" / "free400_H14.4_s4.json", "w") as f:
        json.dump({"grains": 6023, "target": 75e3, "kappa": 0.171, "at_check": at}, f)
    with open(tmp_path / "band" / "free400_H14.4_s1.json", "w") as f:   # another packing's: its band top only
        json.dump({"grains": 6023, "target": 75e3, "kappa": 0.165, "at_check": at}, f)
    with open(tmp_path / "band" / "old.json", "w") as f:          # a calibration without its histogram
        json.dump({"grains": 10, "at_check": {k: v for k, v in at.items() if k != "histogram"}}, f)
    written = collect.band_figures(str(tmp_path), str(tmp_path / "figures"))
    assert [os.path.basename(w) for w in written] == ["fig3_modes_free400_H14.4_s4.png"]
    import matplotlib.image
    assert matplotlib.image.imread(written[0]).shape[1] >= 1200


def test_fig11_in_numbers(collect, thickness):
    cal = collect.calibrated_study(str(thickness))
    table = collect.percolation_table(cal["percolation"])
    assert sorted(table) == [3.0, 6.0]
    # H = 3 d: at 16.5 deg only packing 2's 70 kHz ramp (uniform at 17.5) was tested; at 19 deg the 0 kHz
    # ramps of packings 1 and 3 (uniform at 20 and 19.5)
    at = {theta: (n0, n70) for theta, m0, n0, m70, n70 in table[3.0]}
    assert at[16.5] == (0, 1) and at[19.0] == (2, 0)
    markdown = collect.tables_markdown(collect.study_data(str(thickness)))
    assert "### Fig. 11 in numbers" in markdown and "- H = 3 d (0 / 70 kHz): 14°: — / 0.000" in markdown


def test_kappa_means_give_the_mean_shift_and_its_standard_error_per_coupling():
    from acoustic_tools.avalanche_figures import kappa_means
    # the four 14.4 d packings' shifts as recorded (RESULTS: 0.50 +- 0.20, 2.00 +- 0.35 deg)
    rows = kappa_means([0.17, 0.14, 0.17, 0.14, 0.17, 0.14, 0.17, 0.14, 0.3],
                       [1.5, 0.0, 2.0, 0.5, 1.5, 0.5, 3.0, 1.0, 4.0])
    np.testing.assert_allclose(rows[:, 0], [0.14, 0.17, 0.3])
    np.testing.assert_allclose(rows[:, 1], [0.5, 2.0, 4.0])
    np.testing.assert_allclose(rows[:, 2], [np.sqrt(1 / 6) / 2, np.sqrt(0.5) / 2, 0.0])
    np.testing.assert_array_equal(rows[:, 3], [4, 4, 1])
